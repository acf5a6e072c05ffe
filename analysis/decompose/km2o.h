#pragma once
/// KM2O-Langevin data of a stationary scalar series: the biased sample autocovariance, Okabe's
/// forward/backward recursion (in one dimension exactly the Durbin-Levinson recursion) giving the
/// coefficients gamma_+(t, s) and fluctuation variances V_+(t) for t = 0..M, and a direct
/// Yule-Walker solve to check it against (thesis 4.4.2, eqs. 4.26-4.30).

#include "analysis/core/result.h"

#include <Eigen/Core>

namespace bunraku::analysis {

/// The largest reliable correlation length for a series of `frameCount` = T + 1 samples:
/// M_max = floor(3 sqrt(T + 1)) - 1 (thesis eq. 4.30). 29 for the 106-frame puppet takes.
int maxCorrelationLength(Eigen::Index frameCount);

/// Biased sample autocovariance R(tau) = 1/(T+1) sum_{s=0..T-tau} x(s+tau) x(s), tau = 0..maxLag,
/// averaged over the columns of `series` (frames x realisations; thesis eq. 4.26, averaged over
/// the K takes of a cell). No mean is removed: the diff series are zero-mean by construction.
/// Errors: maxLag < 0 or >= frames, no column, non-finite values.
Result<Eigen::VectorXd> biasedAutocovariance(const Eigen::MatrixXd& series, int maxLag);

/// KM2O-Langevin data up to correlation length M.
struct Km2oLangevinData {
    int correlationLength = 0; ///< M
    /// (M+1) x (M+1), gammaPlus(t, s) for 0 <= s < t <= M (zero elsewhere): the coefficient of
    /// x(T0+s) in x(T0+t) = -sum_{s<t} gamma_+(t,s) x(T0+s) + nu_+(T0+t) (thesis eq. 4.13).
    Eigen::MatrixXd gammaPlus;
    /// Backward coefficients gamma_-(t, s), same shape (equal to gammaPlus in one dimension).
    Eigen::MatrixXd gammaMinus;
    Eigen::VectorXd varianceForward;  ///< V_+(t), t = 0..M; V_+(0) = R(0)
    Eigen::VectorXd varianceBackward; ///< V_-(t), t = 0..M
    Eigen::VectorXd partialForward;   ///< delta_+(t) = gamma_+(t, 0), t = 1..M (index 0 unused, 0)
};

/// Okabe's forward/backward recursion from R(0..M):
/// Delta(n) = R(n) + sum_{k=0..n-2} gamma_+(n-1,k) R(k+1); delta_+(n) = -Delta(n)/V_-(n-1),
/// delta_-(n) = -Delta(n)/V_+(n-1); gamma_+(n,0) = delta_+(n),
/// gamma_+(n,k) = gamma_+(n-1,k-1) + delta_+(n) gamma_-(n-1,n-1-k) (1 <= k <= n-1), and
/// symmetrically for gamma_-; V_+-(n) = (1 - delta_+ delta_-) V_+-(n-1).
/// Errors: M < 0, R shorter than M+1, R(0) <= 0 or a variance reaching zero (degenerate data).
Result<Km2oLangevinData> km2oFromAutocovariance(const Eigen::VectorXd& autocovariance, int correlationLength);

/// KM2O-Langevin data of `series` (frames x realisations) with M checked against
/// maxCorrelationLength (the error message names M, M_max and T).
Result<Km2oLangevinData> km2oLangevinData(const Eigen::MatrixXd& series, int correlationLength);

/// The order-n forward linear predictor solved directly from the Toeplitz Yule-Walker system
/// sum_j phi_j R(|i-j|) = R(i), i = 1..n.
struct YuleWalkerPredictor {
    Eigen::VectorXd coefficients; ///< phi_1..phi_n: x(t) ~ sum_j phi_j x(t-j)
    double innovationVariance = 0.0; ///< R(0) - sum_j phi_j R(j)
};

/// Direct (Cholesky/LU) Yule-Walker solve of order n, the peer of the recursion:
/// gamma_+(n, s) = -phi_{n-s}, V_+(n) = innovationVariance.
Result<YuleWalkerPredictor> yuleWalkerPredictor(const Eigen::VectorXd& autocovariance, int order);

} // namespace bunraku::analysis
