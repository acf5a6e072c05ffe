#include "analysis/skeleton/puppet_rig_fit.h"

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/rotation.h"

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace bunraku::analysis {

namespace {

constexpr int kHead = 0;
constexpr int kShoulder = 1;
constexpr int kArm = 2;
constexpr int kHand = 3;

using namespace rig;

RigidTransform channelPose(const Take& take, Eigen::Index frame, int part)
{
    return partPose(take, frame, Eigen::Index(part) * kDofCount);
}

/// Least squares of p_c - p_p = R_p a + R_c b over every frame of every take: (a, b).
Result<std::pair<Eigen::Vector3d, Eigen::Vector3d>> fitJoint(const std::vector<const Take*>& takes, int parent, int child)
{
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    for (const Take* take : takes) {
        for (Eigen::Index f = 0; f < take->frameCount(); ++f) {
            const RigidTransform p = channelPose(*take, f, parent);
            const RigidTransform c = channelPose(*take, f, child);
            Eigen::Matrix<double, 3, 6> a;
            a.leftCols<3>() = p.rotation.toRotationMatrix();
            a.rightCols<3>() = c.rotation.toRotationMatrix();
            const Eigen::Vector3d d = c.translation - p.translation;
            normal.noalias() += a.transpose() * a;
            rhs.noalias() += a.transpose() * d;
        }
    }
    // Minimum norm where a and b are not separable (the child never turns against its parent).
    const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 6, 6>> solver(normal);
    const Eigen::Matrix<double, 6, 1> x = solver.solve(rhs);
    if (!x.allFinite())
        return makeError(ErrorCode::Numerical, "the puppet rig's " + std::string(kPuppetParts[std::size_t(child)]) + " joint cannot be fitted");
    return std::pair<Eigen::Vector3d, Eigen::Vector3d>{x.head<3>(), x.tail<3>()};
}

Status checkLayout(const Take& take)
{
    if (!hasPuppetLayout(take))
        return makeError(ErrorCode::InvalidArgument, "the puppet rig needs the 24 puppet channels (head.x ... hand.roll); " +
                                                         take.displayName() + " has " + std::to_string(take.channelCount()) + " channels");
    return okStatus();
}

const std::vector<JointChannel> kRootChannels{JointChannel::Xposition, JointChannel::Yposition, JointChannel::Zposition,
                                              JointChannel::Zrotation, JointChannel::Yrotation, JointChannel::Xrotation};
const std::vector<JointChannel> kRotationChannels{JointChannel::Zrotation, JointChannel::Yrotation, JointChannel::Xrotation};

} // namespace

Result<PuppetRigFit> fitPuppetRig(const std::vector<const Take*>& takes)
{
    if (takes.empty()) return makeError(ErrorCode::InvalidArgument, "the puppet rig needs at least one take");
    for (const Take* take : takes)
        if (auto ok = checkLayout(*take); !ok) return ok.error();
    auto head = fitJoint(takes, kShoulder, kHead);
    if (!head) return head.error();
    auto arm = fitJoint(takes, kShoulder, kArm);
    if (!arm) return arm.error();
    auto hand = fitJoint(takes, kArm, kHand);
    if (!hand) return hand.error();

    auto skeleton = std::make_shared<Skeleton>();
    skeleton->name = kPuppetRigName;
    skeleton->source = SourceFrame{Eigen::Quaterniond::Identity(), 1.0, "z"};
    skeleton->positionMode = PositionChannelMode::ReplaceOffset;
    skeleton->joints.resize(kSlots);
    // Offsets: the neck and the shoulder joint from the shoulder's sensor, the arm's sensor from
    // the shoulder joint, the wrist from the arm's sensor, the head's and the hand's sensors
    // from the neck and the wrist.
    const std::array<Eigen::Vector3d, kSlots> offsets{Eigen::Vector3d::Zero(), head->first, head->second, arm->first,
                                                         arm->second, hand->first, hand->second};
    for (int slot = 0; slot < kSlots; ++slot) {
        const Slot& layout = kLayout[std::size_t(slot)];
        SkeletonJoint& j = skeleton->joints[std::size_t(slot)];
        j.name = layout.name;
        j.parent = layout.parent;
        j.offset = offsets[std::size_t(slot)];
        j.endSite = layout.endSite;
        if (!layout.endSite) j.channels = layout.parent < 0 ? kRootChannels : kRotationChannels;
    }
    skeleton->parts = *puppetRigBindings(*skeleton);
    if (auto valid = validateSkeleton(*skeleton); !valid) return valid.error();
    auto residual = puppetRigResidual(takes, *skeleton);
    if (!residual) return residual.error();
    return PuppetRigFit{std::move(skeleton), *residual};
}

Result<std::shared_ptr<const SkeletalMotion>> puppetRigMotion(const Take& take, std::shared_ptr<const Skeleton> rig)
{
    if (auto ok = checkLayout(take); !ok) return ok.error();
    if (!rig || !isPuppetRig(*rig)) return makeError(ErrorCode::InvalidArgument, "not a fitted puppet rig");
    auto motion = std::make_shared<SkeletalMotion>(makeRestMotion(rig, take.frameCount()));
    motion->movingJoints = {kRootSlot};
    motion->movingTranslations.resize(take.frameCount(), 3);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        std::array<RigidTransform, kPuppetPartCount> pose;
        for (int p = 0; p < kPuppetPartCount; ++p) pose[std::size_t(p)] = channelPose(take, f, p);
        const Eigen::Quaterniond& shoulder = pose[kShoulder].rotation;
        motion->movingTranslations.row(f) = pose[kShoulder].translation.transpose();
        motion->rotation(f, kRootSlot) = shoulder;
        motion->rotation(f, kNeckSlot) = (shoulder.conjugate() * pose[kHead].rotation).normalized();
        motion->rotation(f, kShoulderSlot) = (shoulder.conjugate() * pose[kArm].rotation).normalized();
        motion->rotation(f, kWristSlot) = (pose[kArm].rotation.conjugate() * pose[kHand].rotation).normalized();
    }
    if (take.frameCount() > 0) motion->staticTranslations[kRootSlot] = motion->movingTranslations.row(0).transpose();
    if (auto valid = validateSkeletalMotion(*motion); !valid) return valid.error();
    return std::shared_ptr<const SkeletalMotion>(std::move(motion));
}

