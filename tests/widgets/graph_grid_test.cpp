#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"

#include "widgets/take_series.h"

#include "analysis/core/puppet_layout.h"

#include "tests/widgets/synthetic_take.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <QComboBox>
#include <QCompleter>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>

using namespace bunraku;
using widgets::GraphLayout;
using widgets::TwoTakeMode;

namespace {

void showGrid(widgets::GraphGrid& grid)
{
    grid.resize(900, 700);
    grid.show();
    REQUIRE(QTest::qWaitForWindowExposed(&grid));
    grid.plot()->replot();
    QCoreApplication::processEvents();
}

} // namespace

TEST_CASE("every graph's cursor and moving points follow the time", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    const auto takeA = test::syntheticPuppetTake(60);
    const auto takeB = test::syntheticPuppetTake(40, 5.0);
    grid.setTakes(takeA, takeB);
    showGrid(grid);
    REQUIRE(grid.graphCount() == 24);
    for (double t : {0.0, 3.3, 7.9, 11.0}) {
        grid.setCursorTime(t);
        for (int g = 0; g < grid.graphCount(); ++g) {
            REQUIRE(grid.graphCursorTime(g) == t);
            const auto& cell = grid.graphCell(g);
            const auto channel = *widgets::findChannel(*takeA, cell.part, cell.dof);
            REQUIRE(grid.graphPointValue(g, 0).value() == Approx(*widgets::valueAt(*takeA, channel, t)));
            // B is 39 frames = 7.8 s long: its point disappears after its end.
            REQUIRE(grid.graphPointValue(g, 1).has_value() == (t <= takeB->duration()));
            if (t <= takeB->duration())
                REQUIRE(grid.graphPointValue(g, 1).value() == Approx(*widgets::valueAt(*takeB, channel, t)));
        }
    }
}

TEST_CASE("moving the cursor replots only the cursor layer, never the curves", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(60), test::syntheticPuppetTake(60, 1.0));
    grid.setTwoTakeMode(TwoTakeMode::SideBySide);
    showGrid(grid);
    REQUIRE(grid.graphCount() == 48);
    QSignalSpy fullReplots(grid.plot(), &QCustomPlot::beforeReplot);
    for (int frame = 0; frame < 30; ++frame) grid.setCursorTime(frame / 5.0);
    REQUIRE(fullReplots.count() == 0);
    REQUIRE(grid.plot()->layer("cursor")->mode() == QCPLayer::lmBuffered);
    // Changing the data does replot the curves.
    grid.setValueScale(widgets::ValueScale::PerDof);
    REQUIRE(fullReplots.count() == 1);
}

TEST_CASE("the two-take layouts count 48, 12, 8 and 2 graphs side by side", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(30), test::syntheticPuppetTake(30, 1.0));
    const auto [layout, overlay, sideBySide] = GENERATE(table<GraphLayout, int, int>({
        {GraphLayout::AllChannels, 24, 48},
        {GraphLayout::OnePart, 6, 12},
        {GraphLayout::OneDof, 4, 8},
        {GraphLayout::Single, 1, 2},
    }));
    grid.setGraphLayout(layout);
    grid.setTwoTakeMode(TwoTakeMode::Overlay);
    REQUIRE(grid.graphCount() == overlay);
    REQUIRE(grid.plot()->graphCount() == 2 * overlay); // A and B curves in each graph
    grid.setTwoTakeMode(TwoTakeMode::SideBySide);
    REQUIRE(grid.graphCount() == sideBySide);
    REQUIRE(grid.plot()->axisRectCount() == sideBySide);
}

