#include "analysis/core/skeleton_take.h"

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"

#include "analysis/core/rotation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace bunraku::analysis {

namespace {

/// The joint binding of each puppet part, in kPuppetParts order; NotFound names a part not bound.
Result<std::array<const PartBinding*, kPuppetPartCount>> boundParts(const Skeleton& skeleton)
{
    std::array<const PartBinding*, kPuppetPartCount> bindings{};
    for (std::size_t p = 0; p < bindings.size(); ++p) {
        bindings[p] = skeleton.binding(kPuppetParts[p]);
        if (!bindings[p]) return makeError(ErrorCode::NotFound, "the puppet part '" + std::string(kPuppetParts[p]) + "' is not bound to a joint");
    }
    return bindings;
}

/// A 6-DOF part of a take posed by its skeleton: world_T_joint * joint_T_part.
struct PosedPart {
    std::string name;
    Eigen::Index firstChannel = 0;
    int joint = -1;
    RigidTransform joint_T_part;
};

/// The parts the skeleton poses: the puppet's four bound parts of a take of the puppet layout, or
/// every part of a take of a skeleton's joints (each named as its joint, its world pose); empty
/// for any other take (a part that is no joint, a puppet part not bound).
std::vector<PosedPart> posedParts(const Take& take)
{
    std::vector<PosedPart> parts;
    if (!take.skeleton || !take.skeleton->skeleton) return parts;
    const Skeleton& skeleton = *take.skeleton->skeleton;
    if (hasPuppetLayout(take)) {
        const auto found = boundParts(skeleton);
        if (!found) return parts;
        for (std::size_t p = 0; p < found->size(); ++p)
            parts.push_back({std::string(kPuppetParts[p]), Eigen::Index(p) * kDofCount, (*found)[p]->joint, (*found)[p]->joint_T_part});
        return parts;
    }
    for (const SixDofPart& part : sixDofParts(take)) {
        const int joint = skeleton.find(part.part);
        if (joint < 0 || skeleton.joints[std::size_t(joint)].endSite) return {};
        parts.push_back({part.part, part.firstChannel, joint, RigidTransform{}});
    }
    return parts;
}

} // namespace

Result<Take> puppetTakeFromSkeleton(std::shared_ptr<const SkeletalMotion> motion, double rateHz, const TakeLabels& labels)
{
    if (!motion || !motion->skeleton) return makeError(ErrorCode::InvalidArgument, "a puppet take needs a skeletal motion");
    const Skeleton& skeleton = *motion->skeleton;
    const auto found = boundParts(skeleton);
    if (!found) return makeError(found.error().code, skeleton.name + ": " + found.error().message);
    const auto& bindings = *found;
    Take take;
    take.channels = puppetChannels();
    take.rateHz = rateHz;
    take.labels = labels;
    take.values.resize(motion->frameCount(), kPuppetChannelCount);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto poses = motion->worldPoses(f);
        for (std::size_t p = 0; p < bindings.size(); ++p)
            setPartPose(take, f, Eigen::Index(p) * kDofCount, poses[std::size_t(bindings[p]->joint)] * bindings[p]->joint_T_part);
    }
    take.skeleton = std::move(motion);
    if (auto valid = validateTake(take); !valid)
        return makeError(ErrorCode::Numerical, skeleton.name + ": the poses overflow (values too large?): " + valid.error().message);
    return take;
}

