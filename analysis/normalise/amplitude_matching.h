#pragma once
/// The baseline the thesis argues against (3.1, 3.4): DP matching / DTW on the values
/// themselves, with the same band T_cmp, window and non-decreasing constraint as the wavelet
/// matcher, so that the comparison isolates the features.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/normalise/wavelet_matching.h"

#include <Eigen/Core>

namespace bunraku::analysis {

struct AmplitudeMatchOptions {
    int tau = 0;                            ///< half window, frames (0 = classic DTW local cost)
    int searchBand = 20;                    ///< T_cmp, frames
    PathMethod path = PathMethod::Optimal;  ///< DTW is a dynamic programme
    ChannelWeighting weighting = ChannelWeighting::None;
    LevelAlignment level = LevelAlignment::FirstFrame;
};

/// reference, sample: frames x channels sharing one correspondence; cost = squared value
/// differences summed over the window and the channels. Errors as matchChannels.
Result<MatchResult> matchAmplitudes(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& sample,
                                    const AmplitudeMatchOptions& options = {}, const RunControl& control = {});

} // namespace bunraku::analysis
