#pragma once
/// What `bunraku info` says of a corpus's takes beyond their labels: each channel's range over
/// every take, and how well the puppet's rig fits takes of its 24 channels without a skeleton
/// (analysis/skeleton/puppet_rig_fit.h), as JSON and as text.

#include "analysis/core/corpus.h"
#include "analysis/skeleton/puppet_rig_fit.h"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::report {

/// Per channel of the first take's layout (every take of a corpus has it): the least and the
/// largest value over every frame of every take.
struct ChannelRanges {
    Eigen::VectorXd low, high; ///< channels
};
ChannelRanges channelRanges(const Corpus& corpus);
/// [{channel, unit, min, max}] of `channels`.
nlohmann::json channelRangesJson(const std::vector<Channel>& channels, const ChannelRanges& ranges);
/// A line per channel: name, min .. max (3 decimals), unit.
std::string channelRangesText(const std::vector<Channel>& channels, const ChannelRanges& ranges);

/// {takes, frames, parts {part: {max_cm, rms_cm, max_deg}}, segment_cm {joint: length}} of the rig
/// fitted to `takes` takes.
nlohmann::json puppetRigFitJson(const PuppetRigFit& rig, std::size_t takes);

} // namespace bunraku::analysis::report
