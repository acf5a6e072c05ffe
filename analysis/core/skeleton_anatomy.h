#pragma once
/// Anatomical landmarks of a performer's skeleton around the joints the puppet's four parts are
/// bound to: where the neck, the top of the head, the hips, the shoulders, the wrist and the
/// finger tips are at one frame. The calibration of the part frames
/// (skeleton_calibration.h) and the fit of the puppet's body to the performer
/// (analysis/body/body_fit.h) both read them. Positions in workbench axes, cm.
///
/// Skeletons rarely carry every landmark (the Bandai files end the head and the hands in End
/// Sites of length 0): a missing one is estimated from the others, and `estimated` says which.

#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace bunraku::analysis {

/// Which of the performer's limbs the puppet's arm and hand parts follow.
enum class BodySide { Right, Left };

/// "right" or "left".
const char* bodySideName(BodySide side);

/// Joint indices of the puppet's parts in Skeleton::joints, in kPuppetParts order
/// (head, shoulder, arm, hand).
using PartJoints = std::array<int, 4>;

struct SkeletonLandmarks {
    Eigen::Vector3d head = Eigen::Vector3d::Zero();     ///< the head part's joint
    Eigen::Vector3d neck = Eigen::Vector3d::Zero();     ///< the head joint's parent (base of the skull or neck)
    Eigen::Vector3d headTop = Eigen::Vector3d::Zero();  ///< the top of the head
    Eigen::Vector3d chest = Eigen::Vector3d::Zero();    ///< the shoulder part's joint
    /// The base of the neck: the first joint from the chest towards the head, or the chest
    /// when the head hangs from it.
    Eigen::Vector3d neckBase = Eigen::Vector3d::Zero();
    Eigen::Vector3d hips = Eigen::Vector3d::Zero();     ///< the pelvis (first joint where the legs branch)
    /// The upper-arm (shoulder) joints: the arm joint's parent on the bound side and the joint
    /// at the same depth of the other arm chain; `otherShoulderFound` false when there is none.
    Eigen::Vector3d boundShoulder = Eigen::Vector3d::Zero();
    Eigen::Vector3d otherShoulder = Eigen::Vector3d::Zero();
    bool otherShoulderFound = false;
    Eigen::Vector3d elbow = Eigen::Vector3d::Zero();     ///< the arm part's joint
    Eigen::Vector3d wrist = Eigen::Vector3d::Zero();     ///< the hand part's joint
    Eigen::Vector3d fingerTip = Eigen::Vector3d::Zero(); ///< the end of the hand
    /// Landmarks estimated rather than read from a joint: "head top", "finger tip", "hips".
    std::vector<std::string> estimated;
};

/// The landmarks at `frame` of the skeleton posed by `motion`, for the parts bound to `parts`.
/// Estimates (documented in docs/FORMATS.md, "Calibration"): a head top without a joint or End
/// Site of its own lies 0.45 x the hips-to-head chain length above the head joint, along the
/// trunk (hips -> base of the neck); a finger tip, 0.75 x the forearm beyond the wrist, along
/// the forearm. Errors: a part
/// without a joint, an arm joint without a parent.
Result<SkeletonLandmarks> findLandmarks(const SkeletalMotion& motion, const PartJoints& parts, Eigen::Index frame);

/// The joint where the legs (or any two chains) branch below `joint`'s chain: the first joint
/// from the root of `joint`'s chain with two or more children that are joints, or the root.
int pelvisJoint(const Skeleton& skeleton, int joint);

/// Lowest common ancestor of two joints, -1 when they are in different trees.
int commonAncestor(const Skeleton& skeleton, int a, int b);

} // namespace bunraku::analysis
