#include "analysis/report/corpus_description.h"

#include "analysis/core/puppet_layout.h"

#include <iomanip>
#include <limits>
#include <sstream>

namespace bunraku::analysis::report {

ChannelRanges channelRanges(const Corpus& corpus)
{
    const Eigen::Index channels = corpus.takes.front().channelCount();
    ChannelRanges ranges;
    ranges.low = Eigen::VectorXd::Constant(channels, std::numeric_limits<double>::infinity());
    ranges.high = -ranges.low;
    for (const Take& take : corpus.takes) {
        ranges.low = ranges.low.cwiseMin(take.values.colwise().minCoeff().transpose());
        ranges.high = ranges.high.cwiseMax(take.values.colwise().maxCoeff().transpose());
    }
    return ranges;
}

nlohmann::json channelRangesJson(const std::vector<Channel>& channels, const ChannelRanges& ranges)
{
    nlohmann::json out = nlohmann::json::array();
    for (Eigen::Index c = 0; c < ranges.low.size(); ++c)
        out.push_back({{"channel", channels[std::size_t(c)].name()},
                       {"unit", channels[std::size_t(c)].unit},
                       {"min", ranges.low[c]},
                       {"max", ranges.high[c]}});
    return out;
}

std::string channelRangesText(const std::vector<Channel>& channels, const ChannelRanges& ranges)
{
    std::ostringstream out;
    for (Eigen::Index c = 0; c < ranges.low.size(); ++c)
        out << "  " << std::left << std::setw(22) << channels[std::size_t(c)].name() << std::right << std::fixed
            << std::setprecision(3) << std::setw(12) << ranges.low[c] << " .. " << std::setw(12) << ranges.high[c] << " " << channels[std::size_t(c)].unit << "\n";
    return out.str();
}

nlohmann::json puppetRigFitJson(const PuppetRigFit& rig, std::size_t takes)
{
    nlohmann::json parts = nlohmann::json::object();
    for (std::size_t p = 0; p < kPuppetParts.size(); ++p)
        parts[std::string(kPuppetParts[p])] = {{"max_cm", rig.residual.maxCm[p]},
                                               {"rms_cm", rig.residual.rmsCm[p]},
                                               {"max_deg", rig.residual.maxDeg[p]}};
    nlohmann::json segments = nlohmann::json::object();
    for (const auto& joint : rig.skeleton->joints)
        if (joint.parent >= 0) segments[joint.name] = joint.offset.norm();
    return {{"takes", takes}, {"frames", rig.residual.frames}, {"parts", parts}, {"segment_cm", segments}};
}

} // namespace bunraku::analysis::report
