#pragma once
/// The chains of a performer's skeleton, for the `chains` coupling (coupling.h): the thesis's
/// method 1 couples the arm with the hand because they move as one limb (3.6); on a whole
/// skeleton the limbs are the chains below, found from the topology and named with the
/// automatic part map's name rules (analysis/io/bvh_joint_map.h, `jointNameInfo`):
///
/// - `root`: the root joint down to the pelvis (the first joint where chains branch), e.g.
///   Bandai's joint_Root + Hips, 3ds Max's Bip01 + Pelvis + Spine;
/// - `spine`: from the pelvis's spine child up to the head, with everything the head carries
///   (eyes, jaw, head top);
/// - `left_arm`, `right_arm`: each chain branching off the spine, from the collar to the hand
///   with its fingers;
/// - `left_leg`, `right_leg`: each chain branching off the pelvis, from the hip to the toe.
///
/// Which child continues the spine: the one holding the joint named "head" (no side mark);
/// without one, of three or more children the largest apart from the most similar pair (the
/// limbs), of two the larger (two alike: both are limbs and the spine ends). A limb is a leg
/// or an arm by its joints' names (thigh, knee, foot, ... / collar, elbow, hand, ...), else by
/// where it branches (the pelvis: a leg; the spine: an arm). Its side by its joints' side
/// marks (Left, _L, r...), else by where it lies at the first frame: left of the facing
/// direction (the toes' horizontal direction, else +x) is left. A second limb of one kind and
/// side gets "_2"; a limb without a side is `arm` or `leg`; further roots are `root_2`, ...

#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

struct SkeletonChain {
    std::string name;        ///< "root", "spine", "left_arm", "right_arm", "left_leg", "right_leg", ...
    std::vector<int> joints; ///< indices into Skeleton::joints (no End Sites), parents first
};

/// The chains of `skeleton` in the order root, spine, arms (left, right), legs (left, right),
/// other limbs; every joint that is not an End Site is in exactly one chain. `positions`: one
/// world position per joint of Skeleton::joints (a frame of the motion) to tell left from
/// right where names cannot; null: the offsets' rest pose. InvalidArgument for a skeleton
/// without joints.
Result<std::vector<SkeletonChain>> skeletonChains(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>* positions = nullptr);

/// The same for a motion's skeleton, with the positions of its first frame.
Result<std::vector<SkeletonChain>> skeletonChains(const SkeletalMotion& motion);

} // namespace bunraku::analysis
