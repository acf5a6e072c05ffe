#pragma once
/// The puppet take of a skeletal motion: the 24 channels of the four bound parts
/// (world_T_part = world_T_joint * joint_T_part, analysis/core/skeleton.h), so that the
/// analysis channels and the full skeleton of a take always agree.

#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/take.h"

#include <memory>

namespace bunraku::analysis {

/// A take with the 24 puppet channels (head.x ... hand.roll; angles continuous from frame to
/// frame) posed from `motion`'s part bindings, at `rateHz`, with `labels`, carrying `motion`
/// as its skeleton. Errors: a part that is not bound, a non-finite pose.
Result<Take> puppetTakeFromSkeleton(std::shared_ptr<const SkeletalMotion> motion, double rateHz, const TakeLabels& labels = {});

/// The same motion at another rate: frame k at time k / toHz, rotations interpolated
/// spherically and translations linearly between the two nearest source frames, the last
/// frame held (frames = floor(duration x toHz) + 1).
SkeletalMotion resampleSkeletalMotion(const SkeletalMotion& motion, double fromHz, double toHz);

} // namespace bunraku::analysis