TEST_CASE("zooming time in one graph zooms every graph", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(100), nullptr);
    showGrid(grid);
    REQUIRE(grid.timeRange().second == Approx(99.0 / 5.0));
    const QRect rect = grid.graphRect(5);
    QWheelEvent wheel(QPointF(rect.center()), grid.plot()->mapToGlobal(QPointF(rect.center())), QPoint(), QPoint(0, 240),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(grid.plot(), &wheel);
    const auto [lower, upper] = grid.timeRange();
    REQUIRE(upper - lower < 99.0 / 5.0 * 0.9);
    for (int g = 0; g < grid.graphCount(); ++g) {
        const QCPRange range = grid.plot()->axisRect(g)->axis(QCPAxis::atBottom)->range();
        REQUIRE(range.lower == Approx(lower));
        REQUIRE(range.upper == Approx(upper));
    }
    grid.resetTimeRange();
    REQUIRE(grid.timeRange().first == 0.0);
    REQUIRE(grid.timeRange().second == Approx(99.0 / 5.0));
}

TEST_CASE("pressing and dragging in a graph scrubs the time under the mouse", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(100), nullptr);
    showGrid(grid);
    QSignalSpy scrubbed(&grid, &widgets::GraphGrid::timeScrubbed);
    const QRect rect = grid.graphRect(13);
    const QPoint quarter(rect.left() + rect.width() / 4, rect.center().y());
    const QPoint threeQuarters(rect.left() + 3 * rect.width() / 4, rect.center().y());
    QTest::mousePress(grid.plot(), Qt::LeftButton, Qt::NoModifier, quarter);
    QMouseEvent move(QEvent::MouseMove, QPointF(threeQuarters), grid.plot()->mapToGlobal(QPointF(threeQuarters)),
                     Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(grid.plot(), &move);
    QTest::mouseRelease(grid.plot(), Qt::LeftButton, Qt::NoModifier, threeQuarters);
    REQUIRE(scrubbed.count() == 2);
    const double duration = 99.0 / 5.0;
    REQUIRE(scrubbed[0][0].toDouble() == Approx(duration / 4).margin(duration / 50));
    REQUIRE(scrubbed[1][0].toDouble() == Approx(3 * duration / 4).margin(duration / 50));
}

TEST_CASE("per-DOF scaling gives graphs of one DOF the same value range", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(60), nullptr);
    grid.setValueScale(widgets::ValueScale::PerDof);
    for (int g = 0; g < grid.graphCount(); ++g)
        for (int h = 0; h < grid.graphCount(); ++h)
            if (grid.graphCell(g).dof == grid.graphCell(h).dof) REQUIRE(grid.graphValueRange(g) == grid.graphValueRange(h));
    grid.setValueScale(widgets::ValueScale::PerGraph);
    // head.x (channel 0, amplitude 1) and hand.x (channel 18, amplitude 19) now differ.
    REQUIRE(grid.graphValueRange(0) != grid.graphValueRange(12 + 6));
}

namespace {

/// `take` with every value multiplied by `factor` (a new take, as a live result would be).
std::shared_ptr<analysis::Take> scaled(const analysis::Take& take, double factor)
{
    auto result = std::make_shared<analysis::Take>(take);
    result->values *= factor;
    return result;
}

/// The value range autoscaling gives `take`'s graph `graph` (per graph, padded).
std::pair<double, double> autoscaledRange(const std::shared_ptr<analysis::Take>& take, int graph)
{
    widgets::GraphGrid reference;
    reference.setTakes(take, nullptr);
    return reference.graphValueRange(graph);
}

} // namespace

