#include "analysis/synth/demo_corpus.h"
#include "analysis/synth/motion_curves.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis::synth;

TEST_CASE("minimum-jerk step rises from 0 to 1 with flat ends and symmetry", "[synth]")
{
    CHECK(minimumJerk(-1.0) == 0.0);
    CHECK(minimumJerk(0.0) == 0.0);
    CHECK(minimumJerk(1.0) == 1.0);
    CHECK(minimumJerk(2.0) == 1.0);
    CHECK(minimumJerk(0.5) == Approx(0.5));
    const double x = GENERATE(0.1, 0.25, 0.4);
    CHECK(minimumJerk(x) + minimumJerk(1.0 - x) == Approx(1.0));
    // Velocity vanishes at the ends: a small step changes the value by O(h^3).
    CHECK(minimumJerk(1e-3) < 1e-8);
}

TEST_CASE("monotone cubic passes through its knots, never decreases and inverts", "[synth]")
{
    const MonotoneCubic map({0, 10, 24, 50, 105}, {0, 12, 20, 55, 105});
    CHECK(map(0) == Approx(0).margin(1e-12));
    CHECK(map(24) == Approx(20));
    CHECK(map(50) == Approx(55));
    CHECK(map(105) == Approx(105));
    double previous = map(0);
    for (double x = 0.1; x <= 105.0; x += 0.1) {
        const double y = map(x);
        CHECK(y > previous);
        previous = y;
    }
    for (double y : {0.5, 11.0, 33.3, 99.0}) CHECK(map(map.inverse(y)) == Approx(y).margin(1e-9));
}

TEST_CASE("angles wrap into the range above -180 up to 180", "[synth]")
{
    CHECK(wrapDegrees(180.0) == 180.0);
    CHECK(wrapDegrees(-180.0) == 180.0);
    CHECK(wrapDegrees(181.0) == Approx(-179.0));
    CHECK(wrapDegrees(-181.0) == Approx(179.0));
    CHECK(wrapDegrees(725.0) == Approx(5.0));
    CHECK(wrapDegrees(-3.5) == -3.5);
}

TEST_CASE("demo random source is reproducible and has the stated moments", "[synth]")
{
    DemoRandom a(42), b(42), c(43);
    double sum = 0.0, sumSquares = 0.0;
    bool differs = false;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double x = a.gaussian();
        CHECK(x == b.gaussian());
        differs = differs || x != c.gaussian();
        sum += x;
        sumSquares += x * x;
    }
    CHECK(differs);
    CHECK(sum / n == Approx(0.0).margin(0.03));
    CHECK(sumSquares / n == Approx(1.0).epsilon(0.03));
    for (int i = 0; i < 1000; ++i) {
        const int k = a.uniformInt(5, 10);
        CHECK(k >= 5);
        CHECK(k <= 10);
        const double u = a.uniform();
        CHECK(u >= 0.0);
        CHECK(u < 1.0);
    }
}

TEST_CASE("cubic motion interpolation hits the samples and reproduces straight lines", "[synth]")
{
    Eigen::MatrixXd motion(6, 2);
    for (int r = 0; r < 6; ++r) {
        motion(r, 0) = 2.0 * r - 1.0;          // a line
        motion(r, 1) = std::sin(0.7 * r);      // a curve
    }
    for (int r = 0; r < 6; ++r) CHECK((interpolateMotion(motion, r) - motion.row(r)).norm() < 1e-12);
    CHECK(interpolateMotion(motion, 2.25)(0) == Approx(3.5));
    CHECK(interpolateMotion(motion, 0.6)(0) == Approx(0.2));
    CHECK(interpolateMotion(motion, -3.0)(1) == motion(0, 1));
    CHECK(interpolateMotion(motion, 9.0)(1) == motion(5, 1));
    CHECK(interpolateMotion(motion, 2.5)(1) == Approx(std::sin(0.7 * 2.5)).margin(0.02));
    const Eigen::VectorXd frames = Eigen::VectorXd::LinSpaced(11, 0.0, 5.0);
    const Eigen::MatrixXd resampled = resampleMotion(motion, frames);
    REQUIRE(resampled.rows() == 11);
    CHECK(resampled(4, 0) == Approx(3.0));
}
