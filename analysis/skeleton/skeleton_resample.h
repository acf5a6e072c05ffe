#pragma once
/// Time operations on a take's full skeleton (analysis/core/skeleton.h), shared by every derived
/// take: resampling at fractional frames (a time warp, a constant time scale, padding, a start
/// shift), and rigid moves of the whole body (a heading turn, a start-position move, the design's
/// per-frame axis correction). Rotations are interpolated on rotations (slerp along the shorter
/// arc), translations linearly; bone offsets (static translations) are never touched, so bone
/// lengths stay those of the source.

#include "analysis/core/pose.h"
#include "analysis/core/skeleton.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace bunraku::analysis {

using SkeletalMotionPtr = std::shared_ptr<const SkeletalMotion>;

/// The motion at fractional source frames `at` (one output frame each, clamped to the source's
/// frames): every joint's local rotation slerped between the two neighbouring frames, the moving
/// joints' translations interpolated linearly. Whole frames are copied exactly. A source
/// without frames gives null.
SkeletalMotionPtr resampleSkeletalMotion(const SkeletalMotion& motion, const Eigen::VectorXd& at);

/// Source frame of each of `frames` output frames for a take shifted by `shift` frames (thesis
/// 2.2 step 3, preprocess::shiftTake): clamp(t + shift, 0, sourceFrames - 1).
Eigen::VectorXd shiftedFrames(Eigen::Index sourceFrames, Eigen::Index frames, int shift);

/// Every root joint (parent -1) of the skeleton moved by world_T_new at every frame: the whole
/// body turned and translated rigidly (new world_T_root = world_T_new * world_T_root). The
/// root's local translation becomes moving when the move changes it.
SkeletalMotionPtr moveSkeletalMotion(const SkeletalMotion& motion, const RigidTransform& world_T_new);

/// Per frame `corrections[f]` applied to the roots in `roots` (new world_T_root =
/// corrections[f] * world_T_root); other roots keep their motion. corrections has one entry
/// per frame (asserted).
SkeletalMotionPtr moveSkeletalRoots(const SkeletalMotion& motion, const std::vector<RigidTransform>& corrections,
                                    const std::vector<int>& roots);

/// The roots whose subtrees hold a joint bound to a puppet part (Skeleton::parts); every root
/// when no part is bound.
std::vector<int> partChainRoots(const Skeleton& skeleton);

/// The joints whose local translation is a position rather than a bone: every root and every
/// joint moving in any of `motions`, in joint order.
std::vector<int> translatingJoints(const std::vector<const SkeletalMotion*>& motions);

/// True when both motions have the same joints (names, parents, End Sites): motions that can be
/// averaged joint by joint. Roots may stand anywhere (a take moved to its start position), and
/// bones may differ (files of one performer written with other End Sites or rounding, or
/// performers of other sizes): an average or weighted motion moves the first motion's bones, so
/// that it is one body whose segment lengths never change (docs/NORMALISATION.md).
bool compatibleMotions(const SkeletalMotion& a, const SkeletalMotion& b);

} // namespace bunraku::analysis
