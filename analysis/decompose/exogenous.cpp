#include "analysis/decompose/exogenous.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace bunraku::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// KM2O data of one cell from the autocovariance of its diff series (R(0..M) at least), the
/// variances multiplied by `varianceScale` (K/(K-1), eq. 4.35, for a cell's own diff series; 1
/// for the pooled autocovariance of a one-take cell, already unbiased); a noise-free cell (all
/// takes identical) gets gamma = 0 and unit variance, i.e. its inputs are its mean.
Km2oLangevinData cellLangevin(const Eigen::VectorXd& r, const Eigen::VectorXd& mean, double varianceScale, int m)
{
    const double scale = std::max(1.0, mean.squaredNorm() / double(mean.size()));
    auto data = r(0) > 1e-24 * scale ? km2oFromAutocovariance(r, m) : Result<Km2oLangevinData>(Error{});
    if (!data) {
        Km2oLangevinData flat;
        flat.correlationLength = m;
        flat.gammaPlus = flat.gammaMinus = Eigen::MatrixXd::Zero(m + 1, m + 1);
        flat.varianceForward = flat.varianceBackward = Eigen::VectorXd::Ones(m + 1);
        flat.partialForward = Eigen::VectorXd::Zero(m + 1);
        return flat;
    }
    data->varianceForward *= varianceScale; // eq. 4.35: V_+ = K/(K-1) V_+(diff)
    data->varianceBackward *= varianceScale;
    return std::move(data).value();
}

/// For each absolute time, whether a window offset t >= first reaches it.
std::vector<char> reachedByLateOffsets(Eigen::Index frames, int m, Eigen::Index lastT0, int first)
{
    std::vector<char> reached(std::size_t(frames), 0);
    for (Eigen::Index t0 = 0; t0 <= lastT0; ++t0)
        for (int t = std::max(first, 0); t <= m; ++t) reached[std::size_t(t0 + t)] = 1;
    return reached;
}

/// sum / weight element by element; NaN where nothing was averaged (weight 0).
Eigen::MatrixXd weightedMeans(const Eigen::MatrixXd& sum, const Eigen::MatrixXd& weight)
{
    return (weight.array() > 0.0).select(sum.array() / weight.array(), kNaN).matrix();
}

Error outOfRange(int m, int maxM, Eigen::Index frames)
{
    return Error{ErrorCode::InvalidArgument, "KM2O: correlation length M = " + std::to_string(m) + " outside 0..M_max = " +
                                                 std::to_string(maxM) + " (M_max = floor(3 sqrt(T+1)) - 1, T = " +
                                                 std::to_string(frames - 1) + ", thesis eq. 4.30)"};
}

/// The first m + 1 offsets of KM2O data computed up to a larger M: the recursion's values for
/// t <= m do not depend on how far it goes.
Km2oLangevinData leading(const Km2oLangevinData& data, int m)
{
    Km2oLangevinData out;
    out.correlationLength = m;
    out.gammaPlus = data.gammaPlus.topLeftCorner(m + 1, m + 1);
    out.gammaMinus = data.gammaMinus.topLeftCorner(m + 1, m + 1);
    out.varianceForward = data.varianceForward.head(m + 1);
    out.varianceBackward = data.varianceBackward.head(m + 1);
    out.partialForward = data.partialForward.head(m + 1);
    return out;
}

/// out[i] = first[i] + sum (or - sum) over s < count of coefficients[s] * series[s stride + i],
/// for i < n, the terms added in order s = 0, 1, ... for every i: the same bits as one i at a
/// time, eight independent sums at once.
template <bool Subtract>
void addTerms(double* out, const double* first, const double* series, Eigen::Index stride, const double* coefficients, int count,
              Eigen::Index n)
{
    using Block8 = Eigen::Array<double, 8, 1>;
    Eigen::Index i = 0;
    for (; i + 8 <= n; i += 8) {
        Block8 a = Eigen::Map<const Block8>(first + i);
        for (int s = 0; s < count; ++s) {
            const Eigen::Map<const Block8> x(series + Eigen::Index(s) * stride + i);
            if constexpr (Subtract)
                a -= coefficients[s] * x;
            else
                a += coefficients[s] * x;
        }
        Eigen::Map<Block8>(out + i) = a;
    }
    for (; i < n; ++i) {
        double a = first[i];
        for (int s = 0; s < count; ++s) {
            if constexpr (Subtract)
                a -= coefficients[s] * series[Eigen::Index(s) * stride + i];
            else
                a += coefficients[s] * series[Eigen::Index(s) * stride + i];
        }
        out[i] = a;
    }
}

} // namespace

