#pragma once
/// A performer's full skeleton and its motion, kept beside a take's analysis channels so that
/// every derived take (normalised, averaged, weighted, designed) can still be put back on the
/// user's character. Everything here is in the workbench convention (right-handed, z up, x
/// towards the partner, cm); `SourceFrame` remembers how the source file's axes and units map to
/// it, and each joint remembers its source channels, so a writer can give the file back.
///
/// Frames: `parent_T_joint` is a joint's local pose (its translation is the OFFSET, or the
/// per-frame position channels; its rotation the rotation channels), `world_T_joint` the product
/// down the chain. A puppet part bound to a joint has the pose world_T_joint * joint_T_part
/// (`PartBinding`): the part's frame is the puppet's convention (docs/FORMATS.md), the joint's
/// is the file's bone frame.

#include "analysis/core/pose.h"
#include "analysis/core/result.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

struct SkeletonMesh; // analysis/core/skeleton_mesh.h

/// One channel of a joint as the source file lists it (BVH's names), in the source's axes.
enum class JointChannel { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

/// How a joint's position channels combine with its OFFSET (BVH files differ).
enum class PositionChannelMode {
    ReplaceOffset, ///< the channels are the whole local translation (Bandai and most exporters)
    AddToOffset,   ///< local translation = OFFSET + channels
};

struct SkeletonJoint {
    std::string name;   ///< as in the file; End Sites are named "<parent>_End"
    int parent = -1;    ///< index into Skeleton::joints (parents precede children), -1 for a root
    /// The file's OFFSET in the workbench's axes, cm, in the parent's frame.
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    /// The source's channels in file order, 0 to 6 (End Sites have none). Rotation channels are
    /// applied in this order (intrinsic: R = R1 R2 R3) in the source's axes.
    std::vector<JointChannel> channels;
    bool endSite = false;
};

/// How the source file's axes and units relate to the workbench's:
/// p_world = world_R_source * (cmPerUnit * p_source), R_world = world_R_source R_source world_R_source^-1.
struct SourceFrame {
    Eigen::Quaterniond world_R_source = Eigen::Quaterniond::Identity();
    double cmPerUnit = 1.0;
    /// "y" or "z": the source's up axis, for reports and writers.
    std::string upAxis = "y";
};

/// A puppet part (head, shoulder, arm, hand) bound to a joint of the skeleton.
struct PartBinding {
    std::string part;  ///< "head", "shoulder", "arm", "hand"
    int joint = -1;    ///< index into Skeleton::joints
    /// The part's frame in the joint's frame (calibration): world_T_part = world_T_joint * joint_T_part.
    RigidTransform joint_T_part;
};

struct Skeleton {
    std::string name; ///< usually the source file's stem
    std::vector<SkeletonJoint> joints;
    SourceFrame source;
    PositionChannelMode positionMode = PositionChannelMode::ReplaceOffset;
    /// The puppet parts mapped onto this skeleton (empty when no map was applied).
    std::vector<PartBinding> parts;
    /// The skinned mesh the source file carries for this skeleton (skeleton_mesh.h), null when
    /// it has none. Kept by copies of the skeleton; a user checks meshFitsSkeleton.
    std::shared_ptr<const SkeletonMesh> mesh;

    /// Index of the joint (or End Site) with this exact name, -1 when absent.
    int find(std::string_view jointName) const;
    /// Joints that are not End Sites.
    int jointCount() const;
    /// Direct children of `joint` (End Sites included), in file order.
    std::vector<int> children(int joint) const;
    /// The binding of a puppet part, nullptr when the part is not bound.
    const PartBinding* binding(std::string_view part) const;
};

/// Checks parents precede children, names are non-empty and unique, End Sites have no children
/// or channels, offsets are finite, bindings name existing joints.
Status validateSkeleton(const Skeleton& skeleton);

/// The skeleton's motion: per frame the local pose (parent_T_joint) of every joint, workbench
/// axes and cm. Rotations are stored as unit quaternions (never as Euler numbers). Translations
/// that never change over the take (every bone of a rigid skeleton) are stored once.
struct SkeletalMotion {
    std::shared_ptr<const Skeleton> skeleton;
    /// frames x joints (all of Skeleton::joints, End Sites identity): parent_R_joint of joint j
    /// at frame f is rotations[f * joints + j].
    std::vector<Eigen::Quaterniond> rotations;
    /// Per joint: its local translation when it does not change over the take (cm); for a joint
    /// in movingJoints, its translation at the first frame.
    std::vector<Eigen::Vector3d> staticTranslations;
    /// Joints whose local translation changes from frame to frame (the root, usually).
    std::vector<int> movingJoints;
    /// frames x (3 * movingJoints.size()): the local translation of movingJoints[k] at frame f is
    /// movingTranslations.block<1, 3>(f, 3 * k) (cm).
    Eigen::MatrixXd movingTranslations;

    Eigen::Index frameCount() const;
    int jointSlots() const { return skeleton ? int(skeleton->joints.size()) : 0; }
    /// parent_R_joint.
    const Eigen::Quaterniond& rotation(Eigen::Index frame, int joint) const
    {
        return rotations[std::size_t(frame) * std::size_t(jointSlots()) + std::size_t(joint)];
    }
    Eigen::Quaterniond& rotation(Eigen::Index frame, int joint)
    {
        return rotations[std::size_t(frame) * std::size_t(jointSlots()) + std::size_t(joint)];
    }
    /// The local translation of a joint at a frame (cm).
    Eigen::Vector3d translation(Eigen::Index frame, int joint) const;
    /// parent_T_joint.
    RigidTransform localPose(Eigen::Index frame, int joint) const;
    /// world_T_joint of every joint (End Sites included) at a frame.
    std::vector<RigidTransform> worldPoses(Eigen::Index frame) const;
    /// world_T_part of a bound puppet part at a frame; nullopt when the part is not bound.
    std::optional<RigidTransform> partPose(Eigen::Index frame, std::string_view part) const;
};

/// An empty motion of `frames` frames on `skeleton`: identity rotations, every translation
/// static at the joint's offset.
SkeletalMotion makeRestMotion(std::shared_ptr<const Skeleton> skeleton, Eigen::Index frames);

/// Checks the skeleton, that rotations hold frames x joints unit quaternions, that every value is
/// finite and that movingJoints / staticTranslations / movingTranslations agree in size.
Status validateSkeletalMotion(const SkeletalMotion& motion);

} // namespace bunraku::analysis