TEST_CASE("during an interaction new data redraws only the curves and value ranges autoscale when it ends",
          "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    const auto original = test::syntheticPuppetTake(60);
    grid.setTakes(original, nullptr);
    grid.setGhost(original);
    showGrid(grid);
    REQUIRE(grid.graphCount() == 24);
    REQUIRE(grid.plot()->layer("live")->mode() == QCPLayer::lmBuffered);
    const auto before = grid.graphValueRange(18);
    QSignalSpy fullReplots(grid.plot(), &QCustomPlot::beforeReplot);

    grid.beginInteraction();
    std::shared_ptr<analysis::Take> last;
    for (double factor : {1.5, 2.0, 3.0}) {
        last = scaled(*original, factor);
        grid.setTakes(last, nullptr);
    }
    CHECK(fullReplots.count() == 0);
    CHECK(grid.graphValueRange(18) == before); // held
    // The curves and the moving points show the new data.
    grid.setCursorTime(2.0);
    const auto channel = *widgets::findChannel(*last, grid.graphCell(18).part, grid.graphCell(18).dof);
    CHECK(grid.graphPointValue(18, 0).value() == Approx(*widgets::valueAt(*last, channel, 2.0)));
    QCPGraph* curve = nullptr;
    for (int i = 0; i < grid.plot()->graphCount(); ++i)
        if (grid.plot()->graph(i)->layer()->name() == "live" &&
            grid.plot()->graph(i)->keyAxis()->axisRect()->rect().translated(grid.plot()->pos()) == grid.graphRect(18))
            curve = grid.plot()->graph(i);
    REQUIRE(curve != nullptr);
    CHECK(curve->data()->at(7)->value == Approx(last->values(7, channel)));

    grid.endInteraction();
    CHECK(fullReplots.count() == 1);
    const auto after = grid.graphValueRange(18);
    CHECK(after != before);
    // The ghost (the original) still counts in the range: it is the union of both.
    const auto ghostRange = autoscaledRange(original, 18);
    const auto lastRange = autoscaledRange(last, 18);
    CHECK(after.first == Approx(std::min(ghostRange.first, lastRange.first)));
    CHECK(after.second == Approx(std::max(ghostRange.second, lastRange.second)));
}

TEST_CASE("take A's ghost and per-channel result are drawn in A's graphs only, never in B's column side by side",
          "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    const auto takeA = test::syntheticPuppetTake(60);
    grid.setTakes(takeA, test::syntheticPuppetTake(60, 1.0));
    grid.setGhost(scaled(*takeA, 0.8));
    grid.setPerChannelGhost(scaled(*takeA, 1.2));
    showGrid(grid);
    // Overlaid: every graph shows A (and B), so every graph has A's two ghosts.
    REQUIRE(grid.graphCount() == 24);
    CHECK(grid.plot()->graphCount() == 24 * 4);
    grid.setTwoTakeMode(TwoTakeMode::SideBySide);
    REQUIRE(grid.graphCount() == 48);
    // Side by side: A's 24 graphs hold A's curve and both ghosts, B's 24 hold B's curve alone.
    CHECK(grid.plot()->graphCount() == 24 * 3 + 24);
    int withGhosts = 0, alone = 0;
    for (int r = 0; r < grid.plot()->axisRectCount(); ++r) {
        const auto curves = grid.plot()->axisRect(r)->graphs().size();
        withGhosts += curves == 3;
        alone += curves == 1;
    }
    CHECK(withGhosts == 24);
    CHECK(alone == 24);
    // Back to overlaid, and side by side again: the structure follows each time.
    grid.setTwoTakeMode(TwoTakeMode::Overlay);
    CHECK(grid.plot()->graphCount() == 24 * 4);
    grid.setTwoTakeMode(TwoTakeMode::SideBySide);
    CHECK(grid.plot()->graphCount() == 24 * 3 + 24);
}

