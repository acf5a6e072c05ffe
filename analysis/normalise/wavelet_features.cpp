#include "analysis/normalise/wavelet_features.h"

#include "analysis/wavelet/cwt_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace bunraku::analysis {

Status validateMatchOptions(const MatchOptions& options, Eigen::Index referenceFrames, Eigen::Index sampleFrames)
{
    if (options.tau < 0) return makeError(ErrorCode::InvalidArgument, "matching: tau must be >= 0, got " + std::to_string(options.tau));
    if (options.searchBand < 0 || options.searchBand > kMaxSearchBand)
        return makeError(ErrorCode::InvalidArgument, "matching: the search band T_cmp must be in 0.." + std::to_string(kMaxSearchBand)
                                                         + " frames, got " + std::to_string(options.searchBand));
    if (options.scales.empty()) return makeError(ErrorCode::InvalidArgument, "matching: no wavelet scales given");
    if (!(options.approximationWeight >= 0.0) || !std::isfinite(options.approximationWeight)) {
        std::ostringstream message;
        message << "matching: the approximation weight M must be finite and >= 0, got " << options.approximationWeight;
        return makeError(ErrorCode::InvalidArgument, message.str());
    }
    // The sample is transformed at the reference's length when a global time scale applies.
    const Eigen::Index transformedSample = globalTimeScale(options, referenceFrames, sampleFrames) == 1.0 ? sampleFrames : referenceFrames;
    const Eigen::Index frames = std::min(referenceFrames, transformedSample);
    const int largest = largestScale(options.cwt.wavelet, frames);
    for (double scale : options.scales) {
        if (!std::isfinite(scale) || scale <= 0.0 || scale > double(largest)) {
            std::ostringstream message;
            message << "matching: scale " << scale << " does not fit a take of " << frames << " frames with wavelet "
                    << options.cwt.wavelet.name << " (usable scales: 0 < c <= " << largest << ")";
            return makeError(ErrorCode::InvalidArgument, message.str());
        }
    }
    return okStatus();
}

Eigen::VectorXd channelWeights(const Eigen::MatrixXd& reference, ChannelWeighting weighting)
{
    Eigen::VectorXd weights = Eigen::VectorXd::Ones(reference.cols());
    if (weighting == ChannelWeighting::None || reference.rows() < 2) return weights;
    for (Eigen::Index c = 0; c < reference.cols(); ++c) {
        const double mean = reference.col(c).mean();
        const double deviation = std::sqrt((reference.col(c).array() - mean).square().sum() / double(reference.rows() - 1));
        if (deviation > 1e-12) weights[c] = 1.0 / deviation;
    }
    return weights;
}

Eigen::MatrixXd levelAligned(const Eigen::MatrixXd& values, LevelAlignment level)
{
    if (level == LevelAlignment::None || values.rows() == 0) return values;
    return values.rowwise() - values.row(0);
}

Status waveletFeaturesInto(const Eigen::MatrixXd& channels, const Eigen::VectorXd& weights, const MatchOptions& options,
                           const CwtFilterBank& bank, FeatureSeries& out, const RunControl& control)
{
    const Eigen::Index scales = Eigen::Index(bank.scales.size());
    const Eigen::MatrixXd aligned = levelAligned(channels, options.level) * weights.asDiagonal();
    if (!(options.approximationWeight > 0.0)) return cwtChannelSeriesInto(aligned, bank, out, RunControl{control.stop, {}});
    auto coefficients = cwtChannelSeries(aligned, bank, RunControl{control.stop, {}});
    if (!coefficients) return coefficients.error();

    // Eq. 5.17: sqrt(M) * A(t) after each channel's coefficients.
    const Eigen::Index perChannel = scales + 1;
    out.resize(channels.rows(), channels.cols() * perChannel);
    const double factor = std::sqrt(options.approximationWeight);
    for (Eigen::Index c = 0; c < channels.cols(); ++c) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "matching cancelled");
        out.middleCols(c * perChannel, scales) = coefficients->middleCols(c * scales, scales);
        auto approximation = cwtApproximation(aligned.col(c), options.scales, options.cwt);
        if (!approximation) return approximation.error();
        out.col(c * perChannel + scales) = factor * *approximation;
    }
    return okStatus();
}

Result<FeatureSeries> waveletFeatures(const Eigen::MatrixXd& channels, const Eigen::VectorXd& weights,
                                      const MatchOptions& options, const CwtFilterBank& bank, const RunControl& control)
{
    FeatureSeries features;
    if (auto status = waveletFeaturesInto(channels, weights, options, bank, features, control); !status) return status.error();
    return features;
}

} // namespace bunraku::analysis
