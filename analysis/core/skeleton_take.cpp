#include "analysis/core/skeleton_take.h"

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"

#include <cmath>

namespace bunraku::analysis {

Result<Take> puppetTakeFromSkeleton(std::shared_ptr<const SkeletalMotion> motion, double rateHz, const TakeLabels& labels)
{
    if (!motion || !motion->skeleton) return makeError(ErrorCode::InvalidArgument, "a puppet take needs a skeletal motion");
    const Skeleton& skeleton = *motion->skeleton;
    std::array<const PartBinding*, kPuppetPartCount> bindings{};
    for (std::size_t p = 0; p < bindings.size(); ++p) {
        bindings[p] = skeleton.binding(kPuppetParts[p]);
        if (!bindings[p])
            return makeError(ErrorCode::NotFound, skeleton.name + ": the puppet part '" + std::string(kPuppetParts[p]) + "' is not bound to a joint");
    }
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
