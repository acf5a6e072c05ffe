#include "analysis/decompose/spectrum.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace bunraku::analysis;

TEST_CASE("the periodogram peaks at a sinusoid's frequency in Hz and keeps the variance")
{
    const double rate = 5.0;
    Eigen::VectorXd x(100);
    for (int t = 0; t < 100; ++t) x(t) = 3.0 + 2.0 * std::sin(2.0 * std::numbers::pi * 0.8 * t / rate);
    auto s = periodogram(x, rate);
    REQUIRE(s.ok());
    REQUIRE(s->frequencyHz.size() == 51);
    CHECK(s->frequencyHz(50) == Approx(2.5)); // Nyquist of 5 Hz
    Eigen::Index peak = 0;
    s->power.maxCoeff(&peak);
    CHECK(s->frequencyHz(peak) == Approx(0.8));
    const double df = rate / 100.0;
    const double variance = (x.array() - x.mean()).square().mean();
    CHECK(s->power.sum() * df == Approx(variance).epsilon(1e-9));
    CHECK(s->power(0) == Approx(0.0).margin(1e-9)); // mean removed
}

TEST_CASE("Welch's estimate of white noise is flat at 2 sigma^2 / rate")
{
    std::mt19937_64 rng(3);
    std::normal_distribution<double> normal(0.0, 2.0);
    Eigen::VectorXd x(4000);
    for (auto& v : x) v = normal(rng);
    WelchOptions options;
    options.segmentLength = 64;
    auto s = welch(x, 5.0, options);
    REQUIRE(s.ok());
    REQUIRE(s->frequencyHz.size() == 33);
    const double level = 2.0 * 4.0 / 5.0;
    CHECK(s->power.segment(1, 31).mean() == Approx(level).epsilon(0.1));
    CHECK(s->power.segment(1, 31).maxCoeff() < 1.6 * level);
}

TEST_CASE("spectra reject a non-positive rate and non-finite values")
{
    CHECK_FALSE(periodogram(Eigen::VectorXd::Ones(10), 0.0).ok());
    Eigen::VectorXd bad = Eigen::VectorXd::Ones(10);
    bad(3) = std::nan("");
    CHECK_FALSE(welch(bad, 5.0).ok());
}
