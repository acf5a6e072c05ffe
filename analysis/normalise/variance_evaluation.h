#pragma once
/// Evaluation of a normalisation (thesis 3.8, Tables 3.4/3.5) and the choice of a reference
/// take (thesis 3.6.1).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

/// sum_t (x_k(t) - x_ref(t))^2 per take and channel, before and after normalisation.
struct VarianceTable {
    std::vector<std::string> takeNames;    ///< displayName of each take
    std::vector<std::string> channelNames;
    Eigen::MatrixXd before;                ///< takes x channels, raw take vs reference
    Eigen::MatrixXd after;                 ///< takes x channels, normalised take vs reference
    Eigen::VectorXd totalBefore;           ///< per take, summed over channels
    Eigen::VectorXd totalAfter;
};

/// Frames are compared over the reference's length; a shorter raw take is padded with its last
/// frame (thesis 2.2). Angle channels of 6-DOF parts are compared as rotation coordinates about
/// the reference's mean part orientations (degrees; analysis/core/angle_channels.h), so a take
/// written on another Euler branch, or crossing a gimbal region, costs only what its
/// orientations differ. InvalidArgument when counts or channels differ.
Result<VarianceTable> varianceTable(const Take& reference, const std::vector<const Take*>& rawTakes,
                                    const std::vector<const Take*>& normalisedTakes);

/// Sum of squared differences over frames of the reference's length (missing sample frames
/// repeat the last one), per channel; angles as in varianceTable when both takes have the same
/// channels.
Eigen::VectorXd squaredDifference(const Take& reference, const Take& take);

struct ReferenceSuggestion {
    int takeIndex = 0;                  ///< index into the takes
    std::vector<bool> outlier;          ///< per take: far from the others (thesis: take 1)
    std::vector<Eigen::Index> activeFrames; ///< per take: frames before the final rest
    std::vector<Eigen::Index> startFrame;   ///< per take: first frame of motion
    std::string reason;
    std::size_t alignments = 0; ///< timing alignments the outlier test made (at most n * kOutlierPeers)
};

/// Thesis 3.6.1: among takes that are not outliers, the one starting earliest, then the longest.
/// Angles are taken as rotation coordinates about the takes' mean part orientations, and
/// channels are standardised over all takes. Outlier: mean distance to the other takes after
/// aligning timing (amplitude DTW, band 20) above twice the median of those means (3+ takes).
/// Motion starts at the first frame whose distance from the first frame exceeds 10% of its
/// maximum; the active part ends at the last frame that far from the final frame.
/// In a cell of more than kOutlierPeers + 1 takes, each take's mean distance is taken over
/// kOutlierPeers others spread evenly over the cell (n * kOutlierPeers alignments, not n^2).
/// InvalidArgument for no takes, differing channels or takes under 2 frames; Cancelled when
/// `control` is (checked for every take).
inline constexpr std::size_t kOutlierPeers = 32;
Result<ReferenceSuggestion> suggestReference(const std::vector<const Take*>& takes, const RunControl& control = {});

} // namespace bunraku::analysis