Result<SkeletonChannelGap> skeletonChannelGap(const Take& take)
{
    if (!take.skeleton || !take.skeleton->skeleton) return makeError(ErrorCode::InvalidArgument, "the take has no skeleton");
    const SkeletalMotion& motion = *take.skeleton;
    if (motion.frameCount() != take.frameCount())
        return makeError(ErrorCode::InvalidArgument, "the take has " + std::to_string(take.frameCount()) + " frames and its skeleton " +
                                                         std::to_string(motion.frameCount()));
    const auto found = boundParts(*motion.skeleton);
    if (!found) return found.error();
    const auto& bindings = *found;
    std::array<Eigen::Index, kPuppetPartCount> firstChannel{};
    for (std::size_t p = 0; p < bindings.size(); ++p) {
        const auto first = take.channelIndex(kPuppetParts[p], "x");
        if (!first) return makeError(ErrorCode::NotFound, "the take has no channels of the part '" + std::string(kPuppetParts[p]) + "'");
        firstChannel[p] = *first;
    }
    SkeletonChannelGap gap;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto poses = motion.worldPoses(f);
        for (std::size_t p = 0; p < bindings.size(); ++p) {
            const RigidTransform fromSkeleton = poses[std::size_t(bindings[p]->joint)] * bindings[p]->joint_T_part;
            const RigidTransform fromChannels = partPose(take, f, firstChannel[p]);
            const double distance = (fromSkeleton.translation - fromChannels.translation).norm();
            const double angle = rotationDistance(fromSkeleton.rotation, fromChannels.rotation) * 180.0 / std::numbers::pi;
            gap.positionCm[p] = std::max(gap.positionCm[p], distance);
            gap.angleDeg[p] = std::max(gap.angleDeg[p], angle);
            gap.maxAngleDeg = std::max(gap.maxAngleDeg, angle);
            if (distance > gap.maxPositionCm) {
                gap.maxPositionCm = distance;
                gap.worstPart = std::string(kPuppetParts[p]);
                gap.worstFrame = f;
            }
        }
    }
    return gap;
}

std::optional<SkeletonChannelGap> noticeableSkeletonGap(const Take& take)
{
    if (!take.skeleton) return std::nullopt;
    auto gap = skeletonChannelGap(take);
    if (!gap || (gap->maxPositionCm < kSkeletonGapNoticeCm && gap->maxAngleDeg < kSkeletonGapNoticeDeg)) return std::nullopt;
    return *gap;
}

std::string describeSkeletonChannelGap(const SkeletonChannelGap& gap)
{
    char text[160];
    std::snprintf(text, sizeof text, "up to %.1f cm (%s, frame %lld) and %.1f deg", gap.maxPositionCm,
                  gap.worstPart.empty() ? "no part" : gap.worstPart.c_str(), static_cast<long long>(gap.worstFrame), gap.maxAngleDeg);
    return text;
}

BodyMotion bodyMotion(Take take, const RunControl& control)
{
    if (!take.skeleton || !take.skeleton->skeleton || take.skeleton->frameCount() != take.frameCount())
        return {std::move(take), nullptr, {}};
    const std::vector<PosedPart> parts = posedParts(take);
    if (parts.empty()) return {std::move(take), nullptr, {}};
    // One pass: the body's channels, and whether they differ from the take's own (the channels of
    // a take that is its body already are kept bit for bit; channels of no posed part stay).
    Eigen::MatrixXd body = take.values;
    bool differs = false;
    PerChannelDistance distance;
    const Eigen::Index frames = take.frameCount();
    for (Eigen::Index f = 0; f < frames; ++f) {
        if (f % 4096 == 4095) {
            if (control.cancelled()) return {std::move(take), nullptr, {}};
            control.report(double(f) / double(frames));
        }
        const auto poses = take.skeleton->worldPoses(f);
        for (const PosedPart& part : parts) {
            const Eigen::Index first = part.firstChannel;
            const RigidTransform pose = poses[std::size_t(part.joint)] * part.joint_T_part;
            const RigidTransform channels = partPose(take, f, first);
            const double cm = (pose.translation - channels.translation).norm();
            const double deg = rotationDistance(pose.rotation, channels.rotation) * 180.0 / std::numbers::pi;
            differs = differs || cm > kBodyAgreementTolerance || deg > kBodyAgreementTolerance;
            distance.maxAngleDeg = std::max(distance.maxAngleDeg, deg);
            if (cm > distance.maxPositionCm) {
                distance.maxPositionCm = cm;
                distance.worstPart = part.name;
                distance.worstFrame = f;
            }
            const Eigen::MatrixXd& previousRow = f == 0 ? take.values : body;
            const Eigen::Index previousFrame = f == 0 ? 0 : f - 1;
            const YawPitchRoll previous{previousRow(previousFrame, first + 3), previousRow(previousFrame, first + 4),
                                        previousRow(previousFrame, first + 5)};
            const YawPitchRoll angles = nearestEquivalent(yawPitchRollFromRotation(pose.rotation), previous);
            body.block<1, 3>(f, first) = pose.translation.transpose();
            body(f, first + 3) = angles.yaw;
            body(f, first + 4) = angles.pitch;
            body(f, first + 5) = angles.roll;
        }
    }
    if (!differs) return {std::move(take), nullptr, {}};
    auto perChannel = std::make_shared<const Eigen::MatrixXd>(std::move(take.values));
    take.values = std::move(body);
    return {std::move(take), std::move(perChannel), std::move(distance)};
}

