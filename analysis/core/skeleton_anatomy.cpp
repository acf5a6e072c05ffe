#include "analysis/core/skeleton_anatomy.h"

#include <cmath>
#include <cstdlib>

namespace bunraku::analysis {
namespace {

/// Children of every joint (End Sites included), built once: Skeleton::children scans all joints.
std::vector<std::vector<int>> childLists(const Skeleton& skeleton)
{
    std::vector<std::vector<int>> children(skeleton.joints.size());
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
        if (skeleton.joints[j].parent >= 0) children[std::size_t(skeleton.joints[j].parent)].push_back(int(j));
    return children;
}

/// Joints (End Sites excluded) in each subtree, the joint itself included.
std::vector<int> subtreeSizes(const Skeleton& skeleton)
{
    std::vector<int> size(skeleton.joints.size(), 0);
    for (std::size_t j = skeleton.joints.size(); j-- > 0;) {
        size[j] += skeleton.joints[j].endSite ? 0 : 1;
        if (skeleton.joints[j].parent >= 0) size[std::size_t(skeleton.joints[j].parent)] += size[j];
    }
    return size;
}

bool isAncestor(const Skeleton& skeleton, int ancestor, int joint)
{
    for (int j = joint; j >= 0; j = skeleton.joints[std::size_t(j)].parent)
        if (j == ancestor) return true;
    return false;
}

/// The child of `ancestor` on the path down to `joint` (`joint` itself when it is a child).
int childTowards(const Skeleton& skeleton, int ancestor, int joint)
{
    int j = joint;
    while (j >= 0 && skeleton.joints[std::size_t(j)].parent != ancestor) j = skeleton.joints[std::size_t(j)].parent;
    return j;
}

/// The descendant of `joint` (End Sites included) farthest from it, and the distance.
std::pair<int, double> farthestDescendant(const std::vector<std::vector<int>>& children, const std::vector<RigidTransform>& poses,
                                          int joint)
{
    std::pair<int, double> best{-1, 0.0};
    std::vector<int> stack = children[std::size_t(joint)];
    const Eigen::Vector3d origin = poses[std::size_t(joint)].translation;
    while (!stack.empty()) {
        const int j = stack.back();
        stack.pop_back();
        const double d = (poses[std::size_t(j)].translation - origin).norm();
        if (d > best.second) best = {j, d};
        for (int c : children[std::size_t(j)]) stack.push_back(c);
    }
    return best;
}

Eigen::Vector3d unitOr(const Eigen::Vector3d& v, const Eigen::Vector3d& fallback)
{
    const double n = v.norm();
    return n > 1e-9 ? Eigen::Vector3d(v / n) : fallback;
}

} // namespace

const char* bodySideName(BodySide side) { return side == BodySide::Left ? "left" : "right"; }

int commonAncestor(const Skeleton& skeleton, int a, int b)
{
    std::vector<char> onPath(skeleton.joints.size(), 0);
    for (int j = a; j >= 0; j = skeleton.joints[std::size_t(j)].parent) onPath[std::size_t(j)] = 1;
    for (int j = b; j >= 0; j = skeleton.joints[std::size_t(j)].parent)
        if (onPath[std::size_t(j)]) return j;
    return -1;
}

int pelvisJoint(const Skeleton& skeleton, int joint)
{
    std::vector<int> chain;
    for (int j = joint; j >= 0; j = skeleton.joints[std::size_t(j)].parent) chain.push_back(j);
    if (chain.empty()) return -1;
    std::vector<int> jointChildren(skeleton.joints.size(), 0);
    for (const auto& j : skeleton.joints)
        if (j.parent >= 0 && !j.endSite) ++jointChildren[std::size_t(j.parent)];
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
        if (jointChildren[std::size_t(*it)] >= 2) return *it;
    return chain.back();
}

Result<SkeletonLandmarks> findLandmarks(const SkeletalMotion& motion, const PartJoints& parts, Eigen::Index frame)
{
    if (!motion.skeleton) return makeError(ErrorCode::InvalidArgument, "landmarks of a motion without a skeleton");
    const Skeleton& skeleton = *motion.skeleton;
    const int slots = int(skeleton.joints.size());
    static constexpr const char* names[4] = {"head", "shoulder", "arm", "hand"};
    for (std::size_t p = 0; p < 4; ++p)
        if (parts[p] < 0 || parts[p] >= slots)
            return makeError(ErrorCode::NotFound, skeleton.name + ": the puppet part '" + names[p] + "' is bound to no joint");
    if (frame < 0 || frame >= motion.frameCount())
        return makeError(ErrorCode::InvalidArgument, skeleton.name + ": no frame " + std::to_string(frame) + " for the landmarks");
    const int head = parts[0], chest = parts[1], arm = parts[2], hand = parts[3];
    const auto poses = motion.worldPoses(frame);
    for (const auto& pose : poses)
        if (!pose.translation.allFinite() || !pose.rotation.coeffs().allFinite())
            return makeError(ErrorCode::Numerical, skeleton.name + ": the poses overflow (values too large?) at frame " + std::to_string(frame));
    const auto children = childLists(skeleton);
    const auto sizes = subtreeSizes(skeleton);
    const auto at = [&](int j) { return poses[std::size_t(j)].translation; };
    const auto parentOf = [&](int j) { return skeleton.joints[std::size_t(j)].parent; };

    SkeletonLandmarks l;
    l.head = at(head);
    l.neck = parentOf(head) >= 0 ? at(parentOf(head)) : at(head);
    l.chest = at(chest);
    l.elbow = at(arm);
    l.wrist = at(hand);

    int hips = pelvisJoint(skeleton, chest);
    if (hips == chest || !isAncestor(skeleton, hips, chest)) {
        // No legs branch below the chest: the chain's root stands for the hips.
        hips = chest;
        while (parentOf(hips) >= 0) hips = parentOf(hips);
    }
    l.hips = at(hips);
    if (hips == chest) {
        l.hips = l.chest - (l.neck - l.chest);
        l.estimated.push_back("hips");
    }

    // The neck's base: the chest's child on the way to the head, or the chest itself when the
    // head hangs from it (3ds Max Biped's arms branch from its Neck).
    if (isAncestor(skeleton, chest, head) && head != chest)
        l.neckBase = parentOf(head) == chest ? l.chest : at(childTowards(skeleton, chest, head));
    else
        l.neckBase = l.neck;

    // The top of the head: a joint or End Site beyond the head, or an estimate along the neck.
    double chainLength = 0.0;
    for (int j = head; j >= 0 && j != hips; j = parentOf(j))
        if (parentOf(j) >= 0) chainLength += (at(j) - at(parentOf(j))).norm();
    const double headHeight = 0.45 * chainLength;
    const auto [top, topDistance] = farthestDescendant(children, poses, head);
    if (top >= 0 && topDistance >= 0.5 * headHeight) {
        l.headTop = at(top);
    } else {
        // Upright as the trunk: the neck leans forward, a head held level does not.
        l.headTop = l.head + unitOr(l.neckBase - l.hips, unitOr(l.head - l.neck, Eigen::Vector3d::UnitZ())) * headHeight;
        l.estimated.push_back("head top");
    }

    // The shoulders (upper-arm joints): the arm joint's parent, and the joint as deep in the
    // other arm chain branching from the chest.
    const int upper = parentOf(arm) >= 0 && parentOf(arm) != chest ? parentOf(arm) : arm;
    l.boundShoulder = at(upper);
    if (isAncestor(skeleton, chest, upper) && upper != chest) {
        const int branch = childTowards(skeleton, chest, upper);
        int depth = 0;
        for (int j = upper; j != branch; j = parentOf(j)) ++depth;
        const int towardsHead = isAncestor(skeleton, chest, head) && head != chest ? childTowards(skeleton, chest, head) : -1;
        int other = -1;
        for (int c : children[std::size_t(chest)]) {
            if (c == branch || c == towardsHead || skeleton.joints[std::size_t(c)].endSite) continue;
            if (other < 0 || std::abs(sizes[std::size_t(c)] - sizes[std::size_t(branch)]) <
                                 std::abs(sizes[std::size_t(other)] - sizes[std::size_t(branch)]))
                other = c;
        }
        for (int step = 0; other >= 0 && step < depth; ++step) {
            int next = -1;
            for (int c : children[std::size_t(other)])
                if (!skeleton.joints[std::size_t(c)].endSite && (next < 0 || sizes[std::size_t(c)] > sizes[std::size_t(next)])) next = c;
            if (next < 0) break;
            other = next;
        }
        if (other >= 0) {
            l.otherShoulder = at(other);
            l.otherShoulderFound = true;
        }
    }

    // The finger tips: the farthest joint or End Site beyond the wrist, or an estimate.
    const double forearm = (l.wrist - l.elbow).norm();
    const auto [tip, tipDistance] = farthestDescendant(children, poses, hand);
    if (tip >= 0 && tipDistance >= 0.3 * forearm && tipDistance > 0.0) {
        l.fingerTip = at(tip);
    } else {
        l.fingerTip = l.wrist + unitOr(l.wrist - l.elbow, Eigen::Vector3d::UnitX()) * (0.75 * forearm);
        l.estimated.push_back("finger tip");
    }
    return l;
}

} // namespace bunraku::analysis
