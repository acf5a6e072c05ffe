#include "analysis/decompose/arma.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>

namespace bunraku::analysis {
namespace {

/// Conditional residuals e(t), t = p..N-1 (stored at t; zero before p), and optionally their
/// derivatives with respect to (a_1..a_p, c_1..c_q).
double residuals(const Eigen::VectorXd& x, int p, int q, const Eigen::VectorXd& theta, Eigen::VectorXd& e,
                 Eigen::MatrixXd* jacobian)
{
    const Eigen::Index n = x.size();
    e = Eigen::VectorXd::Zero(n);
    if (jacobian) *jacobian = Eigen::MatrixXd::Zero(n, p + q);
    double sum = 0.0;
    for (Eigen::Index t = p; t < n; ++t) {
        double value = x(t);
        for (int m = 1; m <= p; ++m) value += theta(m - 1) * x(t - m);
        for (int l = 1; l <= q; ++l)
            if (t - l >= p) value -= theta(p + l - 1) * e(t - l);
        e(t) = value;
        sum += value * value;
        if (jacobian) {
            auto& jac = *jacobian;
            for (int m = 1; m <= p; ++m) jac(t, m - 1) = x(t - m);
            for (int l = 1; l <= q; ++l) jac(t, p + l - 1) = t - l >= p ? -e(t - l) : 0.0;
            for (int l = 1; l <= q; ++l)
                if (t - l >= p) jac.row(t) -= theta(p + l - 1) * jac.row(t - l);
        }
    }
    return sum;
}

/// Hannan-Rissanen start: a long autoregression for the innovations, then one regression.
Eigen::VectorXd hannanRissanen(const Eigen::VectorXd& x, int p, int q)
{
    const Eigen::Index n = x.size();
    Eigen::VectorXd theta = Eigen::VectorXd::Zero(p + q);
    Eigen::VectorXd innovations = Eigen::VectorXd::Zero(n);
    int h = 0;
    if (q > 0) {
        h = int(std::min<Eigen::Index>(std::max(10, 2 * (p + q)), (n - 1) / 3));
        Eigen::MatrixXd lags(n - h, h);
        for (Eigen::Index t = h; t < n; ++t)
            for (int j = 1; j <= h; ++j) lags(t - h, j - 1) = x(t - j);
        const Eigen::VectorXd phi = lags.colPivHouseholderQr().solve(x.tail(n - h));
        innovations.tail(n - h) = x.tail(n - h) - lags * phi;
    }
    const Eigen::Index start = std::max<Eigen::Index>(p, h + q);
    if (p + q == 0 || start >= n - (p + q)) return theta;
    Eigen::MatrixXd design(n - start, p + q);
    for (Eigen::Index t = start; t < n; ++t) {
        for (int m = 1; m <= p; ++m) design(t - start, m - 1) = -x(t - m);
        for (int l = 1; l <= q; ++l) design(t - start, p + l - 1) = innovations(t - l);
    }
    theta = design.colPivHouseholderQr().solve(x.tail(n - start));
    if (!theta.allFinite()) theta.setZero();
    return theta;
}

/// Roots of b_0 z^q + b_1 z^(q-1) + ... + b_q (b_0 != 0) as the companion matrix's eigenvalues.
Eigen::VectorXcd polynomialRoots(const Eigen::VectorXd& b)
{
    const Eigen::Index q = b.size() - 1;
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(q, q);
    for (Eigen::Index k = 0; k < q; ++k) companion(0, k) = -b(k + 1) / b(0);
    for (Eigen::Index k = 1; k < q; ++k) companion(k, k - 1) = 1.0;
    return Eigen::EigenSolver<Eigen::MatrixXd>(companion, false).eigenvalues();
}

/// gain * prod (z - r): coefficients b_0..b_q (real parts; the roots come in conjugate pairs).
Eigen::VectorXd fromRoots(double gain, const Eigen::VectorXcd& roots)
{
    Eigen::VectorXcd coefficients = Eigen::VectorXcd::Zero(roots.size() + 1);
    coefficients(0) = 1.0;
    for (Eigen::Index k = 0; k < roots.size(); ++k)
        for (Eigen::Index n = k + 1; n >= 1; --n) coefficients(n) -= roots(k) * coefficients(n - 1);
    Eigen::VectorXd b = gain * coefficients.real();
    if (b(0) < 0.0) b = -b; // w -> -w
    return b;
}

/// Reflects into (inside = true) or out of the unit circle the roots `select` picks.
template <typename Select>
Eigen::VectorXd reflectRoots(const Eigen::VectorXd& b, Select select)
{
    if (b.size() < 2 || b(0) == 0.0 || !b.allFinite()) return b;
    Eigen::VectorXcd roots = polynomialRoots(b);
    double gain = b(0);
    for (Eigen::Index k = 0; k < roots.size(); ++k) {
        const double modulus = std::abs(roots(k));
        if (modulus == 0.0 || !select(roots(k))) continue;
        roots(k) = 1.0 / std::conj(roots(k));
        gain *= modulus; // |e^{iw} - r| = |r| |e^{iw} - 1 / conj(r)|
    }
    return fromRoots(gain, roots);
}

} // namespace

Eigen::VectorXd thesisMaConvention(const Eigen::VectorXd& b)
{
    if (b.size() < 2 || b(0) == 0.0 || !b.allFinite()) return b;
    const Eigen::VectorXcd roots = polynomialRoots(b);
    const double largest = roots.cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) return b;
    return reflectRoots(b, [largest](std::complex<double> r) {
        const double modulus = std::abs(r);
        return modulus >= largest * (1.0 - 1e-9) && modulus < 1.0;
    });
}

