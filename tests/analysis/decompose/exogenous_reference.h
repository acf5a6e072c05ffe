#pragma once
/// The peer of ExogenousCells (exogenous.h): estimateExogenousInputs as first written, one
/// window T0 and one offset t at a time, straight from eqs. 4.35-4.43. The fast estimate computes
/// every window at once and reuses what does not depend on M; tests require the same bits.

#include "analysis/decompose/exogenous.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace bunraku::test::reference {

using namespace bunraku::analysis;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// KM2O data of one cell from its diff series; a noise-free cell (all takes identical) gets
/// gamma = 0 and unit variance, i.e. its inputs are its mean.
inline Result<Km2oLangevinData> cellLangevin(const Eigen::MatrixXd& takes, const Eigen::VectorXd& mean, int m)
{
    const Eigen::MatrixXd diff = takes.colwise() - mean;
    auto r = biasedAutocovariance(diff, m);
    if (!r) return r.error();
    const double scale = std::max(1.0, mean.squaredNorm() / double(mean.size()));
    auto data = (*r)(0) > 1e-24 * scale ? km2oFromAutocovariance(*r, m) : Result<Km2oLangevinData>(Error{});
    if (!data) {
        Km2oLangevinData flat;
        flat.correlationLength = m;
        flat.gammaPlus = flat.gammaMinus = Eigen::MatrixXd::Zero(m + 1, m + 1);
        flat.varianceForward = flat.varianceBackward = Eigen::VectorXd::Ones(m + 1);
        flat.partialForward = Eigen::VectorXd::Zero(m + 1);
        return flat;
    }
    const double k = double(takes.cols());
    data->varianceForward *= k / (k - 1.0); // eq. 4.35: V_+ = K/(K-1) V_+(diff)
    data->varianceBackward *= k / (k - 1.0);
    return data;
}

/// For each absolute time, whether a window offset t >= first reaches it.
inline std::vector<char> reachedByLateOffsets(Eigen::Index frames, int m, Eigen::Index lastT0, int first)
{
    std::vector<char> reached(std::size_t(frames), 0);
    for (Eigen::Index t0 = 0; t0 <= lastT0; ++t0)
        for (int t = std::max(first, 0); t <= m; ++t) reached[std::size_t(t0 + t)] = 1;
    return reached;
}

/// sum / weight element by element; NaN where nothing was averaged (weight 0).
inline Eigen::MatrixXd weightedMeans(const Eigen::MatrixXd& sum, const Eigen::MatrixXd& weight)
{
    return (weight.array() > 0.0).select(sum.array() / weight.array(), kNaN).matrix();
}

