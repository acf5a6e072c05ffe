#pragma once
/// ARMA(p, q) identification of the fluctuation eta (thesis 4.3.2, eqs. 4.9-4.11, Table 4.1):
///   eta(t) = -sum_{m=1..p} a_m eta(t-m) + sum_{n=0..q} b_n w(t-n),  w unit white noise.
/// Estimator: prediction-error minimisation of the conditional sum of squares (residuals from
/// t = p with zero pre-sample innovations; the conditional Gaussian maximum likelihood) by
/// Levenberg-Marquardt with the analytic gradient recursion, started from a Hannan-Rissanen
/// two-stage regression. In normalised form eta(t) + sum a_m eta(t-m) = e(t) + sum c_n e(t-n),
/// var e = sigma^2, so b_0 = sigma and b_n = c_n sigma. No mean is removed (eta is zero-mean).
/// Order selection by the final prediction error FPE = (1 + n/T)/(1 - n/T) V, n = p + q + 1 (eq. 4.10).
/// The MA part is identified only up to its spectrum: b and any b' with the same MA
/// autocovariances (roots reflected in the unit circle) fit alike. fitArma reports the invertible
/// factor (all roots inside); Table 4.1's b columns are another factor (thesisMaConvention,
/// docs/ARMA.md), reported beside it.

#include "analysis/core/result.h"
#include "analysis/decompose/least_squares.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

struct ArmaModel {
    int p = 0;
    int q = 0;
    Eigen::VectorXd a;         ///< a_1..a_p (thesis sign: AR polynomial 1 + a_1 z^-1 + ...)
    Eigen::VectorXd c;         ///< c_1..c_q, normalised MA polynomial 1 + c_1 z^-1 + ...
    Eigen::VectorXd b;         ///< b_0..b_q = sigma (1, c_1..c_q): invertible (every root of B inside the unit circle)
    /// b_0..b_q in Table 4.1's convention: the same spectrum with B's largest root(s) outside the
    /// unit circle (thesisMaConvention(b)); b1/b0 > 1 where the thesis prints 2.1-4.5.
    Eigen::VectorXd bThesis;
    double innovationVariance = 0.0; ///< sigma^2 = V, the mean squared one-step prediction error
    double fpe = 0.0;          ///< eq. 4.10 with T = series length
    int iterations = 0;
};

struct ArmaOptions {
    int maxIterations = 200;
    double tolerance = 1e-10; ///< relative decrease of the sum of squares that ends the search
};

/// b_0..b_q with the roots of B(z) = b_0 z^q + ... + b_q of largest modulus (a conjugate pair
/// counts as one) reflected outside the unit circle (r -> 1 / conj(r), gain |r|), the others
/// kept; b_0 made positive. |B(e^{iw})|^2, hence the MA autocovariances, are unchanged. Every
/// row of Table 4.1 has exactly this shape (one root at -2.1..-4.5, the other |r| < 0.08).
/// Returns b when q = 0, b_0 = 0 or all roots are 0.
Eigen::VectorXd thesisMaConvention(const Eigen::VectorXd& b);
/// The invertible factor of b: every root outside the unit circle reflected inside, b_0 > 0
/// (the convention fitArma reports).
Eigen::VectorXd invertibleMa(const Eigen::VectorXd& b);
/// The MA part's autocovariances gamma(k) = sum_n b_n b_{n+k}, k = 0..q: the same for every
/// factor, the convention-free comparison.
Eigen::VectorXd maAutocovariance(const Eigen::VectorXd& b);

/// Fits ARMA(p, q). Errors: p, q < 0; series shorter than 3 (p + q + 1) + 10; non-finite values;
/// zero variance.
Result<ArmaModel> fitArma(const Eigen::VectorXd& series, int p, int q, const ArmaOptions& options = {});

enum class ArmaOrderSearch {
    AllPairs,    ///< every (p, q) with 0 <= p, q <= maxOrder
    EqualOrders, ///< (n, n), n = 1..maxOrder (the thesis's "order n")
};

struct ArmaOrderOptions {
    int maxOrder = 4;
    ArmaOrderSearch search = ArmaOrderSearch::AllPairs;
    ArmaOptions fit;
};

struct ArmaOrderSelection {
    ArmaModel best;          ///< smallest FPE
    Eigen::MatrixXd fpe;     ///< (maxOrder+1) x (maxOrder+1), fpe(p, q); NaN where not fitted
};

/// Fits every candidate order and keeps the smallest FPE (eq. 4.10).
Result<ArmaOrderSelection> selectArmaOrder(const Eigen::VectorXd& series, const ArmaOrderOptions& options = {});

/// One row of Table 4.1: the parameters of the K takes of a cell averaged.
struct ArmaCellRow {
    std::string function;
    std::string emotion;
    int takes = 0;
    ArmaModel mean; ///< a, c, b, bThesis, innovationVariance and fpe averaged over the takes (each take converted first)
};

/// ARMA(p, q) of channel `channel` of every fluctuation, averaged per cell (Table 4.1 layout,
/// rows in Decomposition::emotions order). A cell with one take has no fluctuation (its take is
/// its own mean, eq. 4.24, whatever the components' residual): its row has takes = 0. Errors: channel out of range, fit errors (named).
Result<std::vector<ArmaCellRow>> armaCellTable(const Decomposition& decomposition, Eigen::Index channel, int p, int q,
                                               const ArmaOptions& options = {});

} // namespace bunraku::analysis
