#pragma once
/// Averages and linear combinations of full-skeleton motions, done on rotations: the average
/// take of thesis 3.7 takes each joint's mean rotation (meanRotation) of the members at their
/// corresponding frames; the decomposition of thesis 4.3 (y, z, eta) and the emotion weight of
/// eq. 4.45 (x = y + a z) work on skeleton coordinates - each joint's rotation vector about the
/// function's mean rotation of that joint at that frame (the log map, degrees) and the
/// positions of the translating joints (roots, moving joints; cm) - and come back through the
/// exp map, so a = 0, 1, 2 give rotations for every joint, never mixed Euler numbers. Bone
/// offsets are the first member's (they are equal for compatible motions).

#include "analysis/core/angle_channels.h"
#include "analysis/core/result.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

/// One motion in an average: per output frame the member's fractional frame to take.
struct BlendMember {
    const SkeletalMotion* motion = nullptr;
    Eigen::VectorXd at;  ///< one entry per output frame (clamped to the member's frames)
    double weight = 1.0;
};

/// Per output frame, every joint's weighted mean rotation of the members at their frames
/// (slerped at fractional frames) and the weighted mean position of every translating joint.
/// InvalidArgument for no members, members of different lengths of `at`, a null motion or
/// motions that are not compatible (compatibleMotions; the message names the joint layout).
Result<SkeletalMotionPtr> meanSkeletalMotion(const std::vector<BlendMember>& members);

/// Where skeleton coordinates are taken: a base rotation per joint slot and frame, and the
/// joints whose translation is a coordinate.
struct SkeletonChart {
    RotationChart rotations;        ///< tracks = joint slots (End Sites included)
    std::vector<int> translating;   ///< translatingJoints of the motions the chart was made for
    std::shared_ptr<const SkeletalMotion> layout; ///< the first motion: skeleton and bone offsets
    Eigen::Index coordinateCount() const
    {
        return 3 * Eigen::Index(rotations.tracks) + 3 * Eigen::Index(translating.size());
    }
};

/// Per frame (the shortest motion's frames) each joint's mean rotation over `motions` (the
/// chordal mean: a chart needs a base near the data, not the exact mean).
/// InvalidArgument for no motions or incompatible ones.
Result<SkeletonChart> meanSkeletonChart(const std::vector<std::shared_ptr<const SkeletalMotion>>& motions);

/// frames x chart.coordinateCount(): per joint slot the rotation vector of base^-1 q (degrees,
/// continuous over frames, x y z), then per translating joint its local translation (cm).
/// Frames beyond the chart's repeat its last base.
Eigen::MatrixXd skeletonCoordinates(const SkeletalMotion& motion, const SkeletonChart& chart);

/// The inverse: rotations base * exp(r), translating joints moving with the given positions,
/// every other joint at the layout's bone offset.
SkeletalMotionPtr motionFromSkeletonCoordinates(const Eigen::MatrixXd& coordinates, const SkeletonChart& chart);

} // namespace bunraku::analysis