Eigen::VectorXd invertibleMa(const Eigen::VectorXd& b)
{
    return reflectRoots(b, [](std::complex<double> r) { return std::abs(r) > 1.0; });
}

Eigen::VectorXd maAutocovariance(const Eigen::VectorXd& b)
{
    Eigen::VectorXd gamma = Eigen::VectorXd::Zero(b.size());
    for (Eigen::Index k = 0; k < b.size(); ++k)
        for (Eigen::Index n = 0; n + k < b.size(); ++n) gamma(k) += b(n) * b(n + k);
    return gamma;
}

Result<ArmaModel> fitArma(const Eigen::VectorXd& series, int p, int q, const ArmaOptions& options)
{
    if (p < 0 || q < 0) return makeError(ErrorCode::InvalidArgument, "ARMA: orders p, q must be >= 0");
    const Eigen::Index n = series.size();
    if (n < 3 * (p + q + 1) + 10)
        return makeError(ErrorCode::InvalidArgument, "ARMA(" + std::to_string(p) + "," + std::to_string(q) + "): " +
                                                         std::to_string(n) + " samples are too few (need " +
                                                         std::to_string(3 * (p + q + 1) + 10) + ")");
    if (!series.allFinite()) return makeError(ErrorCode::Numerical, "ARMA: the series has non-finite values");
    if (!(series.squaredNorm() > 0.0)) return makeError(ErrorCode::Numerical, "ARMA: the series is identically zero");

    Eigen::VectorXd theta = hannanRissanen(series, p, q);
    Eigen::VectorXd e;
    Eigen::MatrixXd jac;
    double cost = residuals(series, p, q, theta, e, &jac);
    if (!std::isfinite(cost)) {
        theta.setZero();
        cost = residuals(series, p, q, theta, e, &jac);
    }
    ArmaModel model;
    model.p = p;
    model.q = q;
    double lambda = 1e-3;
    for (int iteration = 0; iteration < options.maxIterations && p + q > 0; ++iteration) {
        model.iterations = iteration + 1;
        const Eigen::MatrixXd normal = jac.transpose() * jac;
        const Eigen::VectorXd gradient = jac.transpose() * e;
        bool accepted = false;
        double decrease = 0.0;
        while (lambda < 1e12) {
            Eigen::MatrixXd damped = normal;
            damped.diagonal() += lambda * normal.diagonal().cwiseMax(1e-12);
            const Eigen::VectorXd step = damped.ldlt().solve(-gradient);
            const Eigen::VectorXd candidate = theta + step;
            Eigen::VectorXd candidateE;
            const double candidateCost = residuals(series, p, q, candidate, candidateE, nullptr);
            if (std::isfinite(candidateCost) && candidateCost < cost) {
                decrease = (cost - candidateCost) / cost;
                theta = candidate;
                cost = residuals(series, p, q, theta, e, &jac);
                lambda = std::max(lambda / 10.0, 1e-12);
                accepted = true;
                break;
            }
            lambda *= 10.0;
        }
        if (!accepted || decrease < options.tolerance) break;
    }
    model.a = theta.head(p);
    model.c = theta.tail(q);
    model.innovationVariance = cost / double(n - p);
    const double sigma = std::sqrt(model.innovationVariance);
    model.b.resize(q + 1);
    model.b(0) = sigma;
    for (int l = 1; l <= q; ++l) model.b(l) = model.c(l - 1) * sigma;
    model.bThesis = thesisMaConvention(model.b);
    const double ratio = double(p + q + 1) / double(n); // eq. 4.10
    model.fpe = (1.0 + ratio) / (1.0 - ratio) * model.innovationVariance;
    return model;
}

