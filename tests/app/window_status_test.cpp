// The main window as it first meets the user: it fits the screen whatever --window-size asks.
#include "tests/app/app_test_support.h"

#include "app/window_placement.h"

#include <catch2/catch.hpp>

#include <QScreen>
#include <QStatusBar>

using namespace bunraku;

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
    window.files().openDemoCorpus();
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
