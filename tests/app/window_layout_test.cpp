// The window on small screens: at 1280 x 720 and 1366 x 768 every dock's content lies inside the
// window (between the menu bar and the status bar, overlapping no other dock) at a useful size;
// the splitter between the 3D view and the graphs widens the view; the Design dock's buttons are
// whole inside its visible area; a project brings back the dock layout it was saved with.
#include "tests/app/app_test_support.h"

#include "app/side_columns.h"
#include "app/viewport_panel.h"

#include "widgets/graph_panel.h"
#include "widgets/scrub_bar.h"
#include "widgets/timeline_widget.h"
#include "widgets/viewport_widget.h"

#include <catch2/catch.hpp>

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
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

/// The default dock layout at `size`.
void resetLayoutAt(app::MainWindow& window, QSize size)
{
    window.resetLayout();
    resizeTo(window, size);
}

} // namespace

TEST_CASE("at 1280x720 and 1366x768 every dock is inside the window at a useful size", "[app][layout]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    for (const QSize size : {QSize(1280, 720), QSize(1366, 768)}) {
        INFO("window " << size.width() << "x" << size.height());
        resetLayoutAt(*window, size);
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
        window->document().selectTake(app::TakeSlot::B, app::TakeId::corpus(3));
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
        window->document().selectTake(app::TakeSlot::B, {});
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

TEST_CASE("at 1280x720 and 1366x768 every button of the Design dock is whole inside the dock's visible area", "[app][layout][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    for (const QSize size : {QSize(1280, 720), QSize(1366, 768)}) {
        INFO("window " << size.width() << "x" << size.height());
        resetLayoutAt(*window, size);
        QDockWidget* dock = window->dock("designDock");
        dock->raise();
        for (int pass = 0; pass < 4; ++pass) QCoreApplication::processEvents();
        auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
        REQUIRE(scroll);
        // The content reflows to the dock's width: nothing to scroll sideways to.
        CHECK(scroll->horizontalScrollBar()->maximum() == 0);
        const auto visible = [&] { return QRect(scroll->viewport()->mapTo(window.get(), QPoint(0, 0)), scroll->viewport()->size()); };
        CHECK(inWindow(dock, window.get()).contains(visible()));
        // The warp plot takes the width.
        auto* plot = scroll->widget()->findChild<QWidget*>(QStringLiteral("warpPlot"));
        REQUIRE(plot);
        CHECK(plot->width() >= scroll->viewport()->width() - 24);
        CHECK(visible().left() <= inWindow(plot, window.get()).left());
        CHECK(inWindow(plot, window.get()).right() <= visible().right());
        // Each button (and the snap box) scrolled into view vertically only, as a user scrolls
        // down the dock: whole inside the visible area.
        QList<QAbstractButton*> buttons;
        for (auto* button : scroll->widget()->findChildren<QPushButton*>()) buttons << button;
        buttons << scroll->widget()->findChild<QCheckBox*>();
        CHECK(buttons.size() >= 9);
        for (QAbstractButton* button : buttons) {
            REQUIRE(button);
            INFO("button \"" << button->text().toStdString() << "\"");
            CHECK(button->isVisible());
            const int top = button->mapTo(scroll->widget(), QPoint(0, 0)).y();
            scroll->verticalScrollBar()->setValue(std::max(0, top + button->height() - scroll->viewport()->height() + 4));
            QCoreApplication::processEvents();
            const QRect shown = inWindow(button, window.get());
            INFO("at " << shown.x() << "," << shown.y() << " " << shown.width() << "x" << shown.height() << " in " << visible().x() << ","
                       << visible().y() << " " << visible().width() << "x" << visible().height());
            CHECK(visible().contains(shown));
            // Its text is not cut: the button is as wide as it asks to be.
            CHECK(button->width() >= button->sizeHint().width());
        }
        scroll->verticalScrollBar()->setValue(0);
    }
}