TEST_CASE("the per-channel result is drawn beside the ghost and follows a drag when it ends", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    const auto original = test::syntheticPuppetTake(60);
    grid.setTakes(original, nullptr);
    grid.setGhost(original);
    const auto perChannel = scaled(*original, 1.2);
    grid.setPerChannelGhost(perChannel);
    showGrid(grid);
    REQUIRE(grid.graphCount() == 24);
    CHECK(grid.ghostTakes()[0] == original);
    CHECK(grid.ghostTakes()[1] == perChannel);
    // Both ghosts are drawn in every graph: two curves below the live layer besides take A's.
    int ghostCurves = 0;
    for (int i = 0; i < grid.plot()->graphCount(); ++i)
        if (grid.plot()->graph(i)->layer()->name() != "live") ++ghostCurves;
    CHECK(ghostCurves == 2 * 24);
    // The per-channel result's values count in the value range.
    const auto range = grid.graphValueRange(18);
    const auto perChannelRange = autoscaledRange(perChannel, 18);
    CHECK(range.first <= perChannelRange.first + 1e-9);
    CHECK(range.second >= perChannelRange.second - 1e-9);

    // A drag: new per-channel results wait (no full replot per step), the last one is shown at the end.
    QSignalSpy fullReplots(grid.plot(), &QCustomPlot::beforeReplot);
    grid.beginInteraction();
    // The curves redrawn on each step are not antialiased (as QCustomPlot's own drags).
    CHECK(grid.plot()->notAntialiasedElements() == QCP::aeAll);
    std::shared_ptr<analysis::Take> last;
    for (double factor : {1.5, 2.0, 3.0}) {
        last = scaled(*original, factor);
        grid.setTakes(last, nullptr);
        grid.setPerChannelGhost(scaled(*original, factor * 1.1));
    }
    // A step whose body agrees with its channels has no per-channel result, the next one has:
    // the dots stay as they were until the end (before, each such step rebuilt all 24 graphs).
    for (double factor : {3.0, 3.1, 3.2, 3.3}) {
        grid.setTakes(scaled(*original, factor), nullptr);
        grid.setPerChannelGhost(factor == 3.0 || factor == 3.2 ? nullptr : scaled(*original, factor * 1.1));
    }
    CHECK(fullReplots.count() == 0);
    CHECK(grid.graphCount() == 24);
    CHECK(grid.ghostTakes()[1] == perChannel);
    const auto lastPerChannel = scaled(*original, 3.3);
    grid.setPerChannelGhost(lastPerChannel);
    grid.endInteraction();
    CHECK(grid.plot()->notAntialiasedElements() == QCP::aeNone);
    CHECK(grid.ghostTakes()[1] == lastPerChannel);
    CHECK(fullReplots.count() >= 1);
    grid.setPerChannelGhost(nullptr);
    CHECK_FALSE(grid.ghostTakes()[1]);
    // None at the end of a drag that began with one: none is shown once it ends.
    grid.setPerChannelGhost(perChannel);
    grid.beginInteraction();
    grid.setPerChannelGhost(nullptr);
    CHECK(grid.ghostTakes()[1] == perChannel);
    grid.endInteraction();
    CHECK_FALSE(grid.ghostTakes()[1]);
}

TEST_CASE("a burst of data changes holds the value ranges until it settles", "[widgets][graph_grid]")
{
    widgets::ManualClock clock; // time moves only when the test says so
    widgets::GraphGrid grid;
    grid.setClock(&clock);
    const auto original = test::syntheticPuppetTake(60);
    grid.setTakes(original, nullptr);
    showGrid(grid);
    // An isolated change autoscales at once.
    const auto doubled = scaled(*original, 2.0);
    clock.advance(widgets::GraphGrid::kSettleMs);
    grid.setTakes(doubled, nullptr);
    CHECK(grid.graphValueRange(5) == autoscaledRange(doubled, 5));
    // The next change follows quickly: ranges are held, then autoscale once it settles.
    QSignalSpy fullReplots(grid.plot(), &QCustomPlot::beforeReplot);
    const auto tripled = scaled(*original, 3.0);
    grid.setTakes(tripled, nullptr);
    CHECK(fullReplots.count() == 0);
    CHECK(grid.graphValueRange(5) == autoscaledRange(doubled, 5));
    clock.advance(widgets::GraphGrid::kSettleMs - 1);
    CHECK(fullReplots.count() == 0);
    clock.advance(1);
    CHECK(fullReplots.count() == 1);
    CHECK(grid.graphValueRange(5) == autoscaledRange(tripled, 5));
}

