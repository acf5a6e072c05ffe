#include "analysis/design/approximation_error.h"

#include "analysis/wavelet/cwt_reconstruction.h"

#include <cmath>
#include <limits>
#include <string>

namespace bunraku::analysis {

Result<ApproximationError> approximationErrorByScale(const Eigen::MatrixXd& functional,
                                                     const Eigen::MatrixXd& emotionalOnFunctionalTime,
                                                     const ApproximationErrorOptions& options, const RunControl& control)
{
    if (functional.rows() != emotionalOnFunctionalTime.rows() || functional.cols() != emotionalOnFunctionalTime.cols())
        return makeError(ErrorCode::InvalidArgument,
                         "approximation error: the functional axis is " + std::to_string(functional.rows()) + " x " +
                             std::to_string(functional.cols()) + ", the emotional " +
                             std::to_string(emotionalOnFunctionalTime.rows()) + " x " +
                             std::to_string(emotionalOnFunctionalTime.cols()) + " (expected the same frames x DOF)");
    if (options.maxScale < 1 || options.maxScale > 256)
        return makeError(ErrorCode::InvalidArgument,
                         "approximation error: the largest scale must be in 1..256, got " + std::to_string(options.maxScale));
    if (functional.rows() < 2) return makeError(ErrorCode::InvalidArgument, "approximation error: need at least 2 frames");
    if (!functional.allFinite() || !emotionalOnFunctionalTime.allFinite())
        return makeError(ErrorCode::Numerical, "approximation error: the axes have non-finite values");
    const Eigen::Index dofs = functional.cols();
    ApproximationError result;
    result.relativeError = Eigen::MatrixXd::Constant(options.maxScale, dofs, std::numeric_limits<double>::quiet_NaN());
    result.meanRelativeError = Eigen::VectorXd::Constant(options.maxScale, std::numeric_limits<double>::quiet_NaN());
    for (int c = 1; c <= options.maxScale; ++c) result.scales.push_back(c);
    // The approximation is linear in the signal and, for the integer scales 1..c (each with
    // share 1 of the scale axis), x minus the sum of the single scales' reconstructions: so
    // A_e - A_f = d - sum_{s <= c} R_s(d) with d = emotional - functional, one reconstruction
    // per DOF (cwtScaleContributions) instead of one per largest scale and signal.
    std::vector<double> scales;
    for (int c = 1; c <= options.maxScale; ++c) scales.push_back(double(c));
    for (Eigen::Index q = 0; q < dofs; ++q) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "approximation error cancelled");
        const double norm = functional.col(q).norm();
        if (!(norm > 0.0)) continue;
        const Eigen::VectorXd difference = emotionalOnFunctionalTime.col(q) - functional.col(q);
        auto parts = cwtScaleContributions(difference, scales, options.cwt);
        if (!parts) return parts.error();
        Eigen::VectorXd residual = difference;
        for (int c = 1; c <= options.maxScale; ++c) {
            residual -= parts->col(c - 1);
            result.relativeError(c - 1, q) = residual.norm() / norm; // eq. 5.18
        }
        control.report(double(q + 1) / double(dofs));
    }
    for (int c = 1; c <= options.maxScale; ++c) {
        double sum = 0.0;
        int counted = 0;
        for (Eigen::Index q = 0; q < dofs; ++q)
            if (std::isfinite(result.relativeError(c - 1, q))) {
                sum += result.relativeError(c - 1, q);
                ++counted;
            }
        if (counted > 0) result.meanRelativeError(c - 1) = sum / counted;
    }
    return result;
}

} // namespace bunraku::analysis