void ExogenousCells::markovGains(const std::vector<Km2oLangevinData>& langevin, int m, std::vector<Eigen::MatrixXd>& gain,
                                 std::vector<Eigen::VectorXd>& estimateVariance) const
{
    // Markov estimate per window offset t: unknowns theta = (u, v^{i2}..v^{iJ}), observations
    // e^{ij} = u + v^{ij} + noise of variance V_+^{ij}(t)/K_j (eq. 4.36), so
    // theta = (A^T W A)^-1 A^T W e with A = [1 0; 1 I] and W = diag(K_j / V_+^{ij}(t)).
    const int cellCount = int(m_cells.size());
    Eigen::MatrixXd design = Eigen::MatrixXd::Zero(cellCount, cellCount);
    for (int j = 0; j < cellCount; ++j) {
        design(j, 0) = 1.0;
        if (j > 0) design(j, j) = 1.0;
    }
    gain.resize(std::size_t(m + 1));
    estimateVariance.resize(std::size_t(m + 1));
    for (int t = 0; t <= m; ++t) {
        Eigen::VectorXd w(cellCount);
        for (int j = 0; j < cellCount; ++j)
            w(j) = double(m_cells[std::size_t(j)].cols()) / langevin[std::size_t(j)].varianceForward(t);
        const Eigen::MatrixXd normal = design.transpose() * w.asDiagonal() * design;
        const Eigen::MatrixXd covariance = normal.inverse();
        gain[std::size_t(t)] = covariance * design.transpose() * w.asDiagonal();
        estimateVariance[std::size_t(t)] = covariance.diagonal();
    }
}

Result<ExogenousCells> ExogenousCells::prepare(std::vector<Eigen::MatrixXd> cells, int maxCorrelationLength)
{
    if (cells.empty()) return makeError(ErrorCode::InvalidArgument, "KM2O inputs: no cells");
    const Eigen::Index frames = cells[0].rows();
    for (std::size_t j = 0; j < cells.size(); ++j) {
        if (cells[j].rows() != frames)
            return makeError(ErrorCode::InvalidArgument, "KM2O inputs: cell " + std::to_string(j + 1) + " has " +
                                                             std::to_string(cells[j].rows()) + " frames, expected " +
                                                             std::to_string(frames) + " (pad or normalise first)");
        if (cells[j].cols() < 1) return makeError(ErrorCode::InvalidArgument, "KM2O inputs: cell " + std::to_string(j + 1) + " has no take");
        if (!cells[j].allFinite())
            return makeError(ErrorCode::Numerical, "KM2O inputs: cell " + std::to_string(j + 1) + " has non-finite values");
    }
    if (std::none_of(cells.begin(), cells.end(), [](const Eigen::MatrixXd& c) { return c.cols() >= 2; }))
        return makeError(ErrorCode::InvalidArgument, "KM2O inputs: every cell has 1 take; the diff series (eqs. 4.24-4.26) need at "
                                                     "least one cell with K >= 2 takes");
    const int maxM = analysis::maxCorrelationLength(frames);
    if (maxCorrelationLength < 0 || maxCorrelationLength > maxM) return outOfRange(maxCorrelationLength, maxM, frames);
    ExogenousCells prepared;
    prepared.m_maxLag = maxCorrelationLength;
    prepared.m_means.resize(frames, Eigen::Index(cells.size()));
    // R(tau) of every lag is computed alone, so R(0..M) of a smaller M is a prefix of these.
    const int lags = int(std::min<Eigen::Index>(maxCorrelationLength, frames - 1));
    // A one-take cell's diff series is identically zero (eq. 4.24): its gamma and V_+ are those
    // of the pooled diff series of the cells with K >= 2 (docs/KM2O.md, "Cells with one take"):
    // R_pool = sum_j K_j R_diff^j / sum_j (K_j - 1), unbiased for R of the fluctuation as
    // K/(K-1) R_diff is per cell (eq. 4.35), weighted by the cells' degrees of freedom.
    Eigen::VectorXd pooled = Eigen::VectorXd::Zero(lags + 1);
    double degrees = 0.0;
    for (std::size_t j = 0; j < cells.size(); ++j) {
        prepared.m_means.col(Eigen::Index(j)) = cells[j].rowwise().mean();
        const Eigen::Index k = cells[j].cols();
        prepared.m_varianceScale.push_back(k >= 2 ? double(k) / double(k - 1) : 1.0);
        if (k < 2) {
            prepared.m_autocovariance.emplace_back();
            continue;
        }
        const Eigen::MatrixXd diff = cells[j].colwise() - prepared.m_means.col(Eigen::Index(j));
        auto r = biasedAutocovariance(diff, lags);
        if (!r) return r.error();
        pooled += double(k) * *r;
        degrees += double(k - 1);
        prepared.m_autocovariance.push_back(std::move(r).value());
    }
    pooled /= degrees;
    for (std::size_t j = 0; j < cells.size(); ++j)
        if (cells[j].cols() < 2) prepared.m_autocovariance[j] = pooled;
    prepared.m_cells = std::move(cells);
    // The KM2O data and Markov gains up to the longest M serve every shorter M when the
    // recursion went all the way for every cell (a cell whose recursion stops at some M is
    // flat from there on only: its shorter M are computed on their own).
    prepared.m_leading = true;
    for (std::size_t j = 0; j < prepared.m_cells.size(); ++j) {
        const Eigen::VectorXd& r = prepared.m_autocovariance[j];
        const Eigen::VectorXd mean = prepared.m_means.col(Eigen::Index(j));
        const double scale = std::max(1.0, mean.squaredNorm() / double(mean.size()));
        const bool flatForEveryM = !(r(0) > 1e-24 * scale);
        if (!flatForEveryM && !km2oFromAutocovariance(r, lags)) prepared.m_leading = false;
        prepared.m_langevin.push_back(cellLangevin(r, mean, prepared.m_varianceScale[j], lags));
    }
    if (prepared.m_leading) prepared.markovGains(prepared.m_langevin, lags, prepared.m_gain, prepared.m_estimateVariance);
    return prepared;
}

