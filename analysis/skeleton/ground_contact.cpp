#include "analysis/skeleton/ground_contact.h"

#include "analysis/core/skeleton_anatomy.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace bunraku::analysis {
namespace {

std::vector<int> rootJoints(const Skeleton& skeleton)
{
    std::vector<int> roots;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
        if (skeleton.joints[j].parent < 0) roots.push_back(int(j));
    return roots;
}

double lowestOf(const Skeleton& skeleton, const std::vector<RigidTransform>& poses)
{
    double z = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
        if (skeleton.joints[j].parent >= 0) z = std::min(z, poses[j].translation.z());
    return z;
}

/// The chain from `start` down to the lowest joint of its subtree (at `poses`).
std::vector<int> chainToLowest(const Skeleton& skeleton, const std::vector<std::vector<int>>& children,
                               const std::vector<RigidTransform>& poses, int start)
{
    // The lowest descendant, then the path back up to `start`.
    int lowest = start;
    std::vector<int> stack{start};
    while (!stack.empty()) {
        const int j = stack.back();
        stack.pop_back();
        if (poses[std::size_t(j)].translation.z() < poses[std::size_t(lowest)].translation.z()) lowest = j;
        for (int c : children[std::size_t(j)]) stack.push_back(c);
    }
    std::vector<int> chain;
    for (int j = lowest; j >= 0; j = skeleton.joints[std::size_t(j)].parent) {
        chain.push_back(j);
        if (j == start) break;
    }
    std::reverse(chain.begin(), chain.end());
    return chain;
}

/// Per leg, the knee's hinge axis in the hip's frame at the frame where the knee bends most
/// (nullopt when it never bends): the direction a straight knee bends in.
std::vector<std::optional<Eigen::Vector3d>> kneeAxes(const SkeletalMotion& motion, const std::vector<LegJoints>& legs)
{
    std::vector<std::optional<Eigen::Vector3d>> axes(legs.size());
    std::vector<double> best(legs.size(), 0.0);
    for (Eigen::Index f = 0; f < motion.frameCount(); ++f) {
        const auto poses = motion.worldPoses(f);
        for (std::size_t l = 0; l < legs.size(); ++l) {
            const Eigen::Vector3d u = poses[std::size_t(legs[l].knee)].translation - poses[std::size_t(legs[l].hip)].translation;
            const Eigen::Vector3d v = poses[std::size_t(legs[l].ankle)].translation - poses[std::size_t(legs[l].knee)].translation;
            const double lengths = u.norm() * v.norm();
            if (lengths <= 0.0) continue;
            const Eigen::Vector3d n = u.cross(v);
            const double bend = n.norm() / lengths;
            if (bend > best[l] && bend > 1e-3) {
                best[l] = bend;
                axes[l] = poses[std::size_t(legs[l].hip)].rotation.conjugate() * n.normalized();
            }
        }
    }
    return axes;
}

/// Bends one leg at `frame` so that its ankle moves by `lift` (world z), the foot keeping its
/// orientation (two-bone inverse kinematics: the knee's bend from the law of cosines, then the
/// whole leg turned about the hip onto the target). A target the stretched leg cannot reach is
/// moved in under the hip at the same height; one below the stretched leg is approached as close
/// as the leg goes.
void bendLeg(SkeletalMotion& motion, Eigen::Index frame, const std::vector<RigidTransform>& poses, const LegJoints& leg,
             const std::optional<Eigen::Vector3d>& hipAxis, double lift)
{
    const Skeleton& skeleton = *motion.skeleton;
    const RigidTransform& hip = poses[std::size_t(leg.hip)];
    const RigidTransform& knee = poses[std::size_t(leg.knee)];
    const RigidTransform& ankle = poses[std::size_t(leg.ankle)];
    const Eigen::Vector3d u = knee.translation - hip.translation;
    const Eigen::Vector3d v = ankle.translation - knee.translation;
    const double l1 = u.norm(), l2 = v.norm();
    if (l1 < 1e-6 || l2 < 1e-6) return;
    Eigen::Vector3d toTarget = ankle.translation + Eigen::Vector3d(0.0, 0.0, lift) - hip.translation;
    // Out of reach (a leg spread wider than it can stretch): the foot comes in under the hip, at
    // the height it must reach, as far as the stretched leg needs.
    const double longest = l1 + l2 - 1e-9;
    if (toTarget.norm() > longest && std::abs(toTarget.z()) < longest) {
        const Eigen::Vector2d across = toTarget.head<2>();
        const double allowed = std::sqrt(longest * longest - toTarget.z() * toTarget.z());
        if (across.norm() > allowed) toTarget.head<2>() = across * (allowed / across.norm());
    }
    if (toTarget.norm() < 1e-9) return;
    const double reach = std::clamp(toTarget.norm(), std::abs(l1 - l2) + 1e-9, longest);
    const double bend = std::acos(std::clamp(u.dot(v) / (l1 * l2), -1.0, 1.0));
    const double wanted = std::acos(std::clamp((reach * reach - l1 * l1 - l2 * l2) / (2.0 * l1 * l2), -1.0, 1.0));
    Eigen::Vector3d axis = u.cross(v);
    if (axis.norm() < 1e-6 * l1 * l2) {
        if (!hipAxis) return; // a knee that never bends: no direction to bend it in
        axis = hip.rotation * *hipAxis;
    }
    axis.normalize();
    const Eigen::Quaterniond atKnee(Eigen::AngleAxisd(wanted - bend, axis));
    const Eigen::Vector3d ankleAfterKnee = u + atKnee * v;
    const Eigen::Quaterniond atHip = Eigen::Quaterniond::FromTwoVectors(ankleAfterKnee, toTarget);

    const int hipParent = skeleton.joints[std::size_t(leg.hip)].parent;
    const Eigen::Quaterniond parentWorld = hipParent >= 0 ? poses[std::size_t(hipParent)].rotation : Eigen::Quaterniond::Identity();
    const Eigen::Quaterniond hipWorld = (atHip * hip.rotation).normalized();
    const Eigen::Quaterniond kneeWorld = (atHip * atKnee * knee.rotation).normalized();
    motion.rotation(frame, leg.hip) = (parentWorld.conjugate() * hipWorld).normalized();
    motion.rotation(frame, leg.knee) = (hipWorld.conjugate() * kneeWorld).normalized();
    if (!skeleton.joints[std::size_t(leg.ankle)].endSite)
        motion.rotation(frame, leg.ankle) = (kneeWorld.conjugate() * ankle.rotation).normalized();
}

std::vector<RigidTransform> verticalMoves(const Eigen::VectorXd& dz)
{
    std::vector<RigidTransform> moves(std::size_t(dz.size()));
    for (Eigen::Index f = 0; f < dz.size(); ++f) moves[std::size_t(f)].translation.z() = dz(f);
    return moves;
}

} // namespace

