#include "analysis/decompose/arma.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <random>

using namespace bunraku::analysis;

namespace {

/// Table 4.1 (head-x): b0 b1 b2 of the six cells, as printed.
const std::array<std::array<double, 3>, 6> kTable41b{{{0.2125, 0.5891, 0.0035},
                                                       {0.2414, 0.6818, 0.0486},
                                                       {0.2164, 0.6834, 0.0309},
                                                       {0.3267, 0.6809, -0.0197},
                                                       {0.1484, 0.6383, 0.0056},
                                                       {0.1371, 0.6121, -0.0085}}};

Eigen::VectorXd vector3(const std::array<double, 3>& b) { return Eigen::Vector3d(b[0], b[1], b[2]); }

/// |B(e^{iw})|^2 at w.
double power(const Eigen::VectorXd& b, double w)
{
    std::complex<double> sum = 0.0;
    for (Eigen::Index n = 0; n < b.size(); ++n) sum += b(n) * std::exp(std::complex<double>(0.0, -w * double(n)));
    return std::norm(sum);
}

/// The moduli of the roots of b0 z^2 + b1 z + b2.
std::array<double, 2> rootModuli(const Eigen::VectorXd& b)
{
    const std::complex<double> d = std::sqrt(std::complex<double>(b(1) * b(1) - 4.0 * b(0) * b(2)));
    return {std::abs((-b(1) + d) / (2.0 * b(0))), std::abs((-b(1) - d) / (2.0 * b(0)))};
}

} // namespace

TEST_CASE("Table 4.1's b columns are one spectral factor of an invertible MA: the largest root outside")
{
    for (const auto& row : kTable41b) {
        const Eigen::VectorXd thesis = vector3(row);
        const auto moduli = rootModuli(thesis);
        // every printed row: one root at 2.1-4.5, the other below 0.08
        CHECK(std::max(moduli[0], moduli[1]) > 2.0);
        CHECK(std::min(moduli[0], moduli[1]) < 0.08);
        const Eigen::VectorXd invertible = invertibleMa(thesis);
        const auto inside = rootModuli(invertible);
        CHECK(std::max(inside[0], inside[1]) < 1.0);
        // c1 = b1/b0 of the invertible factor: 0.21..0.45 where the thesis prints b1/b0 = 2.1..4.5
        CHECK(invertible(1) / invertible(0) > 0.2);
        CHECK(invertible(1) / invertible(0) < 0.46);
        // the same spectrum and MA autocovariances
        CHECK((maAutocovariance(invertible) - maAutocovariance(thesis)).norm() < 1e-12);
        for (double w : {0.0, 0.7, 1.9, 3.1}) CHECK(power(invertible, w) == Approx(power(thesis, w)).epsilon(1e-12));
        // and back: the thesis's convention of the invertible factor is the printed row
        CHECK((thesisMaConvention(invertible) - thesis).norm() < 1e-12);
    }
    // the first row worked through (docs/ARMA.md): b = (0.5878, 0.2160, 0.0013) invertible
    const Eigen::VectorXd first = invertibleMa(vector3(kTable41b[0]));
    CHECK(first(0) == Approx(0.5878).margin(5e-5));
    CHECK(first(1) == Approx(0.2160).margin(5e-5));
    CHECK(first(2) == Approx(0.0013).margin(5e-5));
}

TEST_CASE("a complex pair of MA roots is reflected together and trivial MA parts are kept")
{
    const Eigen::VectorXd b = Eigen::Vector3d(0.2, -0.08, 0.12); // roots |r|^2 = 0.6: a pair inside
    const Eigen::VectorXd thesis = thesisMaConvention(b);
    CHECK((thesis - Eigen::Vector3d(0.12, -0.08, 0.2)).norm() < 1e-12); // both reflected: b reversed
    CHECK((invertibleMa(thesis) - b).norm() < 1e-12);
    CHECK(thesisMaConvention(Eigen::VectorXd::Constant(1, 0.3)) == Eigen::VectorXd::Constant(1, 0.3));
    CHECK(thesisMaConvention(Eigen::Vector3d(0.3, 0.0, 0.0)) == Eigen::Vector3d(0.3, 0.0, 0.0));
    CHECK(thesisMaConvention(Eigen::Vector2d(0.0, 1.0)) == Eigen::Vector2d(0.0, 1.0));
    // an MA(1) is simply reversed: (sigma, c sigma) -> (c sigma, sigma)
    CHECK((thesisMaConvention(Eigen::Vector2d(0.6, 0.24)) - Eigen::Vector2d(0.24, 0.6)).norm() < 1e-12);
}

TEST_CASE("fitArma reports the invertible b and Table 4.1's convention of the same spectrum")
{
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, 0.6);
    const int n = 4000, burn = 200;
    // the invertible form of Table 4.1's first row: a = (-1.829, 0.8586), c = (0.3675, 0.0022), sigma 0.5878
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n + burn), e(n + burn);
    for (auto& value : e) value = normal(rng) / 0.6 * 0.5878;
    for (int t = 2; t < n + burn; ++t)
        x(t) = 1.829 * x(t - 1) - 0.8586 * x(t - 2) + e(t) + 0.3675 * e(t - 1) + 0.0022 * e(t - 2);
    auto model = fitArma(x.tail(n), 2, 2);
    REQUIRE(model.ok());
    REQUIRE(model->bThesis.size() == 3);
    CHECK(std::max(rootModuli(model->b)[0], rootModuli(model->b)[1]) < 1.0);
    CHECK((maAutocovariance(model->bThesis) - maAutocovariance(model->b)).norm() < 1e-10);
    // in the thesis's convention the fit reads like its Table 4.1 row: b1/b0 near 1/0.3675 = 2.7
    CHECK(model->bThesis(1) / model->bThesis(0) == Approx(1.0 / 0.3675).epsilon(0.25));
    CHECK(model->bThesis(1) == Approx(0.5891).epsilon(0.1));
    CHECK(std::fabs(model->bThesis(2)) < 0.05);
}
