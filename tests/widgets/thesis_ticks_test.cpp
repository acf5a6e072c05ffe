#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"
#include "widgets/scale_error_plot.h"

#include "tests/widgets/synthetic_take.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <QCheckBox>
#include <QTest>

#include <cmath>

using namespace bunraku;

namespace {

/// The ticks an axis drew at its last replot, with their common step (0 when uneven).
double tickStep(QCPAxis* axis, int* count = nullptr)
{
    const QVector<double> ticks = axis->tickVector();
    if (count) *count = int(ticks.size());
    if (ticks.size() < 2) return 0.0;
    const double step = ticks[1] - ticks[0];
    for (int i = 2; i < ticks.size(); ++i)
        if (std::fabs(ticks[i] - ticks[i - 1] - step) > 1e-9) return 0.0;
    return step;
}

} // namespace

TEST_CASE("thesis ticks: value ticks every 10 units and time ticks every 2 s at any zoom", "[widgets][graph_grid]")
{
    widgets::GraphPanel panel;
    auto take = test::syntheticPuppetTake(106, 0.0);
    // values over several tens of units, as the puppet's positions in cm
    take->values *= 8.0;
    panel.setTakes(take, nullptr);
    panel.resize(1000, 800);
    panel.show();
    REQUIRE(QTest::qWaitForWindowExposed(&panel));
    auto* box = panel.findChild<QCheckBox*>("thesisTicks");
    REQUIRE(box);
    CHECK_FALSE(panel.grid()->thesisTicks());
    box->setChecked(true);
    CHECK(panel.grid()->thesisTicks());
    auto* grid = panel.grid();
    auto* plot = grid->plot();
    grid->setTimeRange(0.0, 21.0);
    plot->replot();
    const QRect rect = grid->graphRect(23);
    REQUIRE(rect.isValid());
    QCPAxisRect* axes = plot->axisRect(23);
    int count = 0;
    CHECK(tickStep(axes->axis(QCPAxis::atLeft), &count) == Approx(10.0));
    CHECK(count >= 2);
    CHECK(tickStep(axes->axis(QCPAxis::atBottom)) == Approx(2.0));
    // zoomed out, the time ticks stay 2 s apart (the default would take multiples of 2 s)
    grid->setTimeRange(0.0, 200.0);
    plot->replot();
    CHECK(tickStep(axes->axis(QCPAxis::atBottom)) == Approx(2.0));
    box->setChecked(false);
    plot->replot();
    CHECK(tickStep(axes->axis(QCPAxis::atBottom)) > 2.0);
    CHECK(tickStep(axes->axis(QCPAxis::atLeft)) != Approx(10.0));
    // a rebuilt layout keeps the choice
    panel.setThesisTicks(true);
    panel.setGraphLayout(widgets::GraphLayout::OnePart);
    grid->setTimeRange(0.0, 21.0);
    plot->replot();
    CHECK(tickStep(plot->axisRect(0)->axis(QCPAxis::atBottom)) == Approx(2.0));
}

TEST_CASE("the scale error plot draws one curve per DOF and the mean", "[widgets]")
{
    widgets::ScaleErrorPlot plot;
    analysis::ApproximationError error;
    error.scales = {1, 2, 3};
    error.relativeError = Eigen::MatrixXd(3, 2);
    error.relativeError << 0.5, 0.3, 0.4, 0.2, 0.35, std::nan("");
    error.meanRelativeError = Eigen::Vector3d(0.4, 0.3, 0.35);
    plot.setError(error, {"axis.x", "axis.y"}, "greeting/friendly");
    REQUIRE(plot.curveCount() == 3);
    CHECK(plot.value(0, 2) == Approx(0.4));
    CHECK(plot.value(2, 3) == Approx(0.35));
    plot.setError({}, {}, {});
    CHECK(plot.curveCount() == 0);
}

TEST_CASE("the scale error plot's legend and axis titles stay clear of its curves in a narrow dock", "[widgets]")
{
    widgets::ScaleErrorPlot plot;
    analysis::ApproximationError error;
    error.scales = {1, 2, 3, 4, 5, 6, 7, 8};
    error.relativeError = Eigen::MatrixXd::Constant(8, 6, 0.4);
    error.meanRelativeError = Eigen::VectorXd::Constant(8, 0.4);
    plot.setError(error, {"x", "y", "z", "rot_x", "rot_y", "rot_z"}, "wave/active");
    // The Design dock at 1366 x 768: about 320 pixels wide.
    plot.resize(320, 220);
    plot.show();
    REQUIRE(QTest::qWaitForWindowExposed(&plot));
    plot.plot()->replot();
    QCustomPlot* custom = plot.plot();
    const QRect axes = custom->axisRect()->outerRect();
    CHECK_FALSE(custom->legend->outerRect().intersects(custom->axisRect()->rect()));
    CHECK(custom->graphCount() == 7);
    // The y axis title fits along the axis (it is drawn rotated): not cut.
    const QFontMetrics metrics(custom->yAxis->labelFont());
    CHECK(metrics.horizontalAdvance(custom->yAxis->label()) <= custom->axisRect()->rect().height());
    CHECK(metrics.horizontalAdvance(custom->xAxis->label()) <= custom->axisRect()->rect().width());
    CHECK(axes.height() >= 100);
}