TEST_CASE("an hour-long take's graphs hold a few points a pixel column, resampled per zoom and never per cursor move",
          "[widgets][graph_grid][envelope]")
{
    // An hour at 120 Hz: 432,000 frames of 24 channels.
    auto take = test::syntheticPuppetTake(432000);
    take->rateHz = 120.0;
    widgets::GraphGrid grid;
    grid.setTakes(take, nullptr);
    showGrid(grid);
    REQUIRE(grid.graphCount() == 24);
    REQUIRE(grid.timeRange().second == Approx(take->duration()));
    auto checkCurves = [&](double lower, double upper) {
        for (int g = 0; g < grid.graphCount(); ++g) {
            const auto* curve = grid.curve(g, 0);
            const QCPAxisRect* rect = curve->keyAxis()->axisRect();
            REQUIRE(curve->dataCount() > 0);
            REQUIRE(curve->dataCount() <= 4 * rect->width() + 6);
            // The curve spans the view to within a pixel (points sit at their buckets' middles).
            const double pixel = (upper - lower) / rect->width();
            REQUIRE(curve->data()->constBegin()->key <= std::max(0.0, lower) + pixel);
            REQUIRE((curve->data()->constEnd() - 1)->key >= std::min(take->duration(), upper) - pixel);
            // Its extremes are the channel's extremes in view.
            const auto& cell = grid.graphCell(g);
            const auto channel = *widgets::findChannel(*take, cell.part, cell.dof);
            const auto first = Eigen::Index(std::ceil(lower * 120.0));
            const auto last = std::min<Eigen::Index>(take->frameCount() - 1, Eigen::Index(std::floor(upper * 120.0)));
            const auto values = take->values.col(channel).segment(first, last - first + 1);
            double low = 1e300, high = -1e300;
            for (auto point = curve->data()->constBegin(); point != curve->data()->constEnd(); ++point) {
                low = std::min(low, point->value);
                high = std::max(high, point->value);
            }
            REQUIRE(low <= values.minCoeff());
            REQUIRE(high >= values.maxCoeff());
        }
    };
    checkCurves(0.0, take->duration());

    const int samplings = grid.samplingCount();
    QSignalSpy fullReplots(grid.plot(), &QCustomPlot::beforeReplot);
    for (int frame = 0; frame < 120; ++frame) grid.setCursorTime(1000.0 + frame / 60.0);
    REQUIRE(grid.samplingCount() == samplings);
    REQUIRE(fullReplots.count() == 0);
    const auto channel3 = *widgets::findChannel(*take, grid.graphCell(3).part, grid.graphCell(3).dof);
    REQUIRE(grid.graphPointValue(3, 0).value() == Approx(*widgets::valueAt(*take, channel3, 1000.0 + 119 / 60.0)));

    // Zoom to a 10 s window: resampled once, every frame in view drawn.
    grid.setTimeRange(1800.0, 1810.0);
    REQUIRE(grid.samplingCount() == samplings + 1);
    checkCurves(1800.0, 1810.0);
    // The view's width changes: resampled at the new width, in the replot.
    grid.resize(500, 700);
    grid.plot()->replot();
    REQUIRE(grid.samplingCount() == samplings + 2);
    checkCurves(1800.0, 1810.0);
}

TEST_CASE("48 graphs at a laptop's size show every name and value without overlap", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    grid.setTakes(test::syntheticPuppetTake(60), test::syntheticPuppetTake(60, 1.0));
    grid.setTwoTakeMode(TwoTakeMode::SideBySide);
    // The graphs dock at 1366 x 768 with A and B side by side.
    for (const QSize size : {QSize(560, 560), QSize(900, 700)}) {
        grid.resize(size);
        grid.show();
        REQUIRE(QTest::qWaitForWindowExposed(&grid));
        grid.setCursorTime(3.3);
        grid.plot()->replot();
        QCoreApplication::processEvents();
        REQUIRE(grid.graphCount() == 48);
        int overlapping = 0, empty = 0;
        for (int g = 0; g < grid.graphCount(); ++g) {
            const auto [name, value] = grid.graphTextBoxes(g);
            empty += value.width() < 4.0 ? 1 : 0;
            if (name.intersects(value)) {
                ++overlapping;
                INFO("graph " << g << " at " << size.width() << "x" << size.height());
                CHECK_FALSE(name.intersects(value));
            }
        }
        CHECK(overlapping == 0);
        CHECK(empty == 0);
    }
}

