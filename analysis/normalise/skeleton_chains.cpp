#include "analysis/normalise/skeleton_chains.h"

#include "analysis/io/bvh_joint_map.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <string_view>

namespace bunraku::analysis {

namespace {

constexpr std::array<std::string_view, 15> kLegWords{"hip", "thigh", "upleg", "upperleg", "femur", "knee", "shin", "leg",
                                                     "tibia", "calf", "ankle", "foot", "toe", "heel", "buttock"};
constexpr std::array<std::string_view, 14> kArmWords{"collar", "clavicle", "shoulder", "shldr", "arm", "humerus", "elbow",
                                                     "radius", "wrist", "hand", "palm", "finger", "thumb", "index"};

bool containsAny(const std::string& term, auto words)
{
    return std::any_of(words.begin(), words.end(), [&](std::string_view w) { return term.find(w) != std::string::npos; });
}

/// The skeleton's joints as trees: children that are joints (End Sites left out), subtree sizes.
struct Tree {
    std::vector<std::vector<int>> children;
    std::vector<int> size;
    explicit Tree(const Skeleton& skeleton) : children(skeleton.joints.size()), size(skeleton.joints.size(), 0)
    {
        for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
            if (skeleton.joints[j].parent >= 0 && !skeleton.joints[j].endSite)
                children[std::size_t(skeleton.joints[j].parent)].push_back(int(j));
        for (std::size_t j = skeleton.joints.size(); j-- > 0;) {
            size[j] += skeleton.joints[j].endSite ? 0 : 1;
            if (skeleton.joints[j].parent >= 0) size[std::size_t(skeleton.joints[j].parent)] += size[j];
        }
    }
    /// `joint` and every joint below it, parents first.
    std::vector<int> subtree(int joint) const
    {
        std::vector<int> out{joint};
        for (std::size_t i = 0; i < out.size(); ++i)
            for (int c : children[std::size_t(out[i])]) out.push_back(c);
        std::sort(out.begin(), out.end()); // parents precede children in Skeleton::joints
        return out;
    }
};

bool below(const Skeleton& skeleton, int joint, int ancestor)
{
    for (int j = joint; j >= 0; j = skeleton.joints[std::size_t(j)].parent)
        if (j == ancestor) return true;
    return false;
}

/// The child of `joint` that continues the spine, -1 when the spine ends at `joint`.
int spineChild(const Skeleton& skeleton, const Tree& tree, int joint, int head)
{
    const auto& c = tree.children[std::size_t(joint)];
    if (joint == head || c.empty()) return -1;
    if (head >= 0)
        for (int k : c)
            if (below(skeleton, head, k)) return k;
    if (c.size() == 1) return c.front();
    if (c.size() == 2) {
        const int a = tree.size[std::size_t(c[0])], b = tree.size[std::size_t(c[1])];
        if (a == b) return -1; // a pair of limbs
        return a > b ? c[0] : c[1];
    }
    // Three or more: the most similar pair are limbs; the largest of the rest goes on.
    std::vector<int> bySize(c.begin(), c.end());
    std::stable_sort(bySize.begin(), bySize.end(), [&](int x, int y) { return tree.size[std::size_t(x)] < tree.size[std::size_t(y)]; });
    std::size_t pair = 0;
    for (std::size_t i = 1; i + 1 < bySize.size(); ++i)
        if (tree.size[std::size_t(bySize[i + 1])] - tree.size[std::size_t(bySize[i])] <
            tree.size[std::size_t(bySize[pair + 1])] - tree.size[std::size_t(bySize[pair])])
            pair = i;
    int best = -1;
    for (std::size_t i = 0; i < bySize.size(); ++i) {
        if (i == pair || i == pair + 1) continue;
        if (best < 0 || tree.size[std::size_t(bySize[i])] > tree.size[std::size_t(best)]) best = bySize[i];
    }
    return best;
}

enum class LimbKind { Arm, Leg };

struct Limb {
    LimbKind kind = LimbKind::Arm;
    int side = 0; ///< +1 left, -1 right, 0 unknown
    std::vector<int> joints;
};

} // namespace

Result<std::vector<SkeletonChain>> skeletonChains(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>* positions)
{
    if (skeleton.jointCount() == 0) return makeError(ErrorCode::InvalidArgument, "skeleton chains: the skeleton has no joints");
    const Tree tree(skeleton);
    const std::size_t n = skeleton.joints.size();
    std::vector<Eigen::Vector3d> rest;
    if (!positions || positions->size() != n) {
        rest.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
            const int parent = skeleton.joints[j].parent;
            rest[j] = skeleton.joints[j].offset + (parent >= 0 ? rest[std::size_t(parent)] : Eigen::Vector3d::Zero());
        }
    }
    const std::vector<Eigen::Vector3d>& where = rest.empty() ? *positions : rest;

    std::vector<io::JointNameInfo> names(n);
    for (std::size_t j = 0; j < n; ++j) names[j] = io::jointNameInfo(skeleton.joints[j].name);

    // Roots: the largest tree is the body; others are chains of their own.
    std::vector<int> roots;
    for (std::size_t j = 0; j < n; ++j)
        if (skeleton.joints[j].parent < 0 && !skeleton.joints[j].endSite) roots.push_back(int(j));
    const int root = *std::max_element(roots.begin(), roots.end(),
                                       [&](int a, int b) { return tree.size[std::size_t(a)] < tree.size[std::size_t(b)]; });

