#include "analysis/core/puppet_layout.h"

namespace bunraku::analysis {

std::vector<Channel> sixDofChannels(std::string_view part)
{
    std::vector<Channel> channels;
    for (int d = 0; d < kDofCount; ++d)
        channels.push_back(Channel{std::string(part), std::string(kDofNames[std::size_t(d)]), isAngleDof(d) ? "deg" : "cm"});
    return channels;
}

std::vector<Channel> puppetChannels()
{
    std::vector<Channel> channels;
    for (auto part : kPuppetParts) {
        auto six = sixDofChannels(part);
        channels.insert(channels.end(), six.begin(), six.end());
    }
    return channels;
}

bool hasPuppetLayout(const Take& take) { return take.channels == puppetChannels(); }

std::vector<SixDofPart> sixDofParts(const Take& take)
{
    std::vector<SixDofPart> result;
    const auto& ch = take.channels;
    for (std::size_t i = 0; i + kDofCount <= ch.size();) {
        bool match = true;
        for (int d = 0; d < kDofCount && match; ++d)
            match = ch[i + std::size_t(d)].part == ch[i].part && ch[i + std::size_t(d)].dof == kDofNames[std::size_t(d)];
        if (match) {
            result.push_back(SixDofPart{ch[i].part, Eigen::Index(i)});
            i += kDofCount;
        } else {
            ++i;
        }
    }
    return result;
}

std::vector<SixDofPart> pointParts(const Take& take)
{
    std::vector<SixDofPart> result;
    const auto& ch = take.channels;
    std::vector<bool> inPart(ch.size(), false);
    for (const SixDofPart& part : sixDofParts(take))
        for (int d = 0; d < kDofCount; ++d) inPart[std::size_t(part.firstChannel + d)] = true;
    for (std::size_t i = 0; i + 3 <= ch.size();) {
        const bool match = !inPart[i] && !inPart[i + 1] && !inPart[i + 2] && ch[i].dof == "x" && ch[i + 1].dof == "y" && ch[i + 2].dof == "z" &&
                           ch[i + 1].part == ch[i].part && ch[i + 2].part == ch[i].part;
        if (match) {
            result.push_back(SixDofPart{ch[i].part, Eigen::Index(i)});
            i += 3;
        } else {
            ++i;
        }
    }
    return result;
}

} // namespace bunraku::analysis
