#pragma once
/// A whole take in new time: every channel and the full skeleton at fractional source frames
/// (a constant time scale, a time warp). Positions and other channels are interpolated
/// linearly, each 6-DOF part's orientation and every joint by slerp, and the angles are written
/// back Euler-filtered (analysis/core/angle_channels.h).

#include "analysis/core/take.h"

#include <Eigen/Core>

namespace bunraku::analysis {

/// The take at source frames `at` (one output frame each, clamped): frames = at.size(), the
/// same rate, channels and labels (source "<source> resampled"). Whole frames are copied
/// exactly; the first output frame starts on the branch of the source frame it shows.
Take resampleTake(const Take& take, const Eigen::VectorXd& at);

/// Source frames of a constant time scale: `frames` output frames spread evenly over the take,
/// t_source = t (sourceFrames - 1) / (frames - 1).
Eigen::VectorXd evenlySpacedFrames(Eigen::Index sourceFrames, Eigen::Index frames);

} // namespace bunraku::analysis
