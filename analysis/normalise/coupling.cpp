#include "analysis/normalise/coupling.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton.h"
#include "analysis/normalise/skeleton_chains.h"

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
                return makeError(ErrorCode::NotFound, "coupling: the take has no part '" + part + "' (method1/method2 need head, shoulder, arm, hand; a skeleton's joints take chains)");
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

// Per dof, the channels of each chain of the take's skeleton together; other channels alone.
// A take without a skeleton: the puppet's two chains (head+shoulder, arm+hand), as method2.
Result<Coupling> chainsPerDof(const Take& take)
{
    const Layout layout = layoutOf(take);
    std::vector<std::string> chainNames;
    std::map<std::string, int> partChain; // part -> index into chainNames
    if (take.skeleton && take.skeleton->skeleton) {
        const Skeleton& skeleton = *take.skeleton->skeleton;
        auto chains = skeletonChains(*take.skeleton);
        if (!chains) return makeError(chains.error().code, "coupling: " + chains.error().message);
        std::vector<int> chainOf(skeleton.joints.size(), -1);
        for (std::size_t k = 0; k < chains->size(); ++k) {
            chainNames.push_back((*chains)[k].name);
            for (int j : (*chains)[k].joints) chainOf[std::size_t(j)] = int(k);
        }
        // Each part's chain: the joint a puppet part is bound to, or the joint of that name.
        for (const auto& part : layout.parts) {
            int joint = -1;
            if (const PartBinding* binding = skeleton.binding(part)) joint = binding->joint;
            if (joint < 0) joint = skeleton.find(part);
            if (joint >= 0 && skeleton.joints[std::size_t(joint)].endSite) joint = -1;
            if (joint >= 0 && std::size_t(joint) < chainOf.size() && chainOf[std::size_t(joint)] >= 0)
                partChain[part] = chainOf[std::size_t(joint)];
        }
    } else {
        for (const auto& part : {"head", "shoulder", "arm", "hand"})
            if (!layout.byPart.count(part))
                return makeError(ErrorCode::NotFound, "coupling: chains needs the take's skeleton or the puppet's parts (head, "
                                                      "shoulder, arm, hand); " + take.displayName() + " has neither");
        chainNames = {"spine", "arm"};
        partChain = {{"head", 0}, {"shoulder", 0}, {"arm", 1}, {"hand", 1}};
    }
    Coupling coupling;
    coupling.preset = "chains";
    std::set<Eigen::Index> used;
    for (const auto& dof : layout.dofs) {
        for (std::size_t k = 0; k < chainNames.size(); ++k) {
            std::vector<Eigen::Index> set;
            for (const auto& part : layout.parts) {
                const auto chain = partChain.find(part);
                if (chain == partChain.end() || chain->second != int(k)) continue;
                const auto& dofs = layout.byPart.at(part);
                if (auto it = dofs.find(dof); it != dofs.end()) set.push_back(it->second);
            }
            if (set.empty()) continue;
            for (auto c : set) used.insert(c);
            coupling.sets.push_back(set);
            coupling.names.push_back(chainNames[k] + "." + dof);
        }
    }
    for (Eigen::Index c = 0; c < Eigen::Index(take.channels.size()); ++c) {
        if (used.count(c)) continue;
        coupling.sets.push_back({c});
        coupling.names.push_back(take.channels[std::size_t(c)].name());
    }
    return coupling;
}

Result<Coupling> presetCoupling(const Take& take, std::string_view spec);

// `auto`: the thesis's method2 on the puppet's parts, chains on a skeleton's joints.
Result<Coupling> automaticCoupling(const Take& take)
{
    const auto parts = take.parts();
    bool puppet = true;
    for (const auto part : kPuppetParts) puppet = puppet && std::find(parts.begin(), parts.end(), part) != parts.end();
    if (puppet && parts.size() <= kPuppetParts.size()) return presetCoupling(take, "method2");
    if (take.skeleton && take.skeleton->skeleton) return presetCoupling(take, "chains");
    if (puppet) return presetCoupling(take, "method2");
    return makeError(ErrorCode::NotFound, "coupling: " + take.displayName() +
                                              " has neither the puppet's parts (head, shoulder, arm, hand) for method2 nor a skeleton "
                                              "for chains; give a coupling (independent, per-part, per-coordinate, all or channel sets)");
}

} // namespace

std::vector<std::string> couplingPresetNames()
{
    return {"auto", "method2", "method1", "chains", "independent", "per-part", "per-coordinate", "all"};
}

Result<Coupling> couplingFor(const Take& take, std::string_view spec)
{
    return presetCoupling(take, spec);
}

namespace {

Result<Coupling> presetCoupling(const Take& take, std::string_view spec)
{
    const Eigen::Index count = Eigen::Index(take.channels.size());
    if (count == 0) return makeError(ErrorCode::InvalidArgument, "coupling: the take has no channels");
    Coupling coupling;
    if (spec == "independent" || spec == "all" || spec == "per-part" || spec == "per-coordinate") coupling.preset = std::string(spec);
    if (spec == "independent") {
        for (Eigen::Index c = 0; c < count; ++c) {
            coupling.sets.push_back({c});
            coupling.names.push_back(take.channels[std::size_t(c)].name());
        }
        return coupling;
    }
    if (spec == "auto") return automaticCoupling(take);
    if (spec == "chains") return chainsPerDof(take);
    if (spec == "method1" || spec == "method2") {
        auto pairs = spec == "method1" ? pairsPerDof(take, {{"arm", "hand"}}) : pairsPerDof(take, {{"head", "shoulder"}, {"arm", "hand"}});
        if (pairs) pairs->preset = std::string(spec);
        return pairs;
    }
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

} // namespace

} // namespace bunraku::analysis
