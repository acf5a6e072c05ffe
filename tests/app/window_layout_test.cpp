// The window on small screens: at 1280 x 720 and 1366 x 768 every dock's content lies inside the
// window (between the menu bar and the status bar, overlapping no other dock) at a useful size;
// the splitter between the 3D view and the graphs widens the view.
#include "tests/app/app_test_support.h"

#include "app/viewport_panel.h"

#include "widgets/graph_panel.h"
#include "widgets/scrub_bar.h"
#include "widgets/timeline_widget.h"
#include "widgets/viewport_widget.h"

#include <catch2/catch.hpp>

#include <QAbstractButton>
#include <QComboBox>
#include <QDockWidget>
#include <QMenuBar>
#include <QWindow>
#include <QStatusBar>

#include <map>

using namespace bunraku;

namespace {

/// The smallest size at which each dock's content is still of use.
const std::map<QString, QSize> kUsefulSize{
    {"corpusDock", {200, 120}},    {"historyDock", {200, 120}}, {"inspectorDock", {200, 150}},
    {"normaliseDock", {200, 150}}, {"emotionDock", {200, 150}}, {"designDock", {200, 150}},
    {"graphsDock", {400, 300}},    {"viewDock", {300, 240}},    {"timelineDock", {600, 26}},
};

QRect inWindow(const QWidget* widget, const QWidget* window) { return QRect(widget->mapTo(window, QPoint(0, 0)), widget->size()); }

/// Resizes the window and waits until it has that size and its layout settled.
void resizeTo(app::MainWindow& window, QSize size)
{
    window.resize(size);
    REQUIRE(QTest::qWaitFor([&] { return window.size() == size; }, 5000));
    // The left column is given back its width once the docks were placed, then laid out again.
    for (int pass = 0; pass < 4; ++pass) QCoreApplication::processEvents();
}

} // namespace

TEST_CASE("at 1280x720 and 1366x768 every dock is inside the window at a useful size", "[app][layout]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    for (const QSize size : {QSize(1280, 720), QSize(1366, 768)}) {
        INFO("window " << size.width() << "x" << size.height());
        window->resetLayout();
        resizeTo(*window, size);
        CHECK(window->minimumSizeHint().width() <= size.width());
        CHECK(window->minimumSizeHint().height() <= size.height());
        const QRect area(0, window->menuBar()->geometry().bottom() + 1, window->width(),
                         window->statusBar()->geometry().top() - window->menuBar()->geometry().bottom() - 1);
        CHECK(window->rect().contains(window->statusBar()->geometry()));
        for (QDockWidget* dock : window->docks()) {
            // Tabbed docks: each in turn in front.
            dock->raise();
            QCoreApplication::processEvents();
            const QString name = dock->objectName();
            INFO("dock " << name.toStdString());
            REQUIRE(dock->isVisible());
            REQUIRE(dock->widget()->isVisible());
            const QRect content = inWindow(dock->widget(), window.get());
            CHECK(area.contains(content));
            CHECK(content.width() >= kUsefulSize.at(name).width());
            CHECK(content.height() >= kUsefulSize.at(name).height());
            // No other visible dock lies over it.
            for (QDockWidget* other : window->docks())
                if (other != dock && other->widget()->isVisible())
                    CHECK_FALSE(inWindow(other->widget(), window.get()).intersects(content));
        }
        // The parts that matter most inside their docks.
        const QRect view = inWindow(window->viewportPanel()->viewport(), window.get());
        CHECK(area.contains(view));
        CHECK(view.width() >= 300);
        CHECK(view.height() >= 240);
        const QRect bar = inWindow(window->timeline()->scrubBar(), window.get());
        CHECK(area.contains(bar));
        CHECK(bar.width() >= 300);
        // Every control of the 3D view's and the graphs' rows is shown, whole, inside its dock:
        // nothing hidden behind an extension menu (the figure of take B with two takes shown).
        window->document().selectTake(app::TakeSlot::B, app::Document::corpusTakeId(3));
        QCoreApplication::processEvents();
        for (const char* row : {"viewToolBar", "graphToolBar"}) {
            QWidget* controls = window->findChild<QWidget*>(QString::fromLatin1(row));
            REQUIRE(controls);
            const QRect dock = inWindow(qobject_cast<QWidget*>(controls->parent()), window.get());
            int checked = 0;
            for (QWidget* control : controls->findChildren<QWidget*>()) {
                if (!qobject_cast<QComboBox*>(control) && !qobject_cast<QAbstractButton*>(control)) continue;
                INFO(row << ": " << control->objectName().toStdString() << " " << control->property("text").toString().toStdString());
                CHECK(control->isVisibleTo(window.get()));
                CHECK(dock.contains(inWindow(control, window.get())));
                ++checked;
            }
            CHECK(checked >= (std::string(row) == "viewToolBar" ? 10 : 6));
        }
        window->document().selectTake(app::TakeSlot::B, QString());
    }
}

TEST_CASE("the splitter between the 3D view and the graphs widens the view", "[app][layout]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    window->resetLayout();
    resizeTo(*window, QSize(1700, 1000));
    QDockWidget* view = window->dock("viewDock");
    QDockWidget* graphs = window->dock("graphsDock");
    REQUIRE(view->geometry().right() < graphs->geometry().left());
    // A wider window widened the views, not the left column.
    CHECK(window->dock("corpusDock")->width() <= 430);
    CHECK(view->width() >= 450);
    auto* viewport = window->viewportPanel()->viewport();
    const int before = viewport->width();
    // Press on the separator between the two docks, drag 200 pixels to the right.
    const QPoint separator((view->geometry().right() + graphs->geometry().left()) / 2, view->geometry().center().y());
    // Through the window system, as a mouse would (a press on the separator, moves with the
    // button held, a release).
    QWindow* handle = window->windowHandle();
    QTest::mousePress(handle, Qt::LeftButton, Qt::NoModifier, separator);
    for (int step = 1; step <= 10; ++step) QTest::mouseMove(handle, separator + QPoint(20 * step, 0));
    QTest::mouseRelease(handle, Qt::LeftButton, Qt::NoModifier, separator + QPoint(200, 0));
    // Docks are animated into place.
    (void)QTest::qWaitFor([&] { return std::abs(viewport->width() - (before + 200)) <= 12; }, 3000);
    INFO("3D view " << before << " -> " << viewport->width() << " pixels wide");
    CHECK(viewport->width() == Approx(before + 200).margin(12));
    CHECK(inWindow(window->graphPanel(), window.get()).width() >= 400);
}
