#include "analysis/design/approximation_error.h"
#include "analysis/wavelet/cwt_reconstruction.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace bunraku::analysis;

namespace {

Eigen::VectorXd sine(Eigen::Index frames, double cyclesPerFrame, double amplitude = 1.0)
{
    Eigen::VectorXd x(frames);
    for (Eigen::Index t = 0; t < frames; ++t) x[t] = amplitude * std::sin(2.0 * std::numbers::pi * cyclesPerFrame * double(t));
    return x;
}

} // namespace

TEST_CASE("the approximation error of eq. 5.18 is zero for the same motion and per scale and DOF")
{
    Eigen::MatrixXd axis(106, 2);
    axis.col(0) = sine(106, 0.027) + Eigen::VectorXd::Constant(106, 100.0);
    axis.col(1) = sine(106, 0.11, 10.0);
    auto same = approximationErrorByScale(axis, axis);
    REQUIRE(same.ok());
    REQUIRE(same->scales.size() == 16);
    CHECK(same->scales.front() == 1);
    CHECK(same->scales.back() == 16);
    REQUIRE(same->relativeError.rows() == 16);
    REQUIRE(same->relativeError.cols() == 2);
    CHECK(same->relativeError.cwiseAbs().maxCoeff() == 0.0);
    CHECK(same->meanRelativeError.cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("a difference above a scale's frequency leaves the approximations of the larger scales alike")
{
    // the emotional motion adds a 0.2 cycles/frame wiggle (scale 4 of sym3) to a slow motion
    const Eigen::Index frames = 106;
    Eigen::MatrixXd functional(frames, 1);
    functional.col(0) = sine(frames, 0.027, 20.0) + Eigen::VectorXd::Constant(frames, 50.0);
    Eigen::MatrixXd emotional = functional;
    emotional.col(0) += sine(frames, 0.2, 5.0);
    auto error = approximationErrorByScale(functional, emotional);
    REQUIRE(error.ok());
    const Eigen::VectorXd e = error->relativeError.col(0);
    INFO("e(1) " << e[0] << ", e(4) " << e[3] << ", e(8) " << e[7] << ", e(12) " << e[11] << ", e(16) " << e[15]);
    // scale 1: the wiggle still in both approximations: e = |wiggle| / |X_f|
    CHECK(e[0] == Approx(sine(frames, 0.2, 5.0).norm() / functional.norm()).epsilon(0.15));
    // once the scales reach the wiggle's, the approximations agree to a small residue
    CHECK(e[11] < 0.25 * e[0]);
    CHECK(e[15] < 0.25 * e[0]);
    CHECK(error->meanRelativeError[15] == e[15]);
}

TEST_CASE("the approximation error is eq. 5.18 of the two approximations, scale by scale")
{
    Eigen::MatrixXd functional(106, 2), emotional(106, 2);
    functional.col(0) = sine(106, 0.031, 12.0) + Eigen::VectorXd::Constant(106, 80.0);
    functional.col(1) = sine(106, 0.09, 3.0);
    emotional.col(0) = sine(106, 0.029, 15.0) + Eigen::VectorXd::Constant(106, 78.0) + sine(106, 0.17, 1.0);
    emotional.col(1) = sine(106, 0.08, 2.0);
    auto error = approximationErrorByScale(functional, emotional);
    REQUIRE(error.ok());
    for (int c : {1, 5, 16}) {
        std::vector<double> scales;
        for (int s = 1; s <= c; ++s) scales.push_back(s);
        for (Eigen::Index q = 0; q < 2; ++q) {
            auto af = cwtApproximation(functional.col(q), scales);
            auto ae = cwtApproximation(emotional.col(q), scales);
            REQUIRE(af.ok());
            REQUIRE(ae.ok());
            const double direct = (*ae - *af).norm() / functional.col(q).norm();
            CHECK(error->relativeError(c - 1, q) == Approx(direct).epsilon(1e-9));
        }
        CHECK(error->meanRelativeError(c - 1) == Approx(0.5 * (error->relativeError(c - 1, 0) + error->relativeError(c - 1, 1))));
    }
}

TEST_CASE("the approximation error rejects mismatched or bad input")
{
    const Eigen::MatrixXd a = Eigen::MatrixXd::Ones(50, 6);
    CHECK(approximationErrorByScale(a, Eigen::MatrixXd::Ones(49, 6)).error().code == ErrorCode::InvalidArgument);
    ApproximationErrorOptions options;
    options.maxScale = 0;
    CHECK(approximationErrorByScale(a, a, options).error().code == ErrorCode::InvalidArgument);
    Eigen::MatrixXd bad = a;
    bad(3, 2) = std::nan("");
    CHECK(approximationErrorByScale(a, bad).error().code == ErrorCode::Numerical);
    // a DOF that is zero throughout has no relative error (NaN), the mean skips it
    Eigen::MatrixXd zero = a;
    zero.col(5).setZero();
    auto result = approximationErrorByScale(zero, zero);
    REQUIRE(result.ok());
    CHECK(std::isnan(result->relativeError(0, 5)));
    CHECK(result->meanRelativeError[0] == 0.0);
}
