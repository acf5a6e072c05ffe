#pragma once
/// Motion = axis motion + relative motion of each part in the axis frame (thesis eq. 5.1):
/// axis_T_part = (world_T_axis)^-1 world_T_part for every 6-DOF part of the take, and back.

#include "analysis/axis/inertia_axis.h"
#include "analysis/core/pose.h"
#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <string>
#include <vector>

namespace bunraku::analysis {

struct RelativeMotion {
    std::vector<std::string> parts;                      ///< the take's 6-DOF parts, in take order
    std::vector<std::vector<RigidTransform>> axis_T_part; ///< [frame][part]
    Eigen::Index frameCount() const { return Eigen::Index(axis_T_part.size()); }
};

/// Relative motion of every 6-DOF part (x..roll) of `take` in the frames of `world_T_axis`
/// (one per take frame). InvalidArgument when the frame counts differ or the take has no
/// 6-DOF part.
Result<RelativeMotion> relativeMotion(const Take& take, const std::vector<RigidTransform>& world_T_axis);

/// The relative motion as a take (same channels as `layout`, the 6-DOF parts' poses expressed
/// in the axis frame, angles continuous), for graphs and the "puppet + axis" display.
Take relativeMotionTake(const RelativeMotion& relative, const Take& layout);

/// world_T_part = world_T_axis axis_T_part written into a copy of `layout`'s channels (its
/// other columns keep their values; the frame count becomes the axis's). Angles are chosen
/// continuous with the previous frame and, on the first frame, nearest `layout`'s first frame.
/// The round trip relativeMotion -> recombine reproduces the poses to rounding (< 1e-9).
Take recombine(const Take& layout, const std::vector<RigidTransform>& world_T_axis, const RelativeMotion& relative);

} // namespace bunraku::analysis
