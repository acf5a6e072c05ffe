#include "tests/support/peer.h"
#include "analysis/decompose/arma.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

using namespace bunraku::analysis;

namespace {

/// eta(t) + a1 eta(t-1) + a2 eta(t-2) = e(t) + c1 e(t-1) + c2 e(t-2), var e = sigma^2.
Eigen::VectorXd armaSeries(int n, double a1, double a2, double c1, double c2, double sigma, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, sigma);
    const int burn = 200;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n + burn);
    Eigen::VectorXd e(n + burn);
    for (int t = 0; t < n + burn; ++t) e(t) = normal(rng);
    for (int t = 2; t < n + burn; ++t) x(t) = -a1 * x(t - 1) - a2 * x(t - 2) + e(t) + c1 * e(t - 1) + c2 * e(t - 2);
    return x.tail(n);
}

/// statsmodels' exact-likelihood ARIMA(p,0,q) parameters (ar.L*, ma.L*, sigma2), empty when
/// Debian's python3-statsmodels is not available.
std::vector<double> statsmodelsArma(const Eigen::VectorXd& series, int p, int q)
{
    const auto dir = bunraku::test::scratchDir("arma_statsmodels");
    const auto file = dir / "series.txt";
    {
        std::ofstream out(file);
        out.precision(17);
        for (Eigen::Index t = 0; t < series.size(); ++t) out << series(t) << "\n";
    }
    std::ostringstream command;
    command << "/usr/bin/python3 -c \"import warnings; warnings.simplefilter('ignore'); import numpy as np; "
            << "from statsmodels.tsa.arima.model import ARIMA; x = np.loadtxt('" << file.string() << "'); "
            << "r = ARIMA(x, order=(" << p << ",0," << q << "), trend='n').fit(); "
            << "print(' '.join(repr(float(v)) for v in r.params))\" 2>/dev/null";
    std::vector<double> values;
    FILE* pipe = popen(command.str().c_str(), "r");
    if (!pipe) return values;
    char buffer[4096];
    std::string text;
    while (fgets(buffer, sizeof buffer, pipe)) text += buffer;
    if (pclose(pipe) != 0) return {};
    std::istringstream in(text);
    double v = 0.0;
    while (in >> v) values.push_back(v);
    return values;
}

} // namespace

TEST_CASE("ARMA(2,2) recovers the parameters of a simulated series")
{
    const Eigen::VectorXd x = armaSeries(3000, -0.75, 0.5, 0.4, 0.2, 0.5, 5);
    auto model = fitArma(x, 2, 2);
    REQUIRE(model.ok());
    CHECK(model->a(0) == Approx(-0.75).margin(0.08));
    CHECK(model->a(1) == Approx(0.5).margin(0.08));
    CHECK(model->c(0) == Approx(0.4).margin(0.08));
    CHECK(model->c(1) == Approx(0.2).margin(0.08));
    CHECK(model->b(0) == Approx(0.5).epsilon(0.05)); // b_0 = sigma
    CHECK(model->b(1) == Approx(model->c(0) * model->b(0)));
    const double ratio = 5.0 / 3000.0;
    CHECK(model->fpe == Approx((1 + ratio) / (1 - ratio) * model->innovationVariance));
}

TEST_CASE("ARMA estimates agree with statsmodels on the same series")
{
    struct Case {
        int p, q;
        double a1, a2, c1, c2;
    };
    const std::vector<Case> cases{{2, 2, -0.75, 0.5, 0.4, 0.2}, {1, 1, -0.6, 0.0, 0.3, 0.0}, {2, 0, -1.2, 0.5, 0.0, 0.0}};
    for (const auto& c : cases) {
        const Eigen::VectorXd x = armaSeries(2000, c.a1, c.a2, c.c1, c.c2, 1.3, 17);
        const auto reference = statsmodelsArma(x, c.p, c.q);
        if (!bunraku::test::requirePeer(!reference.empty(), "python3-statsmodels (/usr/bin/python3 with statsmodels) for the peer comparison",
                                        "apt-get install python3-statsmodels"))
            return;
        REQUIRE(reference.size() == std::size_t(c.p + c.q + 1));
        auto model = fitArma(x, c.p, c.q);
        REQUIRE(model.ok());
        INFO("ARMA(" << c.p << "," << c.q << ")");
        // conditional (ours) vs exact (statsmodels) likelihood: equal up to O(1/T) differences
        for (int m = 0; m < c.p; ++m) CHECK(model->a(m) == Approx(-reference[std::size_t(m)]).margin(0.02));
        for (int l = 0; l < c.q; ++l) CHECK(model->c(l) == Approx(reference[std::size_t(c.p + l)]).margin(0.02));
        CHECK(model->innovationVariance == Approx(reference.back()).epsilon(0.02));
    }
}

TEST_CASE("FPE order selection keeps the smallest FPE and needs at least the AR order of an AR(2) series")
{
    const Eigen::VectorXd x = armaSeries(800, -1.2, 0.6, 0.0, 0.0, 1.0, 9);
    auto selection = selectArmaOrder(x);
    REQUIRE(selection.ok());
    CHECK(selection->best.p >= 2);
    CHECK(selection->best.fpe == Approx(selection->fpe.array().isNaN().select(1e300, selection->fpe.array()).minCoeff()));
    CHECK(selection->best.fpe < selection->fpe(1, 0));
    ArmaOrderOptions equal;
    equal.search = ArmaOrderSearch::EqualOrders;
    auto same = selectArmaOrder(x, equal);
    REQUIRE(same.ok());
    CHECK(same->best.p == same->best.q);
    CHECK(std::isnan(same->fpe(1, 0)));
}

TEST_CASE("ARMA rejects series too short for the order")
{
    auto model = fitArma(Eigen::VectorXd::Random(20), 4, 4);
    REQUIRE_FALSE(model.ok());
    CHECK(model.error().message.find("too few") != std::string::npos);
}
