#include "analysis/decompose/km2o.h"

#include <catch2/catch.hpp>

#include <random>

using namespace bunraku::analysis;

namespace {

/// K realisations of an AR(3) process, frames x K.
Eigen::MatrixXd arSeries(int frames, int takes, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(frames, takes);
    for (int k = 0; k < takes; ++k)
        for (int t = 0; t < frames; ++t)
            x(t, k) = (t > 0 ? 0.6 * x(t - 1, k) : 0.0) - (t > 1 ? 0.3 * x(t - 2, k) : 0.0) + (t > 2 ? 0.1 * x(t - 3, k) : 0.0) +
                      normal(rng);
    return x;
}

} // namespace

TEST_CASE("M_max is floor(3 sqrt(T+1)) - 1")
{
    CHECK(maxCorrelationLength(106) == 29); // the puppet takes: T = 105
    CHECK(maxCorrelationLength(301) == 51); // T = 300 (the thesis quotes 50 for "T = 300" samples)
    CHECK(maxCorrelationLength(1001) == 93);
}

TEST_CASE("the forward/backward recursion equals a direct Yule-Walker solve for every order")
{
    const Eigen::MatrixXd x = arSeries(106, 5, 7);
    const int maxM = maxCorrelationLength(x.rows());
    auto data = km2oLangevinData(x, maxM);
    REQUIRE(data.ok());
    auto r = biasedAutocovariance(x, maxM);
    REQUIRE(r.ok());
    for (int n = 0; n <= maxM; ++n) {
        auto yw = yuleWalkerPredictor(*r, n);
        REQUIRE(yw.ok());
        INFO("order " << n);
        CHECK(data->varianceForward(n) == Approx(yw->innovationVariance).epsilon(1e-9));
        CHECK(data->varianceBackward(n) == Approx(yw->innovationVariance).epsilon(1e-9));
        for (int s = 0; s < n; ++s) {
            CHECK(data->gammaPlus(n, s) == Approx(-yw->coefficients(n - 1 - s)).margin(1e-9)); // lag n - s
            CHECK(data->gammaMinus(n, s) == Approx(data->gammaPlus(n, s)).margin(1e-12));
        }
    }
}

TEST_CASE("the recursion on an AR(3) series finds its coefficients at order 3")
{
    const Eigen::MatrixXd x = arSeries(2000, 5, 3);
    auto data = km2oLangevinData(x, 5);
    REQUIRE(data.ok());
    CHECK(data->gammaPlus(3, 2) == Approx(-0.6).margin(0.03));
    CHECK(data->gammaPlus(3, 1) == Approx(0.3).margin(0.03));
    CHECK(data->gammaPlus(3, 0) == Approx(-0.1).margin(0.03));
    CHECK(data->varianceForward(3) == Approx(1.0).margin(0.05));
    CHECK(data->partialForward(5) == Approx(0.0).margin(0.03)); // beyond the model order
}

TEST_CASE("a correlation length above M_max is a clear error")
{
    const Eigen::MatrixXd x = arSeries(106, 2, 1);
    auto data = km2oLangevinData(x, 30);
    REQUIRE_FALSE(data.ok());
    CHECK(data.error().code == ErrorCode::InvalidArgument);
    CHECK(data.error().message.find("M_max") != std::string::npos);
    CHECK(data.error().message.find("29") != std::string::npos);
}

TEST_CASE("constant data is a numerical error, not a crash")
{
    const Eigen::MatrixXd x = Eigen::MatrixXd::Zero(50, 3);
    auto data = km2oLangevinData(x, 3);
    REQUIRE_FALSE(data.ok());
    CHECK(data.error().code == ErrorCode::Numerical);
}