inline Result<ExogenousEstimate> referenceExogenousEstimate(const std::vector<Eigen::MatrixXd>& cells, const ExogenousOptions& options)
{
    if (cells.empty()) return makeError(ErrorCode::InvalidArgument, "KM2O inputs: no cells");
    const Eigen::Index frames = cells[0].rows();
    const int cellCount = int(cells.size());
    for (std::size_t j = 0; j < cells.size(); ++j) {
        if (cells[j].rows() != frames)
            return makeError(ErrorCode::InvalidArgument, "KM2O inputs: cell " + std::to_string(j + 1) + " has " +
                                                             std::to_string(cells[j].rows()) + " frames, expected " +
                                                             std::to_string(frames) + " (pad or normalise first)");
        if (cells[j].cols() < 2)
            return makeError(ErrorCode::InvalidArgument, "KM2O inputs: cell " + std::to_string(j + 1) +
                                                             " needs at least 2 takes (K/(K-1), eq. 4.35)");
        if (!cells[j].allFinite())
            return makeError(ErrorCode::Numerical, "KM2O inputs: cell " + std::to_string(j + 1) + " has non-finite values");
    }
    const int m = options.correlationLength;
    const int maxM = maxCorrelationLength(frames);
    if (m < 0 || m > maxM)
        return makeError(ErrorCode::InvalidArgument,
                         "KM2O: correlation length M = " + std::to_string(m) + " outside 0..M_max = " + std::to_string(maxM) +
                             " (M_max = floor(3 sqrt(T+1)) - 1, T = " + std::to_string(frames - 1) + ", thesis eq. 4.30)");
    const Eigen::Index lastFrame = frames - 1;
    const Eigen::Index lastT0 = options.initialTimes == InitialTimeRange::Full ? lastFrame - m : lastFrame - m - 1;
    if (lastT0 < 0)
        return makeError(ErrorCode::InvalidArgument, "KM2O: M = " + std::to_string(m) + " leaves no initial time T0 for " +
                                                         std::to_string(frames) + " frames");

    ExogenousEstimate est;
    est.correlationLength = m;
    est.cellMeans.resize(frames, cellCount);
    for (int j = 0; j < cellCount; ++j) {
        est.cellMeans.col(j) = cells[std::size_t(j)].rowwise().mean();
        auto data = cellLangevin(cells[std::size_t(j)], est.cellMeans.col(j), m);
        if (!data) return data.error();
        est.langevin.push_back(std::move(*data));
    }

    // Markov estimate per window offset t: unknowns theta = (u, v^{i2}..v^{iJ}), observations
    // e^{ij} = u + v^{ij} + noise of variance V_+^{ij}(t)/K_j (eq. 4.36), so
    // theta = (A^T W A)^-1 A^T W e with A = [1 0; 1 I] and W = diag(K_j / V_+^{ij}(t)).
    Eigen::MatrixXd design = Eigen::MatrixXd::Zero(cellCount, cellCount);
    for (int j = 0; j < cellCount; ++j) {
        design(j, 0) = 1.0;
        if (j > 0) design(j, j) = 1.0;
    }
    std::vector<Eigen::MatrixXd> gain(std::size_t(m + 1));
    std::vector<Eigen::VectorXd> estimateVariance(std::size_t(m + 1));
    for (int t = 0; t <= m; ++t) {
        Eigen::VectorXd w(cellCount);
        for (int j = 0; j < cellCount; ++j)
            w(j) = double(cells[std::size_t(j)].cols()) / est.langevin[std::size_t(j)].varianceForward(t);
        const Eigen::MatrixXd normal = design.transpose() * w.asDiagonal() * design;
        const Eigen::MatrixXd covariance = normal.inverse();
        gain[std::size_t(t)] = covariance * design.transpose() * w.asDiagonal();
        estimateVariance[std::size_t(t)] = covariance.diagonal();
    }

    const auto reached = reachedByLateOffsets(frames, m, lastT0, options.firstWindowOffset);
    auto used = [&](Eigen::Index t0, int t) {
        return t >= options.firstWindowOffset || !reached[std::size_t(t0 + t)];
    };
    auto weightOf = [&](int t, int unknown) {
        return options.average == WindowAverage::Uniform ? 1.0 : 1.0 / estimateVariance[std::size_t(t)](unknown);
    };

    Eigen::MatrixXd inputSum = Eigen::MatrixXd::Zero(frames, cellCount); // col 0 u, col j v^{ij}
    Eigen::MatrixXd initialValues(lastT0 + 1, cellCount); // the t = 0 Markov estimate of each window (eq. 4.41)
    Eigen::MatrixXd inputWeight = Eigen::MatrixXd::Zero(frames, cellCount);
    est.estimateCount = Eigen::VectorXi::Zero(frames);
    Eigen::VectorXd e(cellCount);
    Eigen::VectorXd theta(cellCount);
    for (Eigen::Index t0 = 0; t0 <= lastT0; ++t0) {
        for (int t = 0; t <= m; ++t) {
            if (t > 0 && !used(t0, t)) continue;
            for (int j = 0; j < cellCount; ++j) {
                const auto& g = est.langevin[std::size_t(j)].gammaPlus;
                double value = est.cellMeans(t0 + t, j);
                for (int s = 0; s < t; ++s) value += g(t, s) * est.cellMeans(t0 + s, j);
                e(j) = value; // left side of eq. 4.36
            }
            theta.noalias() = gain[std::size_t(t)] * e;
            if (t == 0) initialValues.row(t0) = theta.transpose();
            if (!used(t0, t)) continue;
            for (int j = 0; j < cellCount; ++j) {
                const double wt = weightOf(t, j);
                inputSum(t0 + t, j) += wt * theta(j);
                inputWeight(t0 + t, j) += wt;
            }
            ++est.estimateCount(t0 + t);
        }
    }
    const Eigen::MatrixXd inputs = weightedMeans(inputSum, inputWeight);
    est.functionInput = inputs.col(0);
    est.emotionInputs = inputs;
    est.emotionInputs.col(0).setZero();

    // Components (eqs. 4.41-4.43): per window, the recursion with gamma of the neutral cell for
    // y, of cell j for z, from the window's own t = 0 estimate; averaged per absolute time like
    // the inputs.
    Eigen::MatrixXd componentSum = Eigen::MatrixXd::Zero(frames, cellCount);
    Eigen::MatrixXd componentWeight = Eigen::MatrixXd::Zero(frames, cellCount);
    Eigen::VectorXd window(m + 1);
    for (int j = 0; j < cellCount; ++j) {
        const auto& g = est.langevin[std::size_t(j)].gammaPlus;
        for (Eigen::Index t0 = 0; t0 <= lastT0; ++t0) {
            for (int t = 0; t <= m; ++t) {
                // eq. 4.41: the window starts from its own t = 0 Markov estimate (variance V_+(0));
                // later offsets use the inputs averaged per absolute time (eqs. 4.42/4.43).
                double value = t == 0 ? initialValues(t0, j) : inputs(t0 + t, j);
                for (int s = 0; s < t; ++s) value -= g(t, s) * window(s);
                window(t) = value;
                if (!used(t0, t)) continue;
                const double wt = weightOf(t, j);
                componentSum(t0 + t, j) += wt * value;
                componentWeight(t0 + t, j) += wt;
            }
        }
    }
    const Eigen::MatrixXd components = weightedMeans(componentSum, componentWeight);
    est.functionComponent = components.col(0);
    est.emotionComponents = components;
    est.emotionComponents.col(0).setZero();
    return est;
}

} // namespace bunraku::test::reference
