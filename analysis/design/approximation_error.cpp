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
    std::vector<double> scales;
    for (int c = 1; c <= options.maxScale; ++c) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "approximation error cancelled");
        result.scales.push_back(c);
        scales.push_back(double(c));
        double sum = 0.0;
        int counted = 0;
        for (Eigen::Index q = 0; q < dofs; ++q) {
            const double norm = functional.col(q).norm();
            if (!(norm > 0.0)) continue;
            auto af = cwtApproximation(functional.col(q), scales, options.cwt);
            if (!af) return af.error();
            auto ae = cwtApproximation(emotionalOnFunctionalTime.col(q), scales, options.cwt);
            if (!ae) return ae.error();
            const double error = (*ae - *af).norm() / norm; // eq. 5.18
            result.relativeError(c - 1, q) = error;
            sum += error;
            ++counted;
        }
        if (counted > 0) result.meanRelativeError(c - 1) = sum / counted;
        control.report(double(c) / options.maxScale);
    }
    return result;
}

} // namespace bunraku::analysis