TEST_CASE("a take of 10000 channels builds the first 96 graphs and says how many it leaves out", "[widgets][graph_grid]")
{
    // Issue 30: a take of 10,000 channels x 20 frames showed no window after 600 s (a plot per
    // channel; QCustomPlot's layout work grows with the square of the plots).
    auto wide = std::make_shared<analysis::Take>();
    wide->rateHz = 5.0;
    for (int c = 0; c < 10000; ++c) wide->channels.push_back({"c" + std::to_string(c), "x", "cm"});
    wide->values.resize(20, 10000);
    for (Eigen::Index k = 0; k < 20; ++k)
        for (Eigen::Index c = 0; c < 10000; ++c) wide->values(k, c) = test::syntheticValue(k, c % 50, 0.0);
    wide->labels = {"wide", "none", 1, "synthetic"};

    widgets::GraphPanel panel;
    panel.resize(900, 700);
    panel.setTakes(wide, nullptr, QStringLiteral("wide"));
    panel.show();
    REQUIRE(QTest::qWaitForWindowExposed(&panel));
    auto* grid = panel.findChild<widgets::GraphGrid*>();
    REQUIRE(grid);
    CHECK(grid->graphCount() == widgets::GraphGrid::kMaxGraphs);
    CHECK(grid->hiddenGraphCount() == 10000 - widgets::GraphGrid::kMaxGraphs);
    CHECK(grid->graphCell(0).part == "c0");
    CHECK(grid->graphCell(95).part == "c95");
    auto* caption = panel.findChild<QLabel*>(QStringLiteral("graphLimitCaption"));
    REQUIRE(caption);
    CHECK(caption->isVisible());
    CHECK(caption->text().contains(QStringLiteral("96 of 10000")));
    // Every part is one choice away: the part box lists all 10,000, and 'one part' shows any.
    const auto parts = panel.findChildren<QComboBox*>();
    bool listed = false;
    for (auto* box : parts)
        if (box->count() == 10000 && box->itemText(9999) == QStringLiteral("c9999")) listed = true;
    CHECK(listed);

    // A take of 24 channels: every graph, no caption.
    panel.setTakes(test::syntheticPuppetTake(20), nullptr, QStringLiteral("puppet"));
    CHECK(grid->graphCount() == 24);
    CHECK(grid->hiddenGraphCount() == 0);
    CHECK_FALSE(caption->isVisible());
}

TEST_CASE("the part box shows a long part name whole, from its beginning", "[widgets][graph_grid]")
{
    // A GUI walk saw "_right_tip" for the kimono's sleeve_right_tip: the box kept the width of the
    // puppet's short names and showed the end of the longer one.
    widgets::GraphPanel panel;
    panel.resize(900, 700);
    panel.setTakes(test::syntheticPuppetTake(20), nullptr, QStringLiteral("puppet"));
    panel.show();
    REQUIRE(QTest::qWaitForWindowExposed(&panel));
    auto* part = panel.findChild<QComboBox*>(QStringLiteral("graphPart"));
    REQUIRE(part);

    auto take = std::make_shared<analysis::Take>();
    for (const std::string name : {"head", "hem_front", "sleeve_right_tip"})
        for (const auto& channel : analysis::sixDofChannels(name)) take->channels.push_back(channel);
    take->rateHz = 30.0;
    take->values = Eigen::MatrixXd::Zero(20, Eigen::Index(take->channels.size()));
    take->labels = {"bow", "normal", 1, "synthetic"};
    panel.setTakes(take, nullptr, QStringLiteral("kimono"));
    panel.selectPart(QStringLiteral("sleeve_right_tip"));
    QCoreApplication::processEvents();
    REQUIRE(part->currentText() == QStringLiteral("sleeve_right_tip"));
    // The text the line edit has room for holds the whole name, and it is scrolled to its start.
    QLineEdit* edit = part->lineEdit();
    const int room = edit->contentsRect().width() - edit->textMargins().left() - edit->textMargins().right();
    CHECK(room >= edit->fontMetrics().horizontalAdvance(QStringLiteral("sleeve_right_tip")));
    CHECK(edit->cursorPosition() == 0);
    // A name longer than 32 characters shows its beginning.
    auto longer = std::make_shared<analysis::Take>(*take);
    longer->channels.clear();
    for (const std::string name : {"head", "mixamorig:RightHandThumbMetacarpalEnd_Left"})
        for (const auto& channel : analysis::sixDofChannels(name)) longer->channels.push_back(channel);
    longer->values = Eigen::MatrixXd::Zero(20, Eigen::Index(longer->channels.size()));
    panel.setTakes(longer, nullptr, QStringLiteral("long joint"));
    panel.selectPart(QStringLiteral("mixamorig:RightHandThumbMetacarpalEnd_Left"));
    QCoreApplication::processEvents();
    CHECK(part->width() <= part->maximumWidth());
    CHECK(edit->cursorPosition() == 0);
}