    std::vector<SkeletonChain> chains;
    SkeletonChain rootChain{"root", {root}};
    int pelvis = root;
    while (tree.children[std::size_t(pelvis)].size() == 1) {
        pelvis = tree.children[std::size_t(pelvis)].front();
        rootChain.joints.push_back(pelvis);
    }
    if (tree.children[std::size_t(pelvis)].empty()) {
        // One unbranched chain: the root alone and the rest as the spine.
        chains.push_back({"root", {root}});
        if (rootChain.joints.size() > 1) chains.push_back({"spine", std::vector<int>(rootChain.joints.begin() + 1, rootChain.joints.end())});
    } else {
        int head = -1;
        for (int j : tree.subtree(pelvis))
            if (j != pelvis && !names[std::size_t(j)].side && names[std::size_t(j)].term == "head") {
                head = j;
                break;
            }
        // The spine up from the pelvis; what branches off it are limbs.
        SkeletonChain spine{"spine", {}};
        std::vector<std::pair<int, LimbKind>> branches; // (first joint, kind by where it branches)
        int at = pelvis;
        for (int next = spineChild(skeleton, tree, at, head);; next = spineChild(skeleton, tree, at, head)) {
            if (at != head) // what the head carries belongs to the spine
                for (int c : tree.children[std::size_t(at)])
                    if (c != next) branches.emplace_back(c, at == pelvis ? LimbKind::Leg : LimbKind::Arm);
            if (next < 0) break;
            spine.joints.push_back(next);
            at = next;
        }
        if (at == head) {
            for (int j : tree.subtree(head))
                if (j != head) spine.joints.push_back(j);
            std::sort(spine.joints.begin(), spine.joints.end());
        }

        std::vector<Limb> limbs;
        for (const auto& [first, byPlace] : branches) {
            Limb limb;
            limb.joints = tree.subtree(first);
            int legVotes = 0, armVotes = 0, leftVotes = 0, rightVotes = 0;
            for (int j : limb.joints) {
                const auto& info = names[std::size_t(j)];
                legVotes += containsAny(info.term, kLegWords) ? 1 : 0;
                armVotes += containsAny(info.term, kArmWords) ? 1 : 0;
                if (info.side) (*info.side == BodySide::Left ? leftVotes : rightVotes) += 1;
            }
            limb.kind = legVotes > armVotes ? LimbKind::Leg : armVotes > legVotes ? LimbKind::Arm : byPlace;
            limb.side = leftVotes > rightVotes ? 1 : rightVotes > leftVotes ? -1 : 0;
            limbs.push_back(std::move(limb));
        }
        // Sides the names do not tell: left of the facing direction (the toes point forward).
        Eigen::Vector3d forward = Eigen::Vector3d::Zero();
        for (const Limb& limb : limbs) {
            if (limb.kind != LimbKind::Leg || limb.joints.size() < 2) continue;
            const int toe = limb.joints.back();
            const int foot = skeleton.joints[std::size_t(toe)].parent;
            Eigen::Vector3d d = where[std::size_t(toe)] - where[std::size_t(foot)];
            d.z() = 0.0;
            forward += d;
        }
        if (forward.norm() < 1e-9) forward = Eigen::Vector3d::UnitX();
        const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(forward.normalized());
        for (Limb& limb : limbs) {
            if (limb.side != 0) continue;
            const int attach = skeleton.joints[std::size_t(limb.joints.front())].parent;
            Eigen::Vector3d mean = Eigen::Vector3d::Zero();
            for (int j : limb.joints) mean += where[std::size_t(j)];
            mean /= double(limb.joints.size());
            const double lateral = (mean - where[std::size_t(attach)]).dot(left);
            if (std::abs(lateral) > 1e-6) limb.side = lateral > 0 ? 1 : -1;
        }

        chains.push_back(std::move(rootChain));
        if (!spine.joints.empty()) chains.push_back(std::move(spine));
        const auto rank = [](const Limb& limb) { return (limb.kind == LimbKind::Arm ? 0 : 3) + (limb.side > 0 ? 0 : limb.side < 0 ? 1 : 2); };
        std::stable_sort(limbs.begin(), limbs.end(), [&](const Limb& a, const Limb& b) { return rank(a) < rank(b); });
        std::map<std::string, int> seen;
        for (Limb& limb : limbs) {
            std::string name = std::string(limb.side > 0 ? "left_" : limb.side < 0 ? "right_" : "") + (limb.kind == LimbKind::Arm ? "arm" : "leg");
            const int count = ++seen[name];
            if (count > 1) name += "_" + std::to_string(count);
            chains.push_back({std::move(name), std::move(limb.joints)});
        }
    }
    int other = 1;
    for (int r : roots)
        if (r != root) chains.push_back({"root_" + std::to_string(++other), tree.subtree(r)});
    return chains;
}

Result<std::vector<SkeletonChain>> skeletonChains(const SkeletalMotion& motion)
{
    if (!motion.skeleton) return makeError(ErrorCode::InvalidArgument, "skeleton chains: the motion has no skeleton");
    if (motion.frameCount() == 0) return skeletonChains(*motion.skeleton);
    std::vector<Eigen::Vector3d> positions;
    for (const auto& pose : motion.worldPoses(0)) positions.push_back(pose.translation);
    return skeletonChains(*motion.skeleton, &positions);
}

} // namespace bunraku::analysis
