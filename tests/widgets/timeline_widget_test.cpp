#include "widgets/timeline_widget.h"

#include "widgets/scrub_bar.h"

#include <catch2/catch.hpp>

#include <QAction>
#include <QMenu>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace bunraku;

namespace {

/// A scrub bar of `seconds` with phrase ticks at `boundaries`, shown and exposed.
void showBar(widgets::ScrubBar& bar, double seconds, std::vector<double> boundaries, QSize size = QSize(400, 34))
{
    bar.resize(size);
    bar.setDuration(seconds);
    bar.setBoundaries(std::move(boundaries));
    bar.show();
    REQUIRE(QTest::qWaitForWindowExposed(&bar));
}

} // namespace

TEST_CASE("the timeline's keys request play, steps, start and end", "[widgets][timeline]")
{
    widgets::TimelineWidget timeline;
    timeline.setDuration(20.0, 5.0);
    timeline.show();
    REQUIRE(QTest::qWaitForWindowExposed(&timeline));
    timeline.activateWindow();
    QSignalSpy play(&timeline, &widgets::TimelineWidget::playToggled);
    QSignalSpy step(&timeline, &widgets::TimelineWidget::stepRequested);
    QSignalSpy home(&timeline, &widgets::TimelineWidget::homeRequested);
    QSignalSpy end(&timeline, &widgets::TimelineWidget::endRequested);
    timeline.playAction()->trigger();
    timeline.stepForwardAction()->trigger();
    timeline.stepBackAction()->trigger();
    timeline.homeAction()->trigger();
    timeline.endAction()->trigger();
    REQUIRE(play.count() == 1);
    REQUIRE(play[0][0].toBool());
    REQUIRE(step.count() == 2);
    REQUIRE(step[0][0].toInt() == 1);
    REQUIRE(step[1][0].toInt() == -1);
    REQUIRE(home.count() == 1);
    REQUIRE(end.count() == 1);
    REQUIRE(timeline.playAction()->shortcut() == QKeySequence(Qt::Key_Space));
    REQUIRE(timeline.homeAction()->shortcut() == QKeySequence(Qt::Key_Home));
}

TEST_CASE("the speed is limited to 0.1x to 4x", "[widgets][timeline]")
{
    widgets::TimelineWidget timeline;
    timeline.setSpeed(10.0);
    REQUIRE(timeline.speed() == Approx(4.0));
    timeline.setSpeed(0.01);
    REQUIRE(timeline.speed() == Approx(0.1));
}

TEST_CASE("pressing the scrub bar requests the time under the mouse", "[widgets][timeline]")
{
    widgets::ScrubBar bar;
    showBar(bar, 20.0, {4.0, 10.0}, QSize(416, 30));
    QSignalSpy scrubbed(&bar, &widgets::ScrubBar::scrubbed);
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, QPoint(bar.xOfTime(5.0), 15));
    REQUIRE(scrubbed.count() == 1);
    REQUIRE(scrubbed[0][0].toDouble() == Approx(5.0).margin(0.05));
    REQUIRE(bar.timeAtX(bar.xOfTime(12.5)) == Approx(12.5).margin(0.05));
    REQUIRE(bar.boundaries().size() == 2);
}

TEST_CASE("an editable phrase tick is dragged instead of scrubbing", "[widgets][timeline]")
{
    widgets::ScrubBar bar;
    showBar(bar, 10.0, {3.0, 6.0});
    QSignalSpy scrubbed(&bar, &widgets::ScrubBar::scrubbed);
    QSignalSpy started(&bar, &widgets::ScrubBar::boundaryDragStarted);
    QSignalSpy dragged(&bar, &widgets::ScrubBar::boundaryDragged);
    QSignalSpy finished(&bar, &widgets::ScrubBar::boundaryDragFinished);
    const int y = bar.height() / 2;
    const QPoint tick(bar.xOfTime(6.0), y);

    // Not editable: pressing on a tick scrubs.
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, tick);
    QTest::mouseRelease(&bar, Qt::LeftButton, Qt::NoModifier, tick);
    REQUIRE(scrubbed.count() == 1);
    REQUIRE(started.isEmpty());

    bar.setBoundariesEditable(true);
    REQUIRE(bar.boundaryAtX(tick.x() + 2) == 1);
    REQUIRE(bar.boundaryAtX(bar.xOfTime(4.5)) == -1);
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, tick);
    const QPoint to(bar.xOfTime(8.0), y);
    QMouseEvent move(QEvent::MouseMove, QPointF(to), bar.mapToGlobal(QPointF(to)), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&bar, &move);
    QTest::mouseRelease(&bar, Qt::LeftButton, Qt::NoModifier, to);
    REQUIRE(scrubbed.count() == 1); // no scrubbing during the drag
    REQUIRE(started.count() == 1);
    REQUIRE(started.first().at(0).toInt() == 1);
    REQUIRE(dragged.count() == 1);
    REQUIRE(dragged.first().at(0).toInt() == 1);
    REQUIRE(dragged.first().at(1).toDouble() == Approx(8.0).margin(10.0 / 380));
    REQUIRE(finished.count() == 1);

    // Away from the ticks it still scrubs.
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, QPoint(bar.xOfTime(4.5), y));
    REQUIRE(scrubbed.count() == 2);
}

