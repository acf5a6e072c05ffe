#include "analysis/design/phase_extraction.h"
#include "analysis/design/warp_curve.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <random>

using namespace bunraku::analysis;

TEST_CASE("a warp curve through collinear points is that line")
{
    WarpCurve curve;
    curve.points = {{0, 3}, {10, 8}, {30, 18}, {50, 28}};
    for (double x = 0; x <= 50; x += 0.7) CHECK(evaluateWarp(curve, x) == Approx(3 + 0.5 * x));
    CHECK(evaluateWarp(curve, -5) == 3.0);
    CHECK(evaluateWarp(curve, 80) == 28.0);
    // passes through every control point
    curve.points = {{0, 0}, {10, 2}, {20, 19}, {30, 20}, {50, 60}};
    for (const WarpPoint& p : curve.points) CHECK(evaluateWarp(curve, p.output) == Approx(p.source));
}

TEST_CASE("dragging control points never makes time run backwards")
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jump(-40.0, 40.0);
    WarpCurve curve = identityWarp(106, 8);
    REQUIRE(validateWarpCurve(curve).ok());
    for (int drag = 0; drag < 300; ++drag) {
        const std::size_t index = std::size_t(random() % curve.points.size());
        const WarpPoint& p = curve.points[index];
        curve = moveControlPoint(curve, index, {p.output + jump(random), p.source + jump(random)});
        REQUIRE(validateWarpCurve(curve).ok());
        const Eigen::VectorXd samples = sampleWarp(curve);
        REQUIRE(samples.size() == 106);
        for (double x = 0; x < 105; x += 0.25) REQUIRE(evaluateWarp(curve, x + 0.25) >= evaluateWarp(curve, x) - 1e-12);
    }
}

TEST_CASE("moving a control point is clamped between its neighbours")
{
    const WarpCurve curve{{{0, 0}, {10, 10}, {20, 20}}, 21};
    const WarpCurve moved = moveControlPoint(curve, 1, {35, -4});
    CHECK(moved.points[1].output == Approx(19.5));
    CHECK(moved.points[1].source == 0.0);
    const WarpCurve end = moveControlPoint(curve, 2, {40, 30});
    CHECK(end.points[2].output == 20.0); // ends keep their frame
    CHECK(end.points[2].source == 30.0);
}

TEST_CASE("a pushing drag moves the points it meets and no others, and keeps the curve monotone")
{
    const WarpCurve curve{{{0, 0}, {10, 10}, {20, 20}, {30, 30}, {40, 40}}, 41};
    // Up past two neighbours: they are pushed up to it; the point beyond them is not touched.
    const WarpCurve up = moveControlPoint(curve, 1, {10, 27}, 0.5, WarpMove::Push);
    CHECK(up.points[1].source == 27.0);
    CHECK(up.points[2].source == 27.0);
    CHECK(up.points[3].source == 30.0);
    CHECK(up.points[0].source == 0.0);
    // Down past the first: it goes down with it; the output is clamped as without pushing.
    const WarpCurve down = moveControlPoint(curve, 2, {35, 3}, 0.5, WarpMove::Push);
    CHECK(down.points[2].output == Approx(29.5));
    CHECK(down.points[2].source == 3.0);
    CHECK(down.points[1].source == 3.0);
    CHECK(down.points[0].source == 0.0);
    CHECK(down.points[3].source == 30.0);
    // Clamp stops where Push goes on.
    CHECK(moveControlPoint(curve, 1, {10, 27}).points[1].source == 20.0);

    std::mt19937 random(11);
    std::uniform_real_distribution<double> jump(-60.0, 60.0);
    WarpCurve pushed = identityWarp(106, 8);
    for (int drag = 0; drag < 300; ++drag) {
        const std::size_t index = std::size_t(random() % pushed.points.size());
        const WarpPoint& p = pushed.points[index];
        pushed = moveControlPoint(pushed, index, {p.output + jump(random), p.source + jump(random)}, 0.5, WarpMove::Push);
        REQUIRE(validateWarpCurve(pushed).ok());
        for (std::size_t i = 1; i < pushed.points.size(); ++i) REQUIRE(pushed.points[i].source >= pushed.points[i - 1].source);
    }
}

TEST_CASE("the inverse warp finds the output frame that shows a source frame")
{
    // a smooth non-identity warp: slow start, fast end
    Eigen::VectorXd samples(106);
    for (int i = 0; i < 106; ++i) samples[i] = 105.0 * std::pow(i / 105.0, 1.6);
    const WarpCurve curve = warpCurveFromSamples(samples, 8);
    REQUIRE(validateWarpCurve(curve).ok());
    for (double source = 0.0; source <= 105.0; source += 3.7) {
        const double output = inverseWarp(curve, source);
        CHECK(evaluateWarp(curve, output) == Approx(source).margin(1e-6));
        CHECK(output >= source - 1e-9); // this warp lags behind the identity
    }
    // the peer: the dense inverse of the sampled curve agrees to within interpolation error
    const Eigen::VectorXd back = invertMonotone(sampleWarp(curve), 106);
    for (int source = 0; source < 106; source += 5) CHECK(inverseWarp(curve, source) == Approx(back[source]).margin(0.2));
    // outside the curve's range: its ends
    CHECK(inverseWarp(curve, -10.0) == 0.0);
    CHECK(inverseWarp(curve, 500.0) == 105.0);
    // a held source frame maps to the first output frame that shows it
    const WarpCurve hold{{{0, 0}, {10, 10}, {20, 10}, {30, 20}}, 31};
    CHECK(inverseWarp(hold, 10.0) == Approx(10.0).margin(1e-6));
    CHECK(inverseWarp(hold, 15.0) > 20.0);
    CHECK(evaluateWarp(hold, inverseWarp(hold, 15.0)) == Approx(15.0).margin(1e-6));
    // an invalid curve is the identity
    CHECK(inverseWarp(WarpCurve{}, 12.5) == 12.5);
}

TEST_CASE("a dense map is summarised by control points it passes through")
{
    Eigen::VectorXd samples(106);
    for (int i = 0; i < 106; ++i) samples[i] = 105.0 * std::pow(i / 105.0, 1.3);
    const WarpCurve curve = warpCurveFromSamples(samples, 8);
    REQUIRE(validateWarpCurve(curve).ok());
    CHECK(curve.points.front().output == 0.0);
    CHECK(curve.points.back().output == 105.0);
    const Eigen::VectorXd back = sampleWarp(curve);
    CHECK((back - samples).cwiseAbs().maxCoeff() < 0.3);
}

TEST_CASE("warp curves round-trip through CSV and bad files are reported with their line")
{
    const auto dir = bunraku::test::scratchDir("warp-csv");
    const WarpCurve curve{{{0, 0}, {8, 5.5}, {20, 21.25}}, 21};
    REQUIRE(writeWarpCsv(curve, dir / "warp.csv").ok());
    const auto read = readWarpCsv(dir / "warp.csv");
    REQUIRE(read.ok());
    CHECK(read->points == curve.points);
    CHECK(read->outputFrames == 21);

    std::ofstream(dir / "bad.csv") << "output_frame,source_frame\n0,0\n5;3\n";
    const auto bad = readWarpCsv(dir / "bad.csv");
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().message.find("bad.csv:3") != std::string::npos);
    std::ofstream(dir / "backwards.csv") << "output_frame,source_frame\n0,0\n5,3\n9,2\n";
    const auto backwards = readWarpCsv(dir / "backwards.csv");
    REQUIRE_FALSE(backwards.ok());
    CHECK(backwards.error().message.find("backwards") != std::string::npos);
}
