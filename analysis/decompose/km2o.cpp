#include "analysis/decompose/km2o.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace bunraku::analysis {

int maxCorrelationLength(Eigen::Index frameCount)
{
    if (frameCount <= 0) return -1;
    // T + 1 = frameCount; floor(3 sqrt(T+1)) - 1
    return int(std::floor(3.0 * std::sqrt(double(frameCount)))) - 1;
}

Result<Eigen::VectorXd> biasedAutocovariance(const Eigen::MatrixXd& series, int maxLag)
{
    const Eigen::Index frames = series.rows();
    if (series.cols() == 0 || frames == 0)
        return makeError(ErrorCode::InvalidArgument, "autocovariance: the series is empty");
    if (maxLag < 0 || maxLag >= frames)
        return makeError(ErrorCode::InvalidArgument,
                         "autocovariance: lag " + std::to_string(maxLag) + " outside 0.." +
                             std::to_string(frames - 1));
    if (!series.allFinite())
        return makeError(ErrorCode::Numerical, "autocovariance: the series has non-finite values");
    Eigen::VectorXd r = Eigen::VectorXd::Zero(maxLag + 1);
    for (Eigen::Index c = 0; c < series.cols(); ++c) {
        const auto x = series.col(c);
        for (int tau = 0; tau <= maxLag; ++tau)
            r(tau) += x.tail(frames - tau).dot(x.head(frames - tau));
    }
    r /= double(frames) * double(series.cols());
    return r;
}

Result<Km2oLangevinData> km2oFromAutocovariance(const Eigen::VectorXd& autocovariance, int correlationLength)
{
    const int m = correlationLength;
    if (m < 0)
        return makeError(ErrorCode::InvalidArgument, "KM2O: correlation length M must be >= 0");
    if (autocovariance.size() < m + 1)
        return makeError(ErrorCode::InvalidArgument, "KM2O: need R(0.." + std::to_string(m) + ")");
    const auto& r = autocovariance;
    if (!(r(0) > 0.0) || !r.head(m + 1).allFinite())
        return makeError(ErrorCode::Numerical, "KM2O: R(0) must be positive and finite (constant data?)");

    Km2oLangevinData d;
    d.correlationLength = m;
    d.gammaPlus = Eigen::MatrixXd::Zero(m + 1, m + 1);
    d.gammaMinus = Eigen::MatrixXd::Zero(m + 1, m + 1);
    d.varianceForward = Eigen::VectorXd::Zero(m + 1);
    d.varianceBackward = Eigen::VectorXd::Zero(m + 1);
    d.partialForward = Eigen::VectorXd::Zero(m + 1);
    d.varianceForward(0) = r(0);
    d.varianceBackward(0) = r(0);
    for (int n = 1; n <= m; ++n) {
        double delta = r(n);
        for (int k = 0; k <= n - 2; ++k) delta += d.gammaPlus(n - 1, k) * r(k + 1);
        const double deltaPlus = -delta / d.varianceBackward(n - 1);
        const double deltaMinus = -delta / d.varianceForward(n - 1);
        d.gammaPlus(n, 0) = deltaPlus;
        d.gammaMinus(n, 0) = deltaMinus;
        for (int k = 1; k <= n - 1; ++k) {
            d.gammaPlus(n, k) = d.gammaPlus(n - 1, k - 1) + deltaPlus * d.gammaMinus(n - 1, n - 1 - k);
            d.gammaMinus(n, k) = d.gammaMinus(n - 1, k - 1) + deltaMinus * d.gammaPlus(n - 1, n - 1 - k);
        }
        const double shrink = 1.0 - deltaPlus * deltaMinus;
        d.varianceForward(n) = shrink * d.varianceForward(n - 1);
        d.varianceBackward(n) = shrink * d.varianceBackward(n - 1);
        d.partialForward(n) = deltaPlus;
        if (!(d.varianceForward(n) > 0.0))
            return makeError(ErrorCode::Numerical,
                             "KM2O: fluctuation variance V+(" + std::to_string(n) +
                                 ") is not positive (perfectly predictable or degenerate data)");
    }
    return d;
}

Result<Km2oLangevinData> km2oLangevinData(const Eigen::MatrixXd& series, int correlationLength)
{
    const int maxM = maxCorrelationLength(series.rows());
    if (correlationLength > maxM)
        return makeError(ErrorCode::InvalidArgument,
                         "KM2O: correlation length M = " + std::to_string(correlationLength) +
                             " exceeds M_max = floor(3 sqrt(T+1)) - 1 = " + std::to_string(maxM) +
                             " for T = " + std::to_string(series.rows() - 1) + " (thesis eq. 4.30)");
    auto r = biasedAutocovariance(series, correlationLength);
    if (!r) return r.error();
    return km2oFromAutocovariance(*r, correlationLength);
}

Result<YuleWalkerPredictor> yuleWalkerPredictor(const Eigen::VectorXd& autocovariance, int order)
{
    if (order < 0 || autocovariance.size() < order + 1)
        return makeError(ErrorCode::InvalidArgument, "Yule-Walker: need R(0.." + std::to_string(order) + ")");
    YuleWalkerPredictor p;
    p.coefficients = Eigen::VectorXd::Zero(order);
    if (order > 0) {
        Eigen::MatrixXd toeplitz(order, order);
        for (int i = 0; i < order; ++i)
            for (int j = 0; j < order; ++j) toeplitz(i, j) = autocovariance(std::abs(i - j));
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(toeplitz);
        if (ldlt.info() != Eigen::Success || !ldlt.isPositive())
            return makeError(ErrorCode::Numerical, "Yule-Walker: the autocovariance matrix is not positive definite");
        p.coefficients = ldlt.solve(autocovariance.segment(1, order));
    }
    p.innovationVariance = autocovariance(0) - (order > 0 ? p.coefficients.dot(autocovariance.segment(1, order)) : 0.0);
    return p;
}

} // namespace bunraku::analysis
