#include "analysis/core/skeleton.h"

#include <cmath>
#include <unordered_set>

namespace bunraku::analysis {

int Skeleton::find(std::string_view jointName) const
{
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints[j].name == jointName) return int(j);
    return -1;
}

int Skeleton::jointCount() const
{
    int count = 0;
    for (const auto& joint : joints) count += joint.endSite ? 0 : 1;
    return count;
}

std::vector<int> Skeleton::children(int joint) const
{
    std::vector<int> result;
    for (std::size_t j = 0; j < joints.size(); ++j)
        if (joints[j].parent == joint) result.push_back(int(j));
    return result;
}

const PartBinding* Skeleton::binding(std::string_view part) const
{
    for (const auto& b : parts)
        if (b.part == part) return &b;
    return nullptr;
}

Status validateSkeleton(const Skeleton& skeleton)
{
    const std::string name = skeleton.name.empty() ? std::string("skeleton") : skeleton.name;
    if (skeleton.joints.empty()) return makeError(ErrorCode::InvalidArgument, name + ": a skeleton needs at least one joint");
    std::unordered_set<std::string_view> seen;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        const SkeletonJoint& joint = skeleton.joints[j];
        const std::string where = name + ": joint " + std::to_string(j);
        if (joint.name.empty()) return makeError(ErrorCode::InvalidArgument, where + " has no name");
        if (!seen.insert(joint.name).second)
            return makeError(ErrorCode::InvalidArgument, where + ": the name '" + joint.name + "' is used twice");
        if (joint.parent >= int(j) || joint.parent < -1)
            return makeError(ErrorCode::InvalidArgument, where + " ('" + joint.name + "'): its parent must precede it");
        if (joint.parent >= 0 && skeleton.joints[std::size_t(joint.parent)].endSite)
            return makeError(ErrorCode::InvalidArgument, where + " ('" + joint.name + "'): an End Site cannot have children");
        if (joint.endSite && !joint.channels.empty())
            return makeError(ErrorCode::InvalidArgument, where + " ('" + joint.name + "'): an End Site has no channels");
        if (joint.channels.size() > 6)
            return makeError(ErrorCode::InvalidArgument, where + " ('" + joint.name + "'): more than 6 channels");
        if (!joint.offset.allFinite())
            return makeError(ErrorCode::InvalidArgument, where + " ('" + joint.name + "'): the offset is not finite");
    }
    if (!(skeleton.source.cmPerUnit > 0.0) || !std::isfinite(skeleton.source.cmPerUnit))
        return makeError(ErrorCode::InvalidArgument, name + ": the source unit scale must be a positive number");
    for (const auto& b : skeleton.parts) {
        if (b.joint < 0 || b.joint >= int(skeleton.joints.size()))
            return makeError(ErrorCode::InvalidArgument, name + ": the part '" + b.part + "' is bound to no joint of the skeleton");
        if (!b.joint_T_part.translation.allFinite() || !b.joint_T_part.rotation.coeffs().allFinite())
            return makeError(ErrorCode::InvalidArgument, name + ": the calibration of the part '" + b.part + "' is not finite");
    }
    return okStatus();
}

Eigen::Index SkeletalMotion::frameCount() const
{
    const int slots = jointSlots();
    return slots > 0 ? Eigen::Index(rotations.size() / std::size_t(slots)) : 0;
}

Eigen::Vector3d SkeletalMotion::translation(Eigen::Index frame, int joint) const
{
    for (std::size_t k = 0; k < movingJoints.size(); ++k)
        if (movingJoints[k] == joint) return movingTranslations.block<1, 3>(frame, Eigen::Index(3 * k)).transpose();
    return staticTranslations[std::size_t(joint)];
}

RigidTransform SkeletalMotion::localPose(Eigen::Index frame, int joint) const
{
    return RigidTransform{rotation(frame, joint), translation(frame, joint)};
}