TEST_CASE("a project reopens with its dock layout and ignores a malformed one", "[app][layout][project]")
{
    const auto folder = test::scratchDir("project-layout");
    const QString file = QString::fromStdString((folder / "layout.bunraku.json").string());
    const auto leftWidth = [](app::MainWindow& window) { return window.dock("corpusDock")->width(); };
    const auto settle = [] {
        for (int pass = 0; pass < 6; ++pass) QCoreApplication::processEvents();
    };
    int saved = 0;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        window->resetLayout();
        resizeTo(*window, QSize(1366, 768));
        window->resizeDocks({window->dock("corpusDock")}, {557}, Qt::Horizontal);
        settle();
        saved = leftWidth(*window); // as wide as the other docks' minimum widths let it be
        CHECK(saved >= 440);
        REQUIRE(window->files().projects().saveProject(file));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    window->resetLayout();
    resizeTo(*window, QSize(1366, 768));
    const int fresh = leftWidth(*window);
    INFO("fresh " << fresh << " saved " << saved);
    REQUIRE(fresh < saved - 100);
    REQUIRE(window->files().projects().openProject(file));
    settle();
    CHECK(leftWidth(*window) == Approx(saved).margin(4));
    // The restored width is the one kept when the window is resized.
    resizeTo(*window, QSize(1500, 900));
    CHECK(leftWidth(*window) == Approx(saved).margin(4));
    resizeTo(*window, QSize(1366, 768));

    // A layout that is not base64, or base64 of no layout: the project opens, the layout stays.
    window->resetLayout();
    settle();
    const int before = leftWidth(*window);
    QFile project(file);
    REQUIRE(project.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(project.readAll()).object();
    project.close();
    for (const QString& malformed : {QStringLiteral("not base64 at all!"), QStringLiteral("QUJDREVGRw==")}) {
        INFO(malformed.toStdString());
        QJsonObject view = root["view"].toObject();
        view["windowState"] = malformed;
        root["view"] = view;
        const QString broken = QString::fromStdString((folder / "broken.bunraku.json").string());
        QFile out(broken);
        REQUIRE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(QJsonDocument(root).toJson());
        out.close();
        REQUIRE(window->files().projects().openProject(broken));
        settle();
        CHECK(leftWidth(*window) == Approx(before).margin(4));
        for (QDockWidget* dock : window->docks()) CHECK(dock->isVisible());
    }
}

TEST_CASE("a 3D view narrowed below a third of the window reopens as narrow in a window of the same size",
          "[app][layout][project]")
{
    const auto folder = test::scratchDir("project-layout-narrow-view");
    const QString file = QString::fromStdString((folder / "narrow.bunraku.json").string());
    const auto settle = [] {
        for (int pass = 0; pass < 6; ++pass) QCoreApplication::processEvents();
    };
    const QSize size(1500, 920);
    int saved = 0;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        resetLayoutAt(*window, size);
        settle();
        const int laidOut = window->dock("viewDock")->width();
        window->resizeDocks({window->dock("viewDock")}, {laidOut - 90}, Qt::Horizontal);
        settle();
        saved = window->dock("viewDock")->width();
        INFO("laid out " << laidOut << ", narrowed to " << saved);
        REQUIRE(saved * 3 < size.width()); // narrower than the third a larger window gives it
        REQUIRE(window->files().projects().saveProject(file));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    resetLayoutAt(*window, size);
    settle();
    REQUIRE(window->files().projects().openProject(file));
    settle();
    CHECK(window->dock("viewDock")->width() == Approx(saved).margin(4));
}

TEST_CASE("a project saved at 1366x768 reopens at 1920x1080 with every dock useful and the 3D view a third of the width",
          "[app][layout][project]")
{
    const auto folder = test::scratchDir("project-layout-screens");
    const QString file = QString::fromStdString((folder / "laptop.bunraku.json").string());
    const auto settle = [] {
        for (int pass = 0; pass < 6; ++pass) QCoreApplication::processEvents();
    };
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        resetLayoutAt(*window, QSize(1366, 768));
        settle();
        REQUIRE(window->files().projects().saveProject(file));
    }
    for (const QSize size : {QSize(1920, 1080), QSize(2560, 1440)}) {
        auto window = test::demoWindow();
        REQUIRE(window);
        resetLayoutAt(*window, size);
        REQUIRE(window->files().projects().openProject(file));
        settle();
        INFO("reopened at " << size.width() << "x" << size.height());
        for (QDockWidget* dock : window->docks()) {
            // (A tab behind another is "visible" but placed outside the window.)
            if (!dock->isVisible() || !dock->geometry().intersects(window->rect())) continue;
            const auto useful = kUsefulSize.find(dock->objectName());
            if (useful == kUsefulSize.end()) continue;
            INFO(dock->objectName().toStdString() << " " << dock->width() << "x" << dock->height());
            CHECK(dock->width() >= useful->second.width());
            CHECK(dock->height() >= useful->second.height());
        }
        const int view = window->dock("viewDock")->width();
        INFO("3D view " << view << " px wide");
        CHECK(view * 3 >= size.width());
        // The left column is as wide as it was on the laptop, not stretched.
        CHECK(window->dock("corpusDock")->width() <= app::SideColumns::preferredLeftWidth(1366) + 8);
    }
}
