#include "analysis/normalise/amplitude_matching.h"

#include "analysis/normalise/feature_matching.h"
#include "analysis/normalise/wavelet_features.h"

#include <string>

namespace bunraku::analysis {

Result<MatchResult> matchAmplitudes(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& sample,
                                    const AmplitudeMatchOptions& options, const RunControl& control)
{
    if (reference.cols() == 0 || reference.cols() != sample.cols())
        return makeError(ErrorCode::InvalidArgument, "matching: reference and sample need the same (non-zero) number of channels, got "
                                                         + std::to_string(reference.cols()) + " and " + std::to_string(sample.cols()));
    if (!reference.allFinite() || !sample.allFinite())
        return makeError(ErrorCode::InvalidArgument, "matching: the takes contain NaN or infinite values");
    const Eigen::VectorXd weights = channelWeights(reference, options.weighting);
    const FeatureMatrix referenceFeatures = levelAligned(reference, options.level) * weights.asDiagonal();
    const FeatureMatrix sampleFeatures = levelAligned(sample, options.level) * weights.asDiagonal();
    return matchFeatures(referenceFeatures, sampleFeatures, {options.tau, options.searchBand, options.path}, control);
}

} // namespace bunraku::analysis