Take bodyTake(Take take)
{
    return bodyMotion(std::move(take)).take;
}

std::optional<PerChannelDistance> perChannelDistance(const Take& take, const Eigen::MatrixXd& perChannel)
{
    if (perChannel.rows() != take.frameCount() || perChannel.cols() != take.channelCount()) return std::nullopt;
    // The puppet's four parts, or every part of a take of a skeleton's joints.
    std::vector<SixDofPart> parts;
    if (hasPuppetLayout(take)) {
        for (int p = 0; p < kPuppetPartCount; ++p) parts.push_back({std::string(kPuppetParts[std::size_t(p)]), Eigen::Index(p) * kDofCount});
    } else if (take.skeleton && take.skeleton->skeleton) {
        parts = sixDofParts(take);
        for (const SixDofPart& part : parts) {
            const int joint = take.skeleton->skeleton->find(part.part);
            if (joint < 0 || take.skeleton->skeleton->joints[std::size_t(joint)].endSite) return std::nullopt;
        }
    }
    if (parts.empty()) return std::nullopt;
    Take ghost;
    ghost.channels = take.channels;
    ghost.values = perChannel;
    PerChannelDistance d;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        for (const SixDofPart& part : parts) {
            const RigidTransform a = partPose(take, f, part.firstChannel);
            const RigidTransform b = partPose(ghost, f, part.firstChannel);
            const double distance = (a.translation - b.translation).norm();
            d.maxAngleDeg = std::max(d.maxAngleDeg, rotationDistance(a.rotation, b.rotation) * 180.0 / std::numbers::pi);
            if (distance > d.maxPositionCm) {
                d.maxPositionCm = distance;
                d.worstPart = part.part;
                d.worstFrame = f;
            }
        }
    }
    return d;
}

SkeletalMotion resampleSkeletalMotion(const SkeletalMotion& motion, double fromHz, double toHz)
{
    const Eigen::Index sourceFrames = motion.frameCount();
    const int slots = motion.jointSlots();
    const double duration = sourceFrames > 1 ? double(sourceFrames - 1) / fromHz : 0.0;
    const Eigen::Index frames = sourceFrames > 0 ? Eigen::Index(std::floor(duration * toHz + 1e-9)) + 1 : 0;
    SkeletalMotion out;
    out.skeleton = motion.skeleton;
    out.staticTranslations = motion.staticTranslations;
    out.movingJoints = motion.movingJoints;
    out.rotations.resize(std::size_t(frames) * std::size_t(slots));
    out.movingTranslations.resize(frames, motion.movingTranslations.cols());
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double at = std::min(double(f) / toHz * fromHz, double(sourceFrames - 1));
        const Eigen::Index a = Eigen::Index(std::floor(at));
        const Eigen::Index b = std::min(a + 1, sourceFrames - 1);
        const double t = at - double(a);
        for (int j = 0; j < slots; ++j)
            out.rotation(f, j) = t == 0.0 ? motion.rotation(a, j) : motion.rotation(a, j).slerp(t, motion.rotation(b, j)).normalized();
        out.movingTranslations.row(f) = (1.0 - t) * motion.movingTranslations.row(a) + t * motion.movingTranslations.row(b);
    }
    return out;
}

} // namespace bunraku::analysis