Result<ArmaOrderSelection> selectArmaOrder(const Eigen::VectorXd& series, const ArmaOrderOptions& options)
{
    if (options.maxOrder < 0) return makeError(ErrorCode::InvalidArgument, "ARMA: maxOrder must be >= 0");
    ArmaOrderSelection selection;
    const int size = options.maxOrder + 1;
    selection.fpe = Eigen::MatrixXd::Constant(size, size, std::numeric_limits<double>::quiet_NaN());
    bool found = false;
    for (int p = 0; p <= options.maxOrder; ++p) {
        for (int q = 0; q <= options.maxOrder; ++q) {
            if (options.search == ArmaOrderSearch::EqualOrders && (p != q || p == 0)) continue;
            auto model = fitArma(series, p, q, options.fit);
            if (!model) {
                if (model.error().code == ErrorCode::InvalidArgument) continue; // too short for this order
                return model.error();
            }
            selection.fpe(p, q) = model->fpe;
            if (!found || model->fpe < selection.best.fpe) {
                selection.best = *model;
                found = true;
            }
        }
    }
    if (!found) return makeError(ErrorCode::InvalidArgument, "ARMA: the series is too short for any candidate order");
    return selection;
}

Result<std::vector<ArmaCellRow>> armaCellTable(const Decomposition& decomposition, Eigen::Index channel, int p, int q,
                                               const ArmaOptions& options)
{
    if (channel < 0 || channel >= Eigen::Index(decomposition.channels.size()))
        return makeError(ErrorCode::NotFound, "ARMA table: channel index " + std::to_string(channel) + " out of range");
    std::vector<ArmaCellRow> rows;
    for (const auto& cell : decomposition.emotions) {
        ArmaCellRow row;
        row.function = cell.function;
        row.emotion = cell.emotion;
        row.mean.p = p;
        row.mean.q = q;
        row.mean.a = Eigen::VectorXd::Zero(p);
        row.mean.c = Eigen::VectorXd::Zero(q);
        row.mean.b = Eigen::VectorXd::Zero(q + 1);
        row.mean.bThesis = Eigen::VectorXd::Zero(q + 1);
        if (cellTakeCount(decomposition, cell.function, cell.emotion) < 2) { // one take: no fluctuation (eq. 4.24)
            rows.push_back(std::move(row));
            continue;
        }
        for (const auto& eta : decomposition.fluctuations) {
            if (eta.labels.function != cell.function || eta.labels.emotion != cell.emotion) continue;
            if (!(eta.values.col(channel).squaredNorm() > 0.0)) continue; // a single take or a constant channel
            auto model = fitArma(eta.values.col(channel), p, q, options);
            if (!model)
                return makeError(model.error().code, "ARMA table: take " + eta.labels.function + "/" + eta.labels.emotion + "/" +
                                                         std::to_string(eta.labels.takeIndex) + ": " + model.error().message);
            row.mean.a += model->a;
            row.mean.c += model->c;
            row.mean.b += model->b;
            row.mean.bThesis += model->bThesis;
            row.mean.innovationVariance += model->innovationVariance;
            row.mean.fpe += model->fpe;
            ++row.takes;
        }
        if (row.takes > 0) {
            const double k = double(row.takes);
            row.mean.a /= k;
            row.mean.c /= k;
            row.mean.b /= k;
            row.mean.bThesis /= k;
            row.mean.innovationVariance /= k;
            row.mean.fpe /= k;
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace bunraku::analysis