LegLayout findLegs(const SkeletalMotion& motion)
{
    LegLayout layout;
    if (!motion.skeleton || motion.frameCount() == 0) return layout;
    const Skeleton& skeleton = *motion.skeleton;
    const auto poses = motion.worldPoses(0);
    const std::size_t slots = skeleton.joints.size();
    std::vector<std::vector<int>> children(slots);
    for (std::size_t j = 0; j < slots; ++j)
        if (skeleton.joints[j].parent >= 0) children[std::size_t(skeleton.joints[j].parent)].push_back(int(j));
    // The pelvis: where the path to the lowest point first branches.
    int lowest = -1;
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < slots; ++j) {
        top = std::max(top, poses[j].translation.z());
        if (skeleton.joints[j].parent >= 0 && (lowest < 0 || poses[j].translation.z() < poses[std::size_t(lowest)].translation.z()))
            lowest = int(j);
    }
    if (lowest < 0) return layout;
    const int pelvis = pelvisJoint(skeleton, lowest);
    if (pelvis < 0 || children[std::size_t(pelvis)].size() < 2) return layout;
    layout.pelvis = pelvis;
    const double floor = poses[std::size_t(lowest)].translation.z();
    const double tolerance = 0.1 * (top - floor);
    for (int child : children[std::size_t(pelvis)]) {
        const std::vector<int> chain = chainToLowest(skeleton, children, poses, child);
        if (poses[std::size_t(chain.back())].translation.z() > floor + tolerance) continue;
        // The thigh and the shin: the longest pair of consecutive bones, hip and knee joints.
        double longest = 0.0;
        LegJoints leg;
        for (std::size_t k = 0; k + 2 < chain.size(); ++k) {
            const int a = chain[k], b = chain[k + 1], c = chain[k + 2];
            if (skeleton.joints[std::size_t(a)].endSite || skeleton.joints[std::size_t(b)].endSite) continue;
            const double length = (poses[std::size_t(b)].translation - poses[std::size_t(a)].translation).norm() +
                                  (poses[std::size_t(c)].translation - poses[std::size_t(b)].translation).norm();
            if (length > longest) {
                longest = length;
                leg = LegJoints{a, b, c};
            }
        }
        if (leg.hip >= 0) layout.legs.push_back(leg);
    }
    return layout;
}

