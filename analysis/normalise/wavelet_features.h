#pragma once
/// The per-frame feature vectors of wavelet matching: for each channel its CWT coefficients
/// over the scales (thesis 3.2) and, with approximation weight M > 0, sqrt(M) * A(t) (eq. 5.17),
/// so that squared feature distances are exactly the summands of eqs. 3.28 and 5.17.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/normalise/feature_matching.h"
#include "analysis/normalise/wavelet_matching.h"

#include <Eigen/Core>

namespace bunraku::analysis {

/// Checks the options against the take lengths (tau, band, scales fit the shorter of the
/// reference and the sample as transformed - at the reference's length when a global time
/// scale applies: largestScale, M >= 0); InvalidArgument with the offending value.
Status validateMatchOptions(const MatchOptions& options, Eigen::Index referenceFrames, Eigen::Index sampleFrames);

/// Per-channel multipliers: 1 (ChannelWeighting::None) or 1 / standard deviation of the
/// reference's channel (Standardise; 1 for a constant channel). reference: frames x channels.
Eigen::VectorXd channelWeights(const Eigen::MatrixXd& reference, ChannelWeighting weighting);

/// The values with each channel's first frame subtracted (LevelAlignment::FirstFrame) or as
/// they are. frames x channels.
Eigen::MatrixXd levelAligned(const Eigen::MatrixXd& values, LevelAlignment level);

/// frames x (channels * (scales + [M > 0])) features (column-major) of `channels` (frames x channels), each
/// channel level-aligned (options.level) and multiplied by its weight first. InvalidArgument for NaN; Cancelled via control.
Result<FeatureSeries> waveletFeatures(const Eigen::MatrixXd& channels, const Eigen::VectorXd& weights,
                                      const MatchOptions& options, const CwtFilterBank& bank,
                                      const RunControl& control = {});

/// waveletFeatures into `out` (resized; its storage is reused when it already has that size).
Status waveletFeaturesInto(const Eigen::MatrixXd& channels, const Eigen::VectorXd& weights, const MatchOptions& options,
                           const CwtFilterBank& bank, FeatureSeries& out, const RunControl& control = {});

} // namespace bunraku::analysis
