// The main window as it first meets the user: it fits the screen whatever --window-size asks;
// it names the takes it shows outside the title bar; an action's status message goes after a
// while or when the next one comes, and a long one is cut at the window's edge, not beyond it.
#include "tests/app/app_test_support.h"

#include "app/export_controller.h"
#include "app/window_placement.h"

#include "widgets/clock.h"
#include "widgets/elided_label.h"

#include <catch2/catch.hpp>

#include <QLabel>
#include <QScreen>
#include <QStatusBar>

using namespace bunraku;
using app::TakeSlot;

TEST_CASE("a window size as large as the screen keeps the window and its status bar inside the available screen", "[app][window]")
{
    // --window-size 1920x1080 used to put the window at y = 20 with its status bar off the screen.
    const QRect available(0, 24, 1920, 1056); // a 1920 x 1080 screen under a 24-pixel top panel
    const QRect frame = app::fittedFrame(QSize(1920, 1080), QSize(0, 28), QPoint(0, 20), available);
    CHECK(available.contains(frame));
    CHECK(frame.size() == QSize(1920, 1056));
    // A size that fits stays, moved only as far as needed.
    CHECK(app::fittedFrame(QSize(800, 600), QSize(0, 0), QPoint(1500, 900), available) == QRect(1120, 480, 800, 600));
    CHECK(app::fittedFrame(QSize(800, 600), QSize(0, 0), QPoint(100, 100), available) == QRect(100, 100, 800, 600));

    test::isolateSettings();
    app::MainWindow window;
    window.files().setDialogsEnabled(false);
    window.files().corpora().openDemoCorpus();
    window.move(0, 20);
    QScreen* screen = window.screen();
    REQUIRE(screen);
    const QSize asked = screen->geometry().size(); // as large as the whole screen
    app::showInsideScreen(window, asked);
    REQUIRE(QTest::qWaitForWindowExposed(&window));
    QCoreApplication::processEvents();
    const QRect inside = screen->availableGeometry();
    INFO("frame " << window.frameGeometry().x() << "," << window.frameGeometry().y() << " " << window.frameGeometry().width() << "x"
                  << window.frameGeometry().height());
    CHECK(inside.contains(window.frameGeometry()));
    const QRect statusBar(window.statusBar()->mapToGlobal(QPoint(0, 0)), window.statusBar()->size());
    CHECK(inside.contains(statusBar));
}

TEST_CASE("the main window names take A and take B where they are seen, kept current", "[app][window]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    QLabel* shown = window->shownTakesLabel();
    REQUIRE(shown != nullptr);
    CHECK(shown->isVisible());
    CHECK(window->statusBar()->isAncestorOf(shown));
    CHECK(shown->text() == QStringLiteral("A: ") + QString::fromStdString(document.selectedTake(TakeSlot::A)->displayName()));
    document.selectTake(TakeSlot::A, app::TakeId::corpus(3));
    document.selectTake(TakeSlot::B, app::TakeId::corpus(7));
    const QString a = QString::fromStdString(document.corpus().takes[3].displayName());
    const QString b = QString::fromStdString(document.corpus().takes[7].displayName());
    CHECK(shown->text() == QStringLiteral("A: %1   B: %2").arg(a, b));
    // Inside the window, not cut (once the status bar has laid out the longer text).
    QCoreApplication::sendPostedEvents();
    QCoreApplication::processEvents();
    const QRect inWindow(shown->mapTo(window.get(), QPoint(0, 0)), shown->size());
    CHECK(window->rect().contains(inWindow));
    CHECK(shown->width() >= shown->fontMetrics().horizontalAdvance(shown->text()));
    document.selectTake(TakeSlot::B, {});
    CHECK(shown->text() == QStringLiteral("A: ") + a);
}

TEST_CASE("an action's status message goes after a while or when the next comes, and a long one is cut at the window's edge",
          "[app][window][status]")
{
    widgets::ManualClock clock; // outlives the window, whose timer runs on it
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* line = window->statusLine();
    REQUIRE(line != nullptr);
    window->setStatusClock(&clock);
    const int timeout = window->statusTimeout();
    CHECK(timeout >= 5000);
    CHECK(timeout <= 30000);
    // "Made the corpus..." stayed until the next message, however long after.
    window->showStatus(QStringLiteral("Made the corpus /tmp/corpus from 6 files"));
    CHECK(line->text() == QStringLiteral("Made the corpus /tmp/corpus from 6 files"));
    clock.advance(timeout - 1);
    CHECK_FALSE(line->text().isEmpty());
    clock.advance(1);
    CHECK(line->text().isEmpty());

    // Replaced by the next message, which keeps its own time.
    window->showStatus(QStringLiteral("first"));
    clock.advance(timeout / 2);
    window->showStatus(QStringLiteral("second"));
    CHECK(line->text() == QStringLiteral("second"));
    clock.advance(timeout - 1);
    CHECK(line->text() == QStringLiteral("second"));
    clock.advance(1);
    CHECK(line->text().isEmpty());
    // A stage's failure is not an action's message: it stays until the stage runs again (a
    // project's largest scale that does not fit the demo's takes).
    REQUIRE(test::waitUntilIdle(*window));
    app::AnalysisParameters parameters = window->document().parameters();
    parameters.normalise.maxScale = 200;
    window->document().restoreParameters(parameters);
    REQUIRE(QTest::qWaitFor(
        [&] { return window->analysis().scheduler().state(app::AnalysisController::kNormaliseSlot) == app::SlotState::Failed; }, 60000));
    REQUIRE(line->text().contains(QStringLiteral("failed")));
    clock.advance(2 * timeout);
    CHECK(line->text().contains(QStringLiteral("failed")));

    // A message longer than the window: the window keeps its width, the line ends inside it with
    // an ellipsis, and its tool tip holds the whole message.
    const int width = window->width();
    const QString longMessage = QStringLiteral("Exported take A to ") + QString(400, QLatin1Char('x')) + QStringLiteral(".glb");
    window->showStatus(longMessage);
    QCoreApplication::processEvents();
    CHECK(window->width() == width);
    const QRect inWindow(line->mapTo(window.get(), QPoint(0, 0)), line->size());
    CHECK(inWindow.right() <= window->rect().right());
    CHECK(line->shownText() != longMessage);
    CHECK(line->shownText().endsWith(QChar(0x2026)));
    CHECK(line->fontMetrics().horizontalAdvance(line->shownText()) <= line->contentsRect().width());
    CHECK(line->toolTip() == longMessage);
    // The permanent parts of the status bar stay in sight.
    CHECK(window->shownTakesLabel()->isVisible());
    const QRect takes(window->shownTakesLabel()->mapTo(window.get(), QPoint(0, 0)), window->shownTakesLabel()->size());
    CHECK(window->rect().contains(takes));
}