TEST_CASE("editable phrase ticks are added by double click and context menu, removed by context menu and Delete",
          "[widgets][timeline]")
{
    widgets::ScrubBar bar;
    showBar(bar, 10.0, {3.0, 6.0});
    QSignalSpy added(&bar, &widgets::ScrubBar::boundaryAddRequested);
    QSignalSpy removed(&bar, &widgets::ScrubBar::boundaryRemoveRequested);
    const int y = bar.height() / 2;
    const QPoint gap(bar.xOfTime(4.5), y);
    const QPoint tick(bar.xOfTime(6.0), y);

    // Not editable: no menu, double clicks and Delete request nothing.
    REQUIRE(bar.createContextMenu(gap) == nullptr);
    QTest::mouseDClick(&bar, Qt::LeftButton, Qt::NoModifier, gap);
    QTest::keyClick(&bar, Qt::Key_Delete);
    REQUIRE(added.isEmpty());
    REQUIRE(removed.isEmpty());

    bar.setBoundariesEditable(true);
    // A double click away from the ticks asks for a boundary there; on a tick it does not.
    QTest::mouseDClick(&bar, Qt::LeftButton, Qt::NoModifier, gap);
    REQUIRE(added.count() == 1);
    REQUIRE(added[0][0].toDouble() == Approx(4.5).margin(10.0 / 380));
    QTest::mouseDClick(&bar, Qt::LeftButton, Qt::NoModifier, tick);
    REQUIRE(added.count() == 1);

    // The context menu: add between ticks, remove on a tick.
    std::unique_ptr<QMenu> addMenu(bar.createContextMenu(gap));
    REQUIRE(addMenu);
    REQUIRE(addMenu->actions().size() == 1);
    REQUIRE(addMenu->actions()[0]->text() == QStringLiteral("Add phrase boundary here"));
    addMenu->actions()[0]->trigger();
    REQUIRE(added.count() == 2);
    REQUIRE(added[1][0].toDouble() == Approx(4.5).margin(10.0 / 380));
    std::unique_ptr<QMenu> removeMenu(bar.createContextMenu(tick + QPoint(2, 0)));
    REQUIRE(removeMenu->actions().size() == 1);
    REQUIRE(removeMenu->actions()[0]->text() == QStringLiteral("Remove phrase boundary"));
    removeMenu->actions()[0]->trigger();
    REQUIRE(removed.count() == 1);
    REQUIRE(removed[0][0].toInt() == 1);

    // Delete removes the tick under the mouse, else the one pressed last.
    const QPoint first(bar.xOfTime(3.0), y);
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, first);
    QTest::mouseRelease(&bar, Qt::LeftButton, Qt::NoModifier, first);
    REQUIRE(bar.selectedBoundary() == 0);
    QMouseEvent away(QEvent::MouseMove, QPointF(gap), bar.mapToGlobal(QPointF(gap)), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&bar, &away);
    REQUIRE(bar.hoveredBoundary() == -1);
    QTest::keyClick(&bar, Qt::Key_Delete);
    REQUIRE(removed.count() == 2);
    REQUIRE(removed[1][0].toInt() == 0);
    QMouseEvent over(QEvent::MouseMove, QPointF(tick), bar.mapToGlobal(QPointF(tick)), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&bar, &over);
    REQUIRE(bar.hoveredBoundary() == 1);
    QTest::keyClick(&bar, Qt::Key_Backspace);
    REQUIRE(removed.count() == 3);
    REQUIRE(removed[2][0].toInt() == 1);
    // A new set of ticks (one came or went) clears the selection.
    bar.setBoundaries({3.0});
    REQUIRE(bar.selectedBoundary() == -1);
}

TEST_CASE("a tick drag interrupted by a context menu ends (the release never comes)", "[widgets][timeline]")
{
    widgets::ScrubBar bar;
    showBar(bar, 10.0, {3.0, 6.0});
    bar.setBoundariesEditable(true);
    QSignalSpy started(&bar, &widgets::ScrubBar::boundaryDragStarted);
    QSignalSpy finished(&bar, &widgets::ScrubBar::boundaryDragFinished);
    const QPoint tick(bar.xOfTime(3.0), bar.height() / 2);
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, tick);
    REQUIRE(started.count() == 1);
    // A right click mid-drag: its menu takes the mouse.
    QContextMenuEvent menu(QContextMenuEvent::Mouse, tick, bar.mapToGlobal(tick));
    QCoreApplication::sendEvent(&bar, &menu);
    REQUIRE(finished.count() == 1);
    for (auto* popup : bar.findChildren<QMenu*>()) popup->close();
    // A later move without the button does not start or end anything again.
    QMouseEvent move(QEvent::MouseMove, QPointF(tick), bar.mapToGlobal(QPointF(tick)), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&bar, &move);
    REQUIRE(finished.count() == 1);

    // The same when the release is lost and the next move arrives without the button.
    QTest::mousePress(&bar, Qt::LeftButton, Qt::NoModifier, tick);
    REQUIRE(started.count() == 2);
    QCoreApplication::sendEvent(&bar, &move);
    REQUIRE(finished.count() == 2);
}
