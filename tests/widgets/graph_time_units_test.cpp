// What the graphs and the timeline show when takes change: the time axis refitted to other takes
// (the zoom kept while the same takes are shown), the channels' units on the value axes, graphs
// that scroll rather than squeeze, a time read-out that never moves the scrub bar, and spin boxes
// that say when they clamp a typed value.
#include "tests/widgets/synthetic_take.h"

#include "widgets/bounded_spin_box.h"
#include "widgets/graph_grid.h"
#include "widgets/scrub_bar.h"
#include "widgets/take_series.h"
#include "widgets/timeline_widget.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>

using namespace bunraku;

namespace {

void showGrid(widgets::GraphGrid& grid, QSize size = QSize(800, 700))
{
    grid.resize(size);
    grid.show();
    REQUIRE(QTest::qWaitForWindowExposed(&grid));
}

} // namespace

TEST_CASE("other takes refit the time axis, the same takes keep the zoom", "[widgets][graph_grid][time]")
{
    widgets::GraphGrid grid;
    const auto shortTake = test::syntheticPuppetTake(36);  // 7.0 s at 5 Hz
    const auto longTake = test::syntheticPuppetTake(101); // 20.0 s
    grid.setTakes(longTake, nullptr, QStringLiteral("corpus/1|"));
    showGrid(grid);
    REQUIRE(grid.timeRange() == std::pair(0.0, 20.0));

    // A 7 s take after a 20 s one is drawn on 0-7 s, not 0-20 s; a 20 s one after it on 0-20 s.
    grid.setTakes(shortTake, nullptr, QStringLiteral("corpus/2|"));
    CHECK(grid.timeRange() == std::pair(0.0, 7.0));
    grid.setTimeRange(1.0, 3.0); // zoomed
    grid.setTakes(longTake, nullptr, QStringLiteral("corpus/1|"));
    CHECK(grid.timeRange() == std::pair(0.0, 20.0));
    // Take B shown beside: the longer of the two.
    grid.setTimeRange(2.0, 4.0);
    grid.setTakes(shortTake, longTake, QStringLiteral("corpus/2|corpus/1"));
    CHECK(grid.timeRange() == std::pair(0.0, 20.0));

    // The same takes recomputed (a live take, a designed take dragged): the zoom stays.
    grid.setTimeRange(2.0, 4.0);
    grid.setTakes(test::syntheticPuppetTake(36, 1.0), longTake, QStringLiteral("corpus/2|corpus/1"));
    CHECK(grid.timeRange() == std::pair(2.0, 4.0));
    // ...and a view of the whole take follows its new length, once the drag ends.
    grid.setTakes(shortTake, nullptr, QStringLiteral("live/designed|"));
    REQUIRE(grid.timeRange() == std::pair(0.0, 7.0));
    grid.beginInteraction();
    grid.setTakes(test::syntheticPuppetTake(46), nullptr, QStringLiteral("live/designed|"));
    CHECK(grid.timeRange() == std::pair(0.0, 7.0)); // held during the drag
    grid.endInteraction();
    CHECK(grid.timeRange() == std::pair(0.0, 9.0));
}

TEST_CASE("every value axis names its channel's unit", "[widgets][graph_grid][units]")
{
    widgets::GraphGrid grid;
    const auto take = test::syntheticPuppetTake(30);
    grid.setTakes(take, nullptr);
    showGrid(grid);
    REQUIRE(grid.graphCount() == 24);
    for (int g = 0; g < grid.graphCount(); ++g) {
        const auto channel = *widgets::findChannel(*take, grid.graphCell(g).part, grid.graphCell(g).dof);
        INFO("graph " << g);
        CHECK(grid.graphValueLabel(g) == QString::fromStdString(take->channels[std::size_t(channel)].unit));
        CHECK_FALSE(grid.graphValueLabel(g).isEmpty());
    }
    // A take with other units relabels the axes.
    auto millimetres = std::make_shared<analysis::Take>(*take);
    for (auto& channel : millimetres->channels)
        if (channel.unit == "cm") channel.unit = "mm";
    grid.setTakes(millimetres, nullptr, QStringLiteral("other"));
    CHECK(grid.graphValueLabel(0) == QStringLiteral("mm"));
}