std::vector<RigidTransform> SkeletalMotion::worldPoses(Eigen::Index frame) const
{
    const int slots = jointSlots();
    std::vector<RigidTransform> poses(static_cast<std::size_t>(slots));
    for (int j = 0; j < slots; ++j) poses[std::size_t(j)] = RigidTransform{rotation(frame, j), staticTranslations[std::size_t(j)]};
    for (std::size_t k = 0; k < movingJoints.size(); ++k)
        poses[std::size_t(movingJoints[k])].translation = movingTranslations.block<1, 3>(frame, Eigen::Index(3 * k)).transpose();
    for (int j = 0; j < slots; ++j) {
        const int parent = skeleton->joints[std::size_t(j)].parent;
        if (parent >= 0) poses[std::size_t(j)] = poses[std::size_t(parent)] * poses[std::size_t(j)];
    }
    return poses;
}

std::optional<RigidTransform> SkeletalMotion::partPose(Eigen::Index frame, std::string_view part) const
{
    if (!skeleton) return std::nullopt;
    const PartBinding* b = skeleton->binding(part);
    if (!b) return std::nullopt;
    // Only the chain from the root to the bound joint is needed.
    RigidTransform world_T_joint;
    std::vector<int> chain;
    for (int j = b->joint; j >= 0; j = skeleton->joints[std::size_t(j)].parent) chain.push_back(j);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) world_T_joint = world_T_joint * localPose(frame, *it);
    return world_T_joint * b->joint_T_part;
}

SkeletalMotion makeRestMotion(std::shared_ptr<const Skeleton> skeleton, Eigen::Index frames)
{
    SkeletalMotion motion;
    motion.skeleton = std::move(skeleton);
    const std::size_t slots = motion.skeleton ? motion.skeleton->joints.size() : 0;
    motion.rotations.assign(std::size_t(frames) * slots, Eigen::Quaterniond::Identity());
    motion.staticTranslations.resize(slots);
    for (std::size_t j = 0; j < slots; ++j) motion.staticTranslations[j] = motion.skeleton->joints[j].offset;
    motion.movingTranslations.resize(frames, 0);
    return motion;
}

Status validateSkeletalMotion(const SkeletalMotion& motion)
{
    if (!motion.skeleton) return makeError(ErrorCode::InvalidArgument, "skeletal motion without a skeleton");
    if (auto ok = validateSkeleton(*motion.skeleton); !ok) return ok;
    const std::string name = motion.skeleton->name.empty() ? std::string("skeleton") : motion.skeleton->name;
    const std::size_t slots = motion.skeleton->joints.size();
    if (motion.rotations.size() % slots != 0)
        return makeError(ErrorCode::InvalidArgument, name + ": the rotations are not frames x joints");
    const Eigen::Index frames = motion.frameCount();
    if (motion.staticTranslations.size() != slots)
        return makeError(ErrorCode::InvalidArgument, name + ": one static translation per joint expected");
    if (motion.movingTranslations.rows() != frames || motion.movingTranslations.cols() != Eigen::Index(3 * motion.movingJoints.size()))
        return makeError(ErrorCode::InvalidArgument, name + ": the moving translations are not frames x (3 x moving joints)");
    for (int j : motion.movingJoints)
        if (j < 0 || j >= int(slots)) return makeError(ErrorCode::InvalidArgument, name + ": a moving joint index is out of range");
    for (const auto& t : motion.staticTranslations)
        if (!t.allFinite()) return makeError(ErrorCode::InvalidArgument, name + ": a translation is not finite");
    if (!motion.movingTranslations.allFinite()) return makeError(ErrorCode::InvalidArgument, name + ": a translation is not finite");
    for (std::size_t i = 0; i < motion.rotations.size(); ++i) {
        const auto& q = motion.rotations[i];
        if (!q.coeffs().allFinite() || std::fabs(q.squaredNorm() - 1.0) > 1e-6)
            return makeError(ErrorCode::InvalidArgument, name + ": frame " + std::to_string(i / slots) + ", joint '" +
                                                             motion.skeleton->joints[i % slots].name + "': not a unit rotation");
    }
    return okStatus();
}

} // namespace bunraku::analysis
