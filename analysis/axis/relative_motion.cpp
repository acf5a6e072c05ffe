#include "analysis/axis/relative_motion.h"

#include "analysis/core/puppet_layout.h"

namespace bunraku::analysis {

namespace {

/// setPartPose, but on frame 0 the angles nearest the ones already stored there.
void writePose(Take& take, Eigen::Index frame, Eigen::Index first, const RigidTransform& pose, bool nearestStored)
{
    if (frame > 0 || !nearestStored) {
        setPartPose(take, frame, first, pose);
        return;
    }
    const YawPitchRoll stored{take.values(frame, first + 3), take.values(frame, first + 4), take.values(frame, first + 5)};
    const YawPitchRoll angles = nearestEquivalent(yawPitchRollFromRotation(pose.rotation), stored);
    take.values.block(frame, first, 1, 3) = pose.translation.transpose();
    take.values(frame, first + 3) = angles.yaw;
    take.values(frame, first + 4) = angles.pitch;
    take.values(frame, first + 5) = angles.roll;
}

} // namespace

Result<RelativeMotion> relativeMotion(const Take& take, const std::vector<RigidTransform>& world_T_axis)
{
    if (Eigen::Index(world_T_axis.size()) != take.frameCount())
        return makeError(ErrorCode::InvalidArgument, "axis has " + std::to_string(world_T_axis.size()) + " frames but take " +
                                                         take.displayName() + " has " + std::to_string(take.frameCount()));
    const std::vector<SixDofPart> parts = sixDofParts(take);
    if (parts.empty()) return makeError(ErrorCode::NotFound, "take " + take.displayName() + " has no 6-DOF part");
    RelativeMotion relative;
    for (const SixDofPart& part : parts) relative.parts.push_back(part.part);
    relative.axis_T_part.resize(world_T_axis.size());
    for (Eigen::Index frame = 0; frame < take.frameCount(); ++frame) {
        const RigidTransform axis_T_world = world_T_axis[std::size_t(frame)].inverse();
        auto& row = relative.axis_T_part[std::size_t(frame)];
        row.reserve(parts.size());
        for (const SixDofPart& part : parts) row.push_back(axis_T_world * partPose(take, frame, part.firstChannel));
    }
    return relative;
}

Take relativeMotionTake(const RelativeMotion& relative, const Take& layout)
{
    Take take;
    take.rateHz = layout.rateHz;
    take.channels = layout.channels;
    take.labels = layout.labels;
    take.labels.source = "relative motion of " + layout.displayName();
    take.values = Eigen::MatrixXd::Zero(relative.frameCount(), layout.channelCount());
    const std::vector<SixDofPart> parts = sixDofParts(layout);
    for (Eigen::Index frame = 0; frame < relative.frameCount(); ++frame)
        for (std::size_t p = 0; p < parts.size() && p < relative.parts.size(); ++p)
            writePose(take, frame, parts[p].firstChannel, relative.axis_T_part[std::size_t(frame)][p], false);
    return take;
}

Take recombine(const Take& layout, const std::vector<RigidTransform>& world_T_axis, const RelativeMotion& relative)
{
    Take take;
    take.rateHz = layout.rateHz;
    take.channels = layout.channels;
    take.labels = layout.labels;
    const Eigen::Index frames = std::min<Eigen::Index>(Eigen::Index(world_T_axis.size()), relative.frameCount());
    take.values.resize(frames, layout.channelCount());
    for (Eigen::Index frame = 0; frame < frames; ++frame)
        take.values.row(frame) = layout.values.row(std::min(frame, layout.frameCount() - 1));
    const std::vector<SixDofPart> parts = sixDofParts(layout);
    for (Eigen::Index frame = 0; frame < frames; ++frame) {
        const RigidTransform& world_T_axis_now = world_T_axis[std::size_t(frame)];
        for (std::size_t p = 0; p < parts.size() && p < relative.parts.size(); ++p)
            writePose(take, frame, parts[p].firstChannel, world_T_axis_now * relative.axis_T_part[std::size_t(frame)][p],
                      layout.frameCount() > 0);
    }
    return take;
}

} // namespace bunraku::analysis
