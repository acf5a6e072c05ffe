#pragma once
/// Normalising whole takes (thesis 3.6): every coupling set of a sample take is matched to the
/// reference take and the sample is resampled on the reference's time axis. Angles are matched
/// and resampled as rotation coordinates (analysis/core/angle_channels.h) about the
/// reference's mean part orientations, so neither the Euler branch nor gimbal regions of the
/// takes change the result; the normalised take's angles are Euler-filtered. Takes of any
/// lengths: MatchOptions::timeScaling. The sample's full skeleton is resampled at its body time.

#include "analysis/core/angle_channels.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"
#include "analysis/normalise/coupling.h"
#include "analysis/normalise/wavelet_matching.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

enum class MatchFeatures {
    Wavelet,   ///< CWT coefficients (the thesis)
    Amplitude, ///< raw values: the DP/DTW baseline
};

struct NormaliseOptions {
    MatchOptions match;
    std::string coupling = kDefaultCoupling; ///< see couplingFor: method2 on the puppet, chains on a skeleton
    MatchFeatures features = MatchFeatures::Wavelet;
};

struct TakeNormalisation {
    /// The sample on the reference's time axis: reference frames x sample channels.
    Take normalised;
    Coupling coupling;
    /// One match per coupling set, in coupling.sets order.
    std::vector<MatchResult> matches;
    /// reference frames x channels: the sample frame each channel took at each reference frame.
    Eigen::MatrixXi correspondence;
    /// reference frames x channels: `normalised` in rotation coordinates about `chart`.
    Eigen::MatrixXd coordinates;
    /// The reference's mean part orientations (ChartTime::Constant), where angles were matched.
    RotationChart chart;
    /// Per reference frame the (fractional) sample frame the whole body shows: the mean of the
    /// channels' correspondences. The normalised skeleton is the sample's resampled at it.
    Eigen::VectorXd bodyTime;
    double cost = 0; ///< summed over the sets
};

/// Matches every coupling set of sample to reference (same channels required; NotFound names a
/// missing channel) and applies the correspondences. Cancelled via control; progress per set.
Result<TakeNormalisation> normaliseTake(const Take& reference, const Take& sample,
                                        const NormaliseOptions& options = {}, const RunControl& control = {});

/// The takes of one cell normalised to one reference (which may be one of them: it maps to
/// itself). Results in the takes' order.
Result<std::vector<TakeNormalisation>> normaliseTakes(const Take& reference, const std::vector<const Take*>& takes,
                                                      const NormaliseOptions& options = {},
                                                      const RunControl& control = {});

} // namespace bunraku::analysis
