#include "analysis/normalise/wavelet_matching.h"

#include "analysis/normalise/wavelet_features.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace bunraku::analysis {

double globalTimeScale(const MatchOptions& options, Eigen::Index referenceFrames, Eigen::Index sampleFrames)
{
    if (referenceFrames < 2 || sampleFrames < 2 || referenceFrames == sampleFrames) return 1.0;
    const bool scale = options.timeScaling == TimeScaling::Global ||
                       (options.timeScaling == TimeScaling::Auto &&
                        double(std::abs(referenceFrames - sampleFrames)) > kAutoScalingBand * double(options.searchBand));
    return scale ? double(sampleFrames - 1) / double(referenceFrames - 1) : 1.0;
}

Eigen::MatrixXd scaledInTime(const Eigen::MatrixXd& values, double scale, Eigen::Index frames)
{
    Eigen::VectorXd at(frames);
    for (Eigen::Index t = 0; t < frames; ++t) at[t] = scale * double(t);
    return applyWarp(values, at);
}

MatchResult unscaledMatch(MatchResult match, double scale, Eigen::Index sampleFrames)
{
    if (scale == 1.0) return match;
    const double last = double(std::max<Eigen::Index>(sampleFrames - 1, 0));
    for (Eigen::Index t = 0; t < match.correspondence.size(); ++t)
        match.correspondence[t] = int(std::lround(std::clamp(scale * double(match.correspondence[t]), 0.0, last)));
    for (Eigen::Index t = 0; t < match.smoothWarp.size(); ++t) match.smoothWarp[t] = std::clamp(scale * match.smoothWarp[t], 0.0, last);
    return match;
}

Result<MatchResult> matchChannels(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& sample,
                                  const MatchOptions& options, const RunControl& control)
{
    if (reference.cols() == 0 || reference.cols() != sample.cols())
        return makeError(ErrorCode::InvalidArgument, "matching: reference and sample need the same (non-zero) number of channels, got "
                                                         + std::to_string(reference.cols()) + " and " + std::to_string(sample.cols()));
    if (!reference.allFinite() || !sample.allFinite())
        return makeError(ErrorCode::InvalidArgument, "matching: the takes contain NaN or infinite values");
    if (auto status = validateMatchOptions(options, reference.rows(), sample.rows()); !status) return status.error();
    auto bank = makeCwtFilterBank(options.scales, options.cwt);
    if (!bank) return bank.error();
    const Eigen::VectorXd weights = channelWeights(reference, options.weighting);
    auto referenceFeatures = waveletFeatures(reference, weights, options, *bank, control);
    if (!referenceFeatures) return referenceFeatures.error();
    const double scale = globalTimeScale(options, reference.rows(), sample.rows());
    auto sampleFeatures =
        waveletFeatures(scale == 1.0 ? sample : scaledInTime(sample, scale, reference.rows()), weights, options, *bank, control);
    if (!sampleFeatures) return sampleFeatures.error();
    auto match = matchFeatures(*referenceFeatures, *sampleFeatures, {options.tau, options.searchBand, options.path}, control);
    if (!match) return match.error();
    return unscaledMatch(std::move(match).value(), scale, sample.rows());
}

Eigen::MatrixXd applyCorrespondence(const Eigen::MatrixXd& sample, const Eigen::VectorXi& correspondence)
{
    Eigen::MatrixXd out(correspondence.size(), sample.cols());
    for (Eigen::Index t = 0; t < correspondence.size(); ++t) {
        const Eigen::Index frame = std::clamp<Eigen::Index>(correspondence[t], 0, sample.rows() - 1);
        out.row(t) = sample.row(frame);
    }
    return out;
}

Eigen::MatrixXd applyWarp(const Eigen::MatrixXd& sample, const Eigen::VectorXd& warp)
{
    Eigen::MatrixXd out(warp.size(), sample.cols());
    const double last = double(sample.rows() - 1);
    for (Eigen::Index t = 0; t < warp.size(); ++t) {
        const double x = std::clamp(warp[t], 0.0, last);
        const auto below = Eigen::Index(std::floor(x));
        const Eigen::Index above = std::min<Eigen::Index>(below + 1, sample.rows() - 1);
        const double f = x - double(below);
        out.row(t) = (1.0 - f) * sample.row(below) + f * sample.row(above);
    }
    return out;
}

} // namespace bunraku::analysis