Eigen::VectorXd lowestPoints(const SkeletalMotion& motion)
{
    Eigen::VectorXd low(motion.frameCount());
    for (Eigen::Index f = 0; f < motion.frameCount(); ++f) low(f) = lowestOf(*motion.skeleton, motion.worldPoses(f));
    return low;
}

Eigen::VectorXd jointHeights(const SkeletalMotion& motion, int joint)
{
    Eigen::VectorXd z(motion.frameCount());
    for (Eigen::Index f = 0; f < motion.frameCount(); ++f) z(f) = motion.worldPoses(f)[std::size_t(joint)].translation.z();
    return z;
}

std::shared_ptr<const SkeletalMotion> groundBody(const SkeletalMotion& motion, const Eigen::VectorXd& pelvisHeight,
                                                 const Eigen::VectorXd& lowestPoint)
{
    if (!motion.skeleton) return nullptr;
    const Eigen::Index frames = motion.frameCount();
    if (pelvisHeight.size() != frames || lowestPoint.size() != frames) return nullptr;
    const Skeleton& skeleton = *motion.skeleton;
    const std::vector<int> roots = rootJoints(skeleton);
    const LegLayout layout = findLegs(motion);
    if (layout.pelvis < 0 || layout.legs.empty()) {
        const Eigen::VectorXd shift = lowestPoint - lowestPoints(motion);
        return moveSkeletalRoots(motion, verticalMoves(shift), roots);
    }
    // 1. The pelvis at its height.
    const Eigen::VectorXd raise = pelvisHeight - jointHeights(motion, layout.pelvis);
    auto held = moveSkeletalRoots(motion, verticalMoves(raise), roots);
    auto bent = std::make_shared<SkeletalMotion>(*held);
    // 2. The legs bent so that the feet reach the lowest point's height.
    const auto axes = kneeAxes(*held, layout.legs);
    Eigen::VectorXd rest(frames);
    for (Eigen::Index f = 0; f < frames; ++f) {
        // Every foot moves by the same height, so a lifted foot stays lifted; where the foot that
        // was lowest cannot reach (its leg stretched), a second pass lowers the others until one
        // of them is on the floor.
        auto poses = held->worldPoses(f);
        for (int pass = 0; pass < 2; ++pass) {
            const double lift = lowestPoint(f) - lowestOf(skeleton, poses);
            if (std::abs(lift) <= 1e-12) break;
            for (std::size_t l = 0; l < layout.legs.size(); ++l) bendLeg(*bent, f, poses, layout.legs[l], axes[l], lift);
            poses = bent->worldPoses(f);
        }
        // 3. What the legs could not reach, or a lowest point off the legs: the roots move.
        rest(f) = lowestPoint(f) - lowestOf(skeleton, poses);
    }
    if ((rest.array().abs() > 1e-9).any()) return moveSkeletalRoots(*bent, verticalMoves(rest), roots);
    return bent;
}

} // namespace bunraku::analysis
