#pragma once
/// The puppet take of a skeletal motion: the 24 channels of the four bound parts
/// (world_T_part = world_T_joint * joint_T_part, analysis/core/skeleton.h), so that the
/// analysis channels and the full skeleton of a take always agree.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/take.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace bunraku::analysis {

/// A take with the 24 puppet channels (head.x ... hand.roll; angles continuous from frame to
/// frame) posed from `motion`'s part bindings, at `rateHz`, with `labels`, carrying `motion`
/// as its skeleton. Errors: a part that is not bound, a non-finite pose.
Result<Take> puppetTakeFromSkeleton(std::shared_ptr<const SkeletalMotion> motion, double rateHz, const TakeLabels& labels = {});

/// How far a take's 24 channels are from the parts its skeleton poses (the part bindings'
/// world_T_joint * joint_T_part), per part over every frame. A take read from BVH has none; a
/// derived take may have some: its channels follow the thesis (each coordinate's own time warp,
/// 3.6; positions averaged, 3.7; x = y + a z on channels, 4.5) while its skeleton moves one body
/// (one time per frame, joint rotations averaged and weighted on rotations).
struct SkeletonChannelGap {
    std::array<double, 4> positionCm{};  ///< per puppet part (kPuppetParts order): largest distance
    std::array<double, 4> angleDeg{};    ///< per part: largest angle between the two orientations
    double maxPositionCm = 0;
    double maxAngleDeg = 0;
    std::string worstPart;               ///< the part of maxPositionCm ("" when 0)
    Eigen::Index worstFrame = 0;         ///< the frame of maxPositionCm
};

/// InvalidArgument when the take has no skeleton or their frame counts differ; NotFound when a
/// puppet part is not bound or not among the take's channels.
Result<SkeletonChannelGap> skeletonChannelGap(const Take& take);

/// Below these a gap is rounding: cm (the tolerance of the Blender acceptance) and degrees.
inline constexpr double kSkeletonGapNoticeCm = 0.1;
inline constexpr double kSkeletonGapNoticeDeg = 0.1;
/// Below this (cm and deg) a take's channels are its skeleton's poses (bodyTake leaves them).
inline constexpr double kBodyAgreementTolerance = 1e-9;

/// The take's gap when it has a skeleton and the gap reaches a notice threshold; nothing for a
/// take without a skeleton, with one its channels follow, or one that cannot be compared.
std::optional<SkeletonChannelGap> noticeableSkeletonGap(const Take& take);

/// "up to 78.7 cm (hand, frame 172) and 127.1 deg".
std::string describeSkeletonChannelGap(const SkeletonChannelGap& gap);

/// The largest distance (cm) and angle (deg) between a take's puppet parts and the same parts
/// posed by `perChannel` (its per-channel ghost), over every part and frame; nothing when the
/// shapes differ or the take is neither of the puppet layout nor of a skeleton's joints.
struct PerChannelDistance {
    double maxPositionCm = 0;
    double maxAngleDeg = 0;
    std::string worstPart;
    Eigen::Index worstFrame = 0;
};
/// One motion for a take (what the 3D view draws, the graphs show and every export writes): for a
/// take with the 24 puppet channels and a skeleton that poses the four parts, or a take of a
/// skeleton's joints (every 6-DOF part a joint, its world pose: the whole body), whose channels
/// are not the parts' poses (a derived take: the thesis's per-channel arithmetic of 3.6, 3.7, 4.5
/// and 5.5), the take whose channels are those poses by forward kinematics of the skeleton (angles
/// continuous, starting on the branch nearest the take's own first frame; other channels kept),
/// with the take's own values as `perChannel`. Any other take (no skeleton, another layout,
/// channels within kBodyAgreementTolerance of the skeleton) is returned as it is, `perChannel` null.
/// Idempotent: the body motion of a body motion is itself.
struct BodyMotion {
    Take take;
    /// The thesis's per-channel result the channels were projected from; null when unchanged.
    std::shared_ptr<const Eigen::MatrixXd> perChannel;
    /// How far the body is from the per-channel result (measured in the same pass; zero when
    /// perChannel is null).
    PerChannelDistance distance;
};
/// `control` is told the fraction of frames done; a cancelled call returns the take as it is.
BodyMotion bodyMotion(Take take, const RunControl& control = {});
/// bodyMotion(take).take.
Take bodyTake(Take take);

std::optional<PerChannelDistance> perChannelDistance(const Take& take, const Eigen::MatrixXd& perChannel);

/// The same motion at another rate: frame k at time k / toHz, rotations interpolated
/// spherically and translations linearly between the two nearest source frames, the last
/// frame held (frames = floor(duration x toHz) + 1).
SkeletalMotion resampleSkeletalMotion(const SkeletalMotion& motion, double fromHz, double toHz);

} // namespace bunraku::analysis