TEST_CASE("a skeleton's joints are found by typing in the part box and shown as one joint's graphs", "[widgets][graph_grid]")
{
    // The 22 joints of a Bandai performer, 6 channels each (132 graphs: more than kMaxGraphs).
    const std::vector<std::string> joints{"joint_Root", "Hips",       "Spine",      "Chest",      "Neck",       "Head",
                                          "Shoulder_L", "UpperArm_L", "LowerArm_L", "Hand_L",     "Shoulder_R", "UpperArm_R",
                                          "LowerArm_R", "Hand_R",     "UpperLeg_L", "LowerLeg_L", "Foot_L",     "Toes_L",
                                          "UpperLeg_R", "LowerLeg_R", "Foot_R",     "Toes_R"};
    auto take = std::make_shared<analysis::Take>();
    for (const auto& joint : joints)
        for (const auto& channel : analysis::sixDofChannels(joint)) take->channels.push_back(channel);
    take->rateHz = 30.0;
    take->values = Eigen::MatrixXd::Zero(20, Eigen::Index(take->channels.size()));
    for (Eigen::Index k = 0; k < 20; ++k)
        for (Eigen::Index c = 0; c < take->values.cols(); ++c) take->values(k, c) = test::syntheticValue(k, c, 0.0);
    take->labels = {"wave", "normal", 1, "synthetic"};

    widgets::GraphPanel panel;
    panel.resize(900, 700);
    panel.setTakes(take, nullptr, QStringLiteral("joints"));
    panel.show();
    REQUIRE(QTest::qWaitForWindowExposed(&panel));
    auto* grid = panel.findChild<widgets::GraphGrid*>();
    auto* part = panel.findChild<QComboBox*>(QStringLiteral("graphPart"));
    REQUIRE(grid);
    REQUIRE(part);
    CHECK(part->count() == 22);
    REQUIRE(part->isEditable());
    // Typing a piece of a name offers every joint that contains it, in any case.
    auto* finder = part->completer();
    REQUIRE(finder);
    finder->setCompletionPrefix(QStringLiteral("hand"));
    CHECK(finder->completionCount() == 2);
    finder->setCompletionPrefix(QStringLiteral("_l"));
    CHECK(finder->completionCount() == 8);
    // A typed name chooses that joint; the 'one part' layout shows its 6 graphs.
    panel.setGraphLayout(GraphLayout::OnePart);
    part->lineEdit()->setText(QStringLiteral("upperleg_l"));
    QTest::keyClick(part->lineEdit(), Qt::Key_Return);
    CHECK(panel.selectedPart() == QStringLiteral("UpperLeg_L"));
    REQUIRE(grid->graphCount() == 6);
    CHECK(grid->graphCell(0).part == "UpperLeg_L");
    // Text that names no joint leaves the choice as it was.
    part->lineEdit()->setText(QStringLiteral("elbow"));
    QTest::keyClick(part->lineEdit(), Qt::Key_Return);
    CHECK(panel.selectedPart() == QStringLiteral("UpperLeg_L"));
    CHECK(part->currentText() == QStringLiteral("UpperLeg_L"));
    // Picking a joint (the 3D view's bone picking calls selectPart) shows that joint's graphs.
    panel.selectPart(QStringLiteral("Hand_R"));
    CHECK(grid->graphCell(0).part == "Hand_R");
    // 'One DOF' across the joints: 22 graphs of the chosen DOF.
    panel.setGraphLayout(GraphLayout::OneDof);
    CHECK(grid->graphCount() == 22);

    // All channels of A and B side by side (264 graphs): the limit keeps the same first 48
    // channels of each take, A's on the left, B's on the right, in full columns.
    panel.setTakes(take, take, QStringLiteral("joints A and B"));
    panel.setGraphLayout(GraphLayout::AllChannels);
    panel.setTwoTakeMode(TwoTakeMode::SideBySide);
    REQUIRE(grid->graphCount() == widgets::GraphGrid::kMaxGraphs);
    CHECK(grid->hiddenGraphCount() == 264 - widgets::GraphGrid::kMaxGraphs);
    int onlyB = 0, lastRow = 0;
    for (int g = 0; g < grid->graphCount(); ++g) {
        onlyB += grid->graphCell(g).takes == widgets::GraphTakes::OnlyB ? 1 : 0;
        lastRow = std::max(lastRow, grid->graphCell(g).row);
    }
    CHECK(onlyB == widgets::GraphGrid::kMaxGraphs / 2);
    CHECK(lastRow == widgets::GraphGrid::kMaxGraphs / 4 - 1); // 4 full columns of 24
    CHECK(grid->graphCell(widgets::GraphGrid::kMaxGraphs / 2).part == "joint_Root");
}

