#include "analysis/wavelet/cwt_reconstruction.h"

#include <Eigen/QR>
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace bunraku::analysis;

namespace {

constexpr double kFrequencyA = 0.110; // cycles per sample, about scale 8 for sym3
constexpr double kFrequencyB = 0.027; // about scale 32
constexpr Eigen::Index kSamples = 1024;
constexpr Eigen::Index kFirst = 260; // interior: beyond the edge effect of scale 32
constexpr Eigen::Index kLast = 764;

Eigen::VectorXd twoSines()
{
    Eigen::VectorXd x(kSamples);
    for (Eigen::Index t = 0; t < kSamples; ++t)
        x[t] = std::sin(2 * std::numbers::pi * kFrequencyA * double(t)) + std::sin(2 * std::numbers::pi * kFrequencyB * double(t) + 0.4);
    return x;
}

// Amplitude of the components of y at frequencies A and B over the interior (least squares on
// sin/cos of both).
std::pair<double, double> amplitudes(const Eigen::VectorXd& y)
{
    const Eigen::Index n = kLast - kFirst;
    Eigen::MatrixXd basis(n, 5);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double t = double(kFirst + i);
        basis(i, 0) = std::sin(2 * std::numbers::pi * kFrequencyA * t);
        basis(i, 1) = std::cos(2 * std::numbers::pi * kFrequencyA * t);
        basis(i, 2) = std::sin(2 * std::numbers::pi * kFrequencyB * t);
        basis(i, 3) = std::cos(2 * std::numbers::pi * kFrequencyB * t);
        basis(i, 4) = 1.0;
    }
    const Eigen::VectorXd c = basis.colPivHouseholderQr().solve(y.segment(kFirst, n));
    return {std::hypot(c[0], c[1]), std::hypot(c[2], c[3])};
}

} // namespace

TEST_CASE("the approximation keeps what the scales do not reach (thesis two-sine test)", "[cwt][approximation]")
{
    const Eigen::VectorXd x = twoSines();
    auto residual = [&](int maxScale) {
        auto approximation = cwtApproximation(x, integerScales(maxScale));
        REQUIRE(approximation.ok());
        return amplitudes(*approximation);
    };
    // Scales 1..4: both sines stay in A.
    const auto [a4, b4] = residual(4);
    CHECK(a4 > 0.7);
    CHECK(b4 > 0.95);
    // 1..8: part of the first sine stays in A.
    const auto [a8, b8] = residual(8);
    CHECK(a8 > 0.1);
    CHECK(a8 < 0.5);
    CHECK(b8 > 0.9);
    // 1..12: the first sine is captured fully, the second is still in A.
    const auto [a12, b12] = residual(12);
    CHECK(a12 < 0.08);
    CHECK(b12 > 0.8);
    // 1..32: both are (almost) captured.
    const auto [a32, b32] = residual(32);
    CHECK(a32 < 0.08);
    CHECK(b32 < 0.3);
}

TEST_CASE("the reconstruction of a mid-band sine is close to the sine itself", "[cwt][approximation]")
{
    Eigen::VectorXd x(512);
    for (Eigen::Index t = 0; t < x.size(); ++t) x[t] = 3.0 * std::cos(2 * std::numbers::pi * 0.09 * double(t));
    auto reconstruction = cwtReconstruction(x, integerScales(40));
    REQUIRE(reconstruction.ok());
    const double error = (reconstruction->segment(150, 200) - x.segment(150, 200)).cwiseAbs().maxCoeff();
    CHECK(error < 0.15 * 3.0);
}

TEST_CASE("reconstruction rejects unsorted scales", "[cwt][approximation]")
{
    auto result = cwtReconstruction(Eigen::VectorXd::Ones(100), {2.0, 1.0});
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().message.find("increasing") != std::string::npos);
}

TEST_CASE("the scales' separate terms sum to the reconstruction, nested integer scales share them")
{
    Eigen::VectorXd x(106);
    for (Eigen::Index t = 0; t < x.size(); ++t) x[t] = std::sin(0.69 * double(t)) + 0.5 * std::cos(0.17 * double(t)) + 3.0;
    std::vector<double> scales;
    for (int c = 1; c <= 16; ++c) scales.push_back(c);
    auto parts = cwtScaleContributions(x, scales);
    REQUIRE(parts.ok());
    REQUIRE(parts->rows() == 106);
    REQUIRE(parts->cols() == 16);
    auto whole = cwtReconstruction(x, scales);
    REQUIRE(whole.ok());
    CHECK((parts->rowwise().sum() - *whole).cwiseAbs().maxCoeff() < 1e-12);
    // scales 1..5: every share is 1, so the approximation is x minus the first 5 terms
    auto approximation = cwtApproximation(x, {1, 2, 3, 4, 5});
    REQUIRE(approximation.ok());
    CHECK((x - parts->leftCols(5).rowwise().sum() - *approximation).cwiseAbs().maxCoeff() < 1e-12);
    CHECK(cwtScaleContributions(x, {2, 1}).error().code == ErrorCode::InvalidArgument);
}
