#pragma once
/// Calibration of the puppet's part frames on a performer's skeleton: the constant
/// joint_T_part of each PartBinding, so that world_T_part = world_T_joint * joint_T_part is a
/// frame in the puppet's convention (resources/puppet/bunraku_puppet.json): head and shoulder
/// x forward, y to the performer's left, z up; arm and hand x along the bone from the shoulder
/// towards the fingers. A file's bone frames (Bandai's x along every bone, so that its all-zero
/// pose lies on its side) never leak into the parts.
///
/// The frames are anatomical, built from bone directions at a reference frame of the take (the
/// first by default, where performers stand in their neutral pose; docs/FORMATS.md,
/// "Calibration"):
///   shoulder  z = hips -> base of the neck, y = right shoulder -> left shoulder (made
///             orthogonal to z), x = y x z;
///   head      the shoulder frame turned by the smallest rotation taking its z onto the neck
///             -> head direction (towards the head top when the skeleton has one);
///   arm       the shoulder frame turned by the smallest rotation taking its x onto the
///             elbow -> wrist direction (the forearm);
///   hand      the arm frame turned by the smallest rotation taking its x onto the
///             wrist -> finger tip direction.
/// Each part's origin is its joint (joint_T_part has no translation).

#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/skeleton_anatomy.h"

#include <vector>

namespace bunraku::analysis {

struct CalibrationOptions {
    Eigen::Index referenceFrame = 0; ///< the frame whose pose defines the part frames
    BodySide side = BodySide::Right; ///< the side of the limbs bound to arm and hand
};

/// The part frames at the reference frame (world_T_part, in kPuppetParts order), from the
/// landmarks. Errors: degenerate landmarks (a bone of length 0, shoulders on the spine line).
Result<std::array<RigidTransform, 4>> anatomicalPartFrames(const SkeletonLandmarks& landmarks, BodySide side,
                                                           const std::string& skeletonName = {});

/// The four bindings (head, shoulder, arm, hand) of `parts` with their calibration
/// joint_T_part = world_T_joint^-1 * world_T_part at the reference frame.
Result<std::vector<PartBinding>> calibratePartBindings(const SkeletalMotion& motion, const PartJoints& parts,
                                                       const CalibrationOptions& options = {});

/// A copy of `motion` on a copy of its skeleton whose part bindings are `bindings`.
SkeletalMotion withPartBindings(const SkeletalMotion& motion, std::vector<PartBinding> bindings);

} // namespace bunraku::analysis
