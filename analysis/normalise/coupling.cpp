#include "analysis/normalise/coupling.h"

#include <algorithm>
#include <map>
#include <set>

namespace bunraku::analysis {

namespace {

// Channel indices by part and dof; dofs in order of first appearance.
struct Layout {
    std::map<std::string, std::map<std::string, Eigen::Index>> byPart;
    std::vector<std::string> parts;
    std::vector<std::string> dofs;
};

Layout layoutOf(const Take& take)
{
    Layout layout;
    for (Eigen::Index c = 0; c < Eigen::Index(take.channels.size()); ++c) {
        const Channel& channel = take.channels[std::size_t(c)];
        if (!layout.byPart.count(channel.part)) layout.parts.push_back(channel.part);
        layout.byPart[channel.part][channel.dof] = c;
        if (std::find(layout.dofs.begin(), layout.dofs.end(), channel.dof) == layout.dofs.end())
            layout.dofs.push_back(channel.dof);
    }
    return layout;
}

// Per dof, the named parts' channels together (eqs. 3.28/3.29); other channels alone.
Result<Coupling> pairsPerDof(const Take& take, const std::vector<std::vector<std::string>>& groups)
{
    const Layout layout = layoutOf(take);
    for (const auto& group : groups)
        for (const auto& part : group)
            if (!layout.byPart.count(part))
                return makeError(ErrorCode::NotFound, "coupling: the take has no part '" + part + "' (method1/method2 need head, shoulder, arm, hand)");
    Coupling coupling;
    std::set<Eigen::Index> used;
    for (const auto& dof : layout.dofs) {
        for (const auto& group : groups) {
            std::vector<Eigen::Index> set;
            std::string name;
            for (const auto& part : group) {
                const auto& dofs = layout.byPart.at(part);
                if (auto it = dofs.find(dof); it != dofs.end()) {
                    set.push_back(it->second);
                    name += (name.empty() ? "" : "+") + part;
                }
            }
            if (set.empty()) continue;
            for (auto c : set) used.insert(c);
            coupling.sets.push_back(set);
            coupling.names.push_back(name + "." + dof);
        }
    }
    for (Eigen::Index c = 0; c < Eigen::Index(take.channels.size()); ++c) {
        if (used.count(c)) continue;
        coupling.sets.push_back({c});
        coupling.names.push_back(take.channels[std::size_t(c)].name());
    }
    return coupling;
}

} // namespace

std::vector<std::string> couplingPresetNames()
{
    return {"independent", "method1", "method2", "per-part", "per-coordinate", "all"};
}

Result<Coupling> couplingFor(const Take& take, std::string_view spec)
{
    const Eigen::Index count = Eigen::Index(take.channels.size());
    if (count == 0) return makeError(ErrorCode::InvalidArgument, "coupling: the take has no channels");
    Coupling coupling;
    if (spec == "independent") {
        for (Eigen::Index c = 0; c < count; ++c) {
            coupling.sets.push_back({c});
            coupling.names.push_back(take.channels[std::size_t(c)].name());
        }
        return coupling;
    }
    if (spec == "method1") return pairsPerDof(take, {{"arm", "hand"}});
    if (spec == "method2") return pairsPerDof(take, {{"head", "shoulder"}, {"arm", "hand"}});
    if (spec == "all") {
        std::vector<Eigen::Index> set(static_cast<std::size_t>(count));
        for (Eigen::Index c = 0; c < count; ++c) set[std::size_t(c)] = c;
        coupling.sets.push_back(set);
        coupling.names.emplace_back("all");
        return coupling;
    }
    if (spec == "per-part" || spec == "per-coordinate") {
        const Layout layout = layoutOf(take);
        const bool perPart = spec == "per-part";
        for (const auto& key : perPart ? layout.parts : layout.dofs) {
            std::vector<Eigen::Index> set;
            for (Eigen::Index c = 0; c < count; ++c) {
                const Channel& channel = take.channels[std::size_t(c)];
                if ((perPart ? channel.part : channel.dof) == key) set.push_back(c);
            }
            coupling.sets.push_back(set);
            coupling.names.push_back(key);
        }
        return coupling;
    }

    // Explicit: "a.x+b.x;c.y+d.y".
    if (spec.find('.') == std::string_view::npos) {
        std::string known;
        for (const auto& name : couplingPresetNames()) known += (known.empty() ? "" : ", ") + name;
        return makeError(ErrorCode::InvalidArgument,
                         "coupling: unknown preset '" + std::string(spec) + "' (expected " + known + ", or channel sets like arm.x+hand.x;head.x+shoulder.x)");
    }
    std::set<Eigen::Index> used;
    std::size_t start = 0;
    while (start <= spec.size()) {
        std::size_t end = spec.find(';', start);
        if (end == std::string_view::npos) end = spec.size();
        const std::string_view group = spec.substr(start, end - start);
        std::vector<Eigen::Index> set;
        std::size_t from = 0;
        while (from <= group.size() && !group.empty()) {
            std::size_t to = group.find('+', from);
            if (to == std::string_view::npos) to = group.size();
            const std::string name(group.substr(from, to - from));
            const auto index = take.channelIndex(name);
            if (!index) return makeError(ErrorCode::NotFound, "coupling: unknown channel '" + name + "'");
            if (!used.insert(*index).second) return makeError(ErrorCode::InvalidArgument, "coupling: channel '" + name + "' is named twice");
            set.push_back(*index);
            from = to + 1;
        }
        if (!set.empty()) {
            coupling.sets.push_back(set);
            coupling.names.emplace_back(group);
        }
        start = end + 1;
    }
    for (Eigen::Index c = 0; c < count; ++c) {
        if (used.count(c)) continue;
        coupling.sets.push_back({c});
        coupling.names.push_back(take.channels[std::size_t(c)].name());
    }
    return coupling;
}

} // namespace bunraku::analysis