Result<PuppetRigResidual> puppetRigResidual(const std::vector<const Take*>& takes, const Skeleton& rig)
{
    auto shared = std::make_shared<const Skeleton>(rig);
    PuppetRigResidual residual;
    std::array<double, kPuppetPartCount> sumSquares{};
    for (const Take* take : takes) {
        auto motion = puppetRigMotion(*take, shared);
        if (!motion) return motion.error();
        for (Eigen::Index f = 0; f < take->frameCount(); ++f) {
            const auto poses = (*motion)->worldPoses(f);
            for (int p = 0; p < kPuppetPartCount; ++p) {
                const PartBinding& b = rig.parts[std::size_t(p)];
                const RigidTransform fromRig = poses[std::size_t(b.joint)] * b.joint_T_part;
                const RigidTransform fromChannels = channelPose(*take, f, p);
                const double distance = (fromRig.translation - fromChannels.translation).norm();
                const double angle = rotationDistance(fromRig.rotation, fromChannels.rotation) * 180.0 / std::numbers::pi;
                sumSquares[std::size_t(p)] += distance * distance;
                residual.maxCm[std::size_t(p)] = std::max(residual.maxCm[std::size_t(p)], distance);
                residual.maxDeg[std::size_t(p)] = std::max(residual.maxDeg[std::size_t(p)], angle);
            }
        }
        residual.frames += take->frameCount();
    }
    for (int p = 0; p < kPuppetPartCount; ++p)
        residual.rmsCm[std::size_t(p)] = residual.frames > 0 ? std::sqrt(sumSquares[std::size_t(p)] / double(residual.frames)) : 0.0;
    return residual;
}

Result<std::optional<PuppetRigFit>> attachPuppetRig(std::vector<Take>& takes)
{
    std::vector<const Take*> needing;
    for (const Take& take : takes)
        if (!take.skeleton && hasPuppetLayout(take) && take.frameCount() > 0) needing.push_back(&take);
    if (needing.empty()) return std::optional<PuppetRigFit>{};
    auto fit = fitPuppetRig(needing);
    if (!fit) return fit.error();
    for (Take& take : takes) {
        if (take.skeleton || !hasPuppetLayout(take) || take.frameCount() == 0) continue;
        auto motion = puppetRigMotion(take, fit->skeleton);
        if (!motion) return makeError(motion.error().code, take.displayName() + ": " + motion.error().message);
        take.skeleton = std::move(motion).value();
    }
    return std::optional<PuppetRigFit>{std::move(fit).value()};
}

std::string describePuppetRigResidual(const PuppetRigResidual& residual)
{
    std::string text;
    char buffer[96];
    for (int p = 0; p < kPuppetPartCount; ++p) {
        std::snprintf(buffer, sizeof buffer, "%s%s %.2f cm (rms %.2f)", p == 0 ? "" : ", ", std::string(kPuppetParts[std::size_t(p)]).c_str(),
                      residual.maxCm[std::size_t(p)], residual.rmsCm[std::size_t(p)]);
        text += buffer;
    }
    return text;
}

} // namespace bunraku::analysis
