#pragma once
/// BVH export on the source skeleton: a take that carries a skeleton (analysis/core/skeleton.h)
/// is written with the source file's hierarchy, joint names, offsets, channel order, axes and
/// units, and 1 / rate as its frame time, so an untouched take gives its file back and a
/// derived take is the edited motion on the performer's own skeleton. docs/FORMATS.md.

#include "analysis/core/skeleton.h"
#include "analysis/core/take.h"
#include "analysis/io/bvh.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace bunraku::analysis::io {

/// Angles (radians) a, b, c with R = R_axes[0](a) * R_axes[1](b) * R_axes[2](c) (intrinsic, BVH's
/// order of rotation channels) for three distinct axes (0 = x, 1 = y, 2 = z). Of the two
/// solutions, the one nearest `previous` (each angle then moved by whole turns to within half a
/// turn of it); without `previous`, the one with |b| <= pi/2 and angles in (-pi, pi].
Eigen::Vector3d eulerAngles(const Eigen::Matrix3d& rotation, const std::array<int, 3>& axes,
                            const std::optional<Eigen::Vector3d>& previous = std::nullopt);

/// The BVH structure of a skeletal motion on its source skeleton: joints, End Sites, offsets and
/// channels as in the source, values in the source's axes and units (SourceFrame), rotation
/// channels as continuous Euler angles in each joint's channel order, frame time 1 / rateHz.
/// Errors (naming the joint and frame) when the motion cannot be written on the source's
/// channels: a joint without position channels whose translation changes, or a rotation that
/// the joint's rotation channels cannot express (fewer than 3 axes, or a repeated axis).
Result<BvhFile> skeletalMotionToBvh(const SkeletalMotion& motion, double rateHz, const std::string& source = {});

/// Writes a take that has a skeleton as BVH on that skeleton, atomically.
Status writeSkeletonBvh(const Take& take, const std::filesystem::path& file);

} // namespace bunraku::analysis::io