Result<ExogenousEstimate> estimateExogenousInputs(const std::vector<Eigen::MatrixXd>& cells, const ExogenousOptions& options)
{
    auto prepared = ExogenousCells::prepare(cells, options.correlationLength);
    if (!prepared) return prepared.error();
    return prepared->estimate(options);
}

Result<ExogenousEstimate> ExogenousCells::estimate(const ExogenousOptions& options) const
{
    const Eigen::Index frames = frameCount();
    const int cellCount = int(m_cells.size());
    const int m = options.correlationLength;
    if (m < 0 || m > analysis::maxCorrelationLength(frames)) return outOfRange(m, analysis::maxCorrelationLength(frames), frames);
    if (m > m_maxLag)
        return makeError(ErrorCode::InvalidArgument, "KM2O: correlation length M = " + std::to_string(m) +
                                                         " beyond the " + std::to_string(m_maxLag) + " the cells were prepared for");
    const Eigen::Index lastFrame = frames - 1;
    const Eigen::Index lastT0 = options.initialTimes == InitialTimeRange::Full ? lastFrame - m : lastFrame - m - 1;
    if (lastT0 < 0)
        return makeError(ErrorCode::InvalidArgument, "KM2O: M = " + std::to_string(m) + " leaves no initial time T0 for " +
                                                         std::to_string(frames) + " frames");
    const Eigen::Index windows = lastT0 + 1;

    ExogenousEstimate est;
    est.correlationLength = m;
    est.cellMeans = m_means;
    std::vector<Eigen::MatrixXd> ownGain;
    std::vector<Eigen::VectorXd> ownVariance;
    if (m_leading) {
        for (int j = 0; j < cellCount; ++j) est.langevin.push_back(leading(m_langevin[std::size_t(j)], m));
    } else {
        for (int j = 0; j < cellCount; ++j)
            est.langevin.push_back(cellLangevin(m_autocovariance[std::size_t(j)], m_means.col(j), m_varianceScale[std::size_t(j)], m));
        markovGains(est.langevin, m, ownGain, ownVariance);
    }
    const std::vector<Eigen::MatrixXd>& gain = m_leading ? m_gain : ownGain;
    const std::vector<Eigen::VectorXd>& estimateVariance = m_leading ? m_estimateVariance : ownVariance;

    const auto reached = reachedByLateOffsets(frames, m, lastT0, options.firstWindowOffset);
    auto used = [&](Eigen::Index t0, int t) {
        return t >= options.firstWindowOffset || !reached[std::size_t(t0 + t)];
    };
    auto weightOf = [&](int t, int unknown) {
        return options.average == WindowAverage::Uniform ? 1.0 : 1.0 / estimateVariance[std::size_t(t)](unknown);
    };

    // Every window at once, offset by offset: row T0 of theta holds the Markov estimates of the
    // window starting at T0, column t J + i unknown i at offset t. Every number takes the same
    // operations in the same order as it would one window at a time (the left side of eq. 4.36
    // summed over s = 0..t-1, the gain applied column by column from zero, the estimates of an
    // absolute time averaged from the earliest window on), so the layout does not change a bit.
    Eigen::MatrixXd theta(windows, (m + 1) * cellCount);
    Eigen::MatrixXd e(windows, cellCount);
    Eigen::ArrayXd sum(windows);
    std::vector<double> coefficients(std::size_t(m + 1));
    auto rowOf = [&](const Eigen::MatrixXd& g, int t) {
        for (int s = 0; s < t; ++s) coefficients[std::size_t(s)] = g(t, s);
        return coefficients.data();
    };
    for (int t = 0; t <= m; ++t) {
        for (int j = 0; j < cellCount; ++j) {
            const double* means = m_means.col(j).data();
            addTerms<false>(e.col(j).data(), means + t, means, 1, rowOf(est.langevin[std::size_t(j)].gammaPlus, t), t, windows);
        }
        const Eigen::MatrixXd& k = gain[std::size_t(t)];
        for (int i = 0; i < cellCount; ++i) {
            sum.setZero();
            for (int j = 0; j < cellCount; ++j) sum = e.col(j).array() * k(i, j) + sum;
            theta.col(t * cellCount + i) = (sum + 0.0).matrix();
        }
    }

    // Window estimates summed per absolute time T0 + t, from the earliest window T0 on: offsets
    // from the last down.
    auto accumulate = [&](Eigen::MatrixXd& total, Eigen::MatrixXd& weights, int t, int unknown, const double* estimates) {
        const double wt = weightOf(t, unknown);
        if (t >= options.firstWindowOffset) {
            total.col(unknown).segment(t, windows) += wt * Eigen::Map<const Eigen::VectorXd>(estimates, windows);
            weights.col(unknown).segment(t, windows).array() += wt;
            return;
        }
        for (Eigen::Index t0 = 0; t0 <= lastT0; ++t0) {
            if (!used(t0, t)) continue;
            total(t0 + t, unknown) += wt * estimates[t0];
            weights(t0 + t, unknown) += wt;
        }
    };
    Eigen::MatrixXd inputSum = Eigen::MatrixXd::Zero(frames, cellCount); // col 0 u, col j v^{ij}
    Eigen::MatrixXd inputWeight = Eigen::MatrixXd::Zero(frames, cellCount);
    est.estimateCount = Eigen::VectorXi::Zero(frames);
    for (int t = m; t >= 0; --t) {
        for (int j = 0; j < cellCount; ++j) accumulate(inputSum, inputWeight, t, j, theta.col(t * cellCount + j).data());
        for (Eigen::Index t0 = 0; t0 <= lastT0; ++t0)
            if (used(t0, t)) ++est.estimateCount(t0 + t);
    }
    const Eigen::MatrixXd inputs = weightedMeans(inputSum, inputWeight);
    est.functionInput = inputs.col(0);
    est.emotionInputs = inputs;
    est.emotionInputs.col(0).setZero();

    // Components (eqs. 4.41-4.43): per window, the recursion with gamma of the neutral cell for
    // y, of cell j for z, from the window's own t = 0 estimate; averaged per absolute time like
    // the inputs. Again every window at once: window.col(t) holds offset t of every window.
    Eigen::MatrixXd componentSum = Eigen::MatrixXd::Zero(frames, cellCount);
    Eigen::MatrixXd componentWeight = Eigen::MatrixXd::Zero(frames, cellCount);
    Eigen::MatrixXd window(windows, m + 1);
    for (int j = 0; j < cellCount; ++j) {
        const auto& g = est.langevin[std::size_t(j)].gammaPlus;
        for (int t = 0; t <= m; ++t) {
            // eq. 4.41: the window starts from its own t = 0 Markov estimate (variance V_+(0));
            // later offsets use the inputs averaged per absolute time (eqs. 4.42/4.43).
            const double* first = t == 0 ? theta.col(j).data() : inputs.col(j).data() + t;
            addTerms<true>(window.col(t).data(), first, window.data(), windows, rowOf(g, t), t, windows);
        }
        for (int t = m; t >= 0; --t) accumulate(componentSum, componentWeight, t, j, window.col(t).data());
    }
    const Eigen::MatrixXd components = weightedMeans(componentSum, componentWeight);
    est.functionComponent = components.col(0);
    est.emotionComponents = components;
    est.emotionComponents.col(0).setZero();
    return est;
}

double relativeError(const Eigen::VectorXd& estimate, const Eigen::VectorXd& truth)
{
    double num = 0.0;
    double den = 0.0;
    for (Eigen::Index t = 0; t < std::min(estimate.size(), truth.size()); ++t) {
        if (!std::isfinite(estimate(t))) continue;
        num += (estimate(t) - truth(t)) * (estimate(t) - truth(t));
        den += truth(t) * truth(t);
    }
    return den > 0.0 ? num / den : kNaN;
}

} // namespace bunraku::analysis
