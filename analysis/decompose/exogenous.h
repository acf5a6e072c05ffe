#pragma once
/// Exogenous inputs of the KM2O-Langevin equation with varying initial time (thesis 4.4.1-4.4.4):
/// for one degree of freedom of one function i, the cells j = 1..J (j = 1 the neutral emotion)
/// each hold K takes x_k^{ij}(t), modelled as
///   x_k^{ij}(T0+t) = -sum_{s<t} gamma_+^{ij}(t,s) x_k^{ij}(T0+s) + u^i(T0+t) + v^{ij}(T0+t) + nu_k(T0+t)
/// (eq. 4.21) with v^{i1} = 0. gamma_+^{ij}, V_+^{ij} come from the diff series x_k - x_mean
/// (eqs. 4.22-4.35); u^i, v^{ij} are Markov (generalised least squares) estimates from eq. 4.36
/// for every initial time T0 and window offset t = 0..M, averaged per absolute time T0 + t.
/// The function and emotion components y^i, z^{ij} follow from eqs. 4.42/4.43.

#include "analysis/core/result.h"
#include "analysis/decompose/km2o.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

/// Which initial times T0 are used.
enum class InitialTimeRange {
    Thesis, ///< T0 = 0..T-M-1 (thesis 4.4.4): the last frame T gets no estimate
    Full,   ///< T0 = 0..T-M: every frame is reached by at least one window
};

/// How window estimates are averaged per absolute time.
enum class WindowAverage {
    Uniform,        ///< every estimate counts once (the digest's reading)
    VarianceWeighted, ///< estimates weighted by 1/V_+(t), the inverse variance of eq. 4.36's noise
};

struct ExogenousOptions {
    int correlationLength = 2; ///< M, 0 <= M <= maxCorrelationLength(frames)
    /// Estimates from window offsets t < firstWindowOffset are used only at absolute times that
    /// no later offset reaches (times 0..firstWindowOffset-1). 0 keeps every estimate (the
    /// digest's reading); 2 drops the below-model-order estimates of an ARX(2) series.
    int firstWindowOffset = 0;
    InitialTimeRange initialTimes = InitialTimeRange::Full;
    WindowAverage average = WindowAverage::Uniform;
};

/// Inputs and components of one function family in one channel; all vectors have one entry per
/// frame, NaN at frames no window reaches (only with InitialTimeRange::Thesis: the last frame).
struct ExogenousEstimate {
    int correlationLength = 0;
    Eigen::VectorXd functionInput;       ///< u^i(t)
    Eigen::MatrixXd emotionInputs;       ///< frames x J, v^{ij}(t); column 0 (neutral) is zero
    /// y^i(t): per window, y(T0) = the window's own t = 0 Markov estimate (eq. 4.41), then eq. 4.42
    /// with gamma of the neutral cell and the averaged inputs; averaged per absolute time.
    Eigen::VectorXd functionComponent;
    Eigen::MatrixXd emotionComponents;   ///< frames x J, z^{ij}(t), likewise with eq. 4.43; column 0 is zero
    Eigen::MatrixXd cellMeans;           ///< frames x J, x_mean^{ij}(t) (eq. 4.22)
    std::vector<Km2oLangevinData> langevin; ///< per cell, V_+ already scaled by K/(K-1) (eq. 4.35)
    Eigen::VectorXi estimateCount;       ///< window estimates averaged at each frame
};

/// Identifies u^i, v^{ij}, y^i, z^{ij} from `cells` (cell j: frames x K_j takes, all with the
/// same frame count; cells[0] is the neutral emotion). A cell with K_j = 1 has an identically
/// zero diff series (eq. 4.24): its gamma_+ and V_+ come from the diff series of the cells with
/// K_j >= 2 pooled (R = sum K_j R_diff^j / sum (K_j - 1), docs/KM2O.md "Cells with one take"),
/// as the thesis's simulation (eq. 4.39) gives all cells of a function the same dynamics a^i.
/// Errors: fewer than one cell, unequal frame counts, no cell with K >= 2, M outside 0..M_max
/// (clear message), non-finite values.
Result<ExogenousEstimate> estimateExogenousInputs(const std::vector<Eigen::MatrixXd>& cells,
                                                  const ExogenousOptions& options = {});

/// What estimateExogenousInputs computes independently of M, for estimating many M of the same
/// cells (choosing M by P, thesis 4.4.4): the checked cells, their means x_mean^{ij} (eq. 4.22)
/// and the autocovariance of their diff series (eq. 4.26) up to the largest M asked for.
class ExogenousCells {
public:
    /// Errors as estimateExogenousInputs's for the cells, and for maxCorrelationLength outside
    /// 0..M_max.
    static Result<ExogenousCells> prepare(std::vector<Eigen::MatrixXd> cells, int maxCorrelationLength);

    /// Bit for bit estimateExogenousInputs(cells, options); InvalidArgument for an M beyond the
    /// prepared one.
    Result<ExogenousEstimate> estimate(const ExogenousOptions& options) const;

    Eigen::Index frameCount() const { return m_means.rows(); }
    /// Whether cell j (one take) has the pooled gamma_+ and V_+ of the cells with K >= 2.
    bool pooled(std::size_t j) const { return m_cells[j].cols() < 2; }
    int maxCorrelationLength() const { return m_maxLag; }

private:
    ExogenousCells() = default;
    /// Eq. 4.36's Markov gains (A^T W A)^-1 A^T W and estimate variances, offsets 0..m.
    void markovGains(const std::vector<Km2oLangevinData>& langevin, int m, std::vector<Eigen::MatrixXd>& gain,
                     std::vector<Eigen::VectorXd>& estimateVariance) const;

    std::vector<Eigen::MatrixXd> m_cells;
    Eigen::MatrixXd m_means;                       ///< frames x J
    /// per cell, R(0..maxLag) of the diff series; of the pooled diff series for a one-take cell
    std::vector<Eigen::VectorXd> m_autocovariance;
    std::vector<double> m_varianceScale;           ///< per cell, K/(K-1) (eq. 4.35); 1 when pooled
    int m_maxLag = 0;
    /// Whether the data below, computed up to maxLag, hold every shorter M's as their first rows.
    bool m_leading = false;
    std::vector<Km2oLangevinData> m_langevin;      ///< per cell, eq. 4.35's scaling applied
    std::vector<Eigen::MatrixXd> m_gain;           ///< per offset 0..maxLag
    std::vector<Eigen::VectorXd> m_estimateVariance;
};

/// Relative error P = sum_t (estimate - truth)^2 / sum_t truth^2 (thesis eq. 4.40, a fraction,
/// not percent), over the frames where the estimate is finite. NaN when truth is all zero.
double relativeError(const Eigen::VectorXd& estimate, const Eigen::VectorXd& truth);

} // namespace bunraku::analysis