TEST_CASE("in a short widget the graphs keep a readable height and scroll", "[widgets][graph_grid][layout]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(30), nullptr);
    showGrid(grid, QSize(500, 240));
    QCoreApplication::processEvents(); // the plot lays out its graphs on the queued replot
    grid.plot()->replot();
    auto* scroll = grid.findChild<QScrollArea*>("graphScroll");
    REQUIRE(scroll != nullptr);
    CHECK(scroll->verticalScrollBar()->isVisible());
    // 12 rows, none squeezed below the readable height.
    for (int g = 0; g < grid.graphCount(); ++g) {
        INFO("graph " << g << ": " << grid.graphRect(g).height() << " pixels high");
        CHECK(grid.graphRect(g).height() >= widgets::GraphGrid::kMinimumGraphHeight - 16);
    }
    // Tall enough: no scroll bar, the graphs share the height.
    grid.resize(500, 900);
    QCoreApplication::processEvents();
    CHECK_FALSE(scroll->verticalScrollBar()->isVisible());
}

TEST_CASE("the time read-out never moves the scrub bar or its ticks", "[widgets][timeline]")
{
    widgets::TimelineWidget timeline;
    timeline.resize(900, 40);
    timeline.setDuration(20.4, 5.0);
    timeline.setBoundaries({2.0, 9.5, 15.0});
    timeline.show();
    REQUIRE(QTest::qWaitForWindowExposed(&timeline));
    auto* bar = timeline.scrubBar();
    const QRect geometry = bar->geometry();
    const int tick = bar->xOfTime(9.5);
    const int labelWidth = timeline.timeLabel()->width();
    QStringList texts;
    for (double seconds : {0.0, 1.2, 9.99, 10.0, 11.11, 18.8, 20.4}) {
        timeline.setTime(seconds);
        QCoreApplication::processEvents();
        texts << timeline.timeLabel()->text();
        INFO("at " << seconds << " s: " << timeline.timeLabel()->text().toStdString());
        CHECK(bar->geometry() == geometry);
        CHECK(bar->xOfTime(9.5) == tick);
        CHECK(timeline.timeLabel()->width() == labelWidth);
        // The whole text fits the label.
        CHECK(timeline.timeLabel()->fontMetrics().horizontalAdvance(timeline.timeLabel()->text()) <= labelWidth);
    }
    CHECK(texts.front() != texts.back());
}

TEST_CASE("a bounded spin box takes a typed value beyond its limits and says it clamped it", "[widgets][spinbox]")
{
    widgets::BoundedSpinBox box;
    box.setRange(1, 60);
    box.setSuffix(QStringLiteral(" frames"));
    box.setValue(20);
    box.setDescription(QStringLiteral("T_cmp: search band."));
    CHECK(box.toolTip() == QStringLiteral("T_cmp: search band. From 1 to 60 frames."));
    box.show();
    REQUIRE(QTest::qWaitForWindowExposed(&box));
    QSignalSpy clamped(&box, &widgets::BoundedSpinBox::clamped);
    QSignalSpy changed(&box, &QSpinBox::valueChanged);
    box.setFocus();
    box.selectAll();
    QTest::keyClicks(&box, QStringLiteral("100"));
    CHECK(changed.count() == 0); // typing applies nothing before Enter (not 1, then 10)
    QTest::keyClick(&box, Qt::Key_Return);
    CHECK(box.value() == 60); // the limit, not "10"
    REQUIRE(clamped.count() == 1);
    CHECK(clamped.at(0).at(0).toInt() == 100);
    CHECK(clamped.at(0).at(1).toInt() == 60);
    CHECK(changed.count() == 1);
    // Within the limits: applied as typed, nothing reported.
    box.selectAll();
    QTest::keyClicks(&box, QStringLiteral("30"));
    QTest::keyClick(&box, Qt::Key_Return);
    CHECK(box.value() == 30);
    CHECK(clamped.count() == 1);
    // Below the minimum.
    box.selectAll();
    QTest::keyClicks(&box, QStringLiteral("0"));
    QTest::keyClick(&box, Qt::Key_Return);
    CHECK(box.value() == 1);
    REQUIRE(clamped.count() == 2);
    CHECK(clamped.at(1).at(0).toInt() == 0);
}