TEST_CASE("a drag's steps draw only the graphs in view, and every graph once it ends", "[widgets][graph_grid]")
{
    widgets::GraphGrid grid;
    const auto original = test::syntheticPuppetTake(60);
    grid.setTakes(original, nullptr);
    grid.resize(900, 260); // the 24 graphs scroll: a few rows in view
    grid.show();
    REQUIRE(QTest::qWaitForWindowExposed(&grid));
    grid.plot()->replot();
    QCoreApplication::processEvents();
    REQUIRE(grid.graphCount() == 24);
    auto* scroll = grid.findChild<QScrollArea*>("graphScroll");
    REQUIRE(scroll);
    REQUIRE(scroll->verticalScrollBar()->maximum() > 0);
    // A graph's plotting rectangle in the plot's coordinates, grown by `margin` pixels (its axes
    // and labels around it), against the part of the plot the scroll area shows.
    const auto inView = [&](int g, int margin = 0) {
        const QRect r = grid.graphRect(g);
        const QRect inPlot(grid.plot()->mapFrom(&grid, r.topLeft()), r.size());
        return grid.plot()->visibleRegion().boundingRect().intersects(inPlot.adjusted(-margin, -margin, margin, margin));
    };
    const auto drawn = [&](int g) { return grid.curve(g, 0)->visible(); };

    grid.beginInteraction();
    const auto step = scaled(*original, 1.5);
    grid.setTakes(step, nullptr);
    int hidden = 0, shown = 0;
    for (int g = 0; g < grid.graphCount(); ++g) {
        if (inView(g)) CHECK(drawn(g));
        if (!inView(g, 60)) CHECK_FALSE(drawn(g));
        (drawn(g) ? shown : hidden) += 1;
    }
    CHECK(shown > 0);
    CHECK(hidden > 0);
    // Scrolled during the drag: the graphs now in view are drawn, with the step's values.
    scroll->verticalScrollBar()->setValue(scroll->verticalScrollBar()->maximum());
    QCoreApplication::processEvents();
    const int last = grid.graphCount() - 1;
    CHECK(inView(last));
    CHECK(drawn(last));
    CHECK(grid.graphPointValue(last, 0).has_value());

    grid.endInteraction();
    for (int g = 0; g < grid.graphCount(); ++g) {
        CHECK(drawn(g));
        // Every curve holds the last step's data (sampled on every step, drawn or not).
        CHECK_FALSE(grid.curve(g, 0)->data()->isEmpty());
        CHECK(grid.graphPointValue(g, 0).has_value());
    }
}
