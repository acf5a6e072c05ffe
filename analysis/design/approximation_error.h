#pragma once
/// The per-scale approximation error of thesis 5.4.1 (eq. 5.18, Fig. 5.16): for every largest
/// scale c = 1..c_max, the approximations A_f and A_e left by scales 1..c (eq. 5.13, thesis
/// 5.3.2) of the functional axis and of the phase-adjusted emotional axis are compared, per axis
/// DOF, relative to the functional motion itself:
///   e_q(c) = sqrt(sum_t |A_e,q(t) - A_f,q(t)|^2) / sqrt(sum_t |X_f,q(t)|^2).
/// The thesis found the error falling as c grows but, for some DOF, still large at large c, and
/// therefore extracted the amplitude component with Fourier series over phrases instead
/// (5.4.2). Figure 5.16's values are not printed in the text.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/wavelet/cwt.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

struct ApproximationErrorOptions {
    int maxScale = 16; ///< c = 1..maxScale (the thesis's range of 5.3.4; at most 21 for 106 frames)
    CwtOptions cwt;    ///< sym3, MATLAB-compatible (no extension)
};

struct ApproximationError {
    std::vector<int> scales;     ///< c = 1..maxScale
    /// scales x DOF: eq. 5.18 per axis DOF (a fraction; NaN where sum X_f^2 = 0).
    Eigen::MatrixXd relativeError;
    /// scales: the mean over the DOF with a finite error.
    Eigen::VectorXd meanRelativeError;
};

/// functional, emotionalOnFunctionalTime: frames x DOF, the same shape (the emotional axis
/// already phase-adjusted, DesignParameters::emotionalOnFunctionalTime). Errors: shapes differ,
/// maxScale outside 1..256, non-finite values, transform errors; Cancelled via control.
Result<ApproximationError> approximationErrorByScale(const Eigen::MatrixXd& functional,
                                                     const Eigen::MatrixXd& emotionalOnFunctionalTime,
                                                     const ApproximationErrorOptions& options = {},
                                                     const RunControl& control = {});

} // namespace bunraku::analysis
