#include "analysis/io/bvh_skeleton_export.h"

#include "analysis/io/atomic_file.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace bunraku::analysis::io {

namespace {

constexpr double kPi = std::numbers::pi;
/// Radians a rotation may differ from what the joint's rotation channels can express.
constexpr double kRotationTolerance = 1e-8;
/// Centimetres a translation may differ from what the joint's position channels can express.
constexpr double kTranslationToleranceCm = 1e-6;

Eigen::Matrix3d axisRotation(int axis, double angle) { return Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix(); }

/// `angle` moved by whole turns to within half a turn of `reference`.
double nearestTurn(double angle, double reference) { return angle - 2.0 * kPi * std::round((angle - reference) / (2.0 * kPi)); }

double wrapped(double angle) { return std::remainder(angle, 2.0 * kPi); }

bool isPositionChannel(JointChannel c) { return c == JointChannel::Xposition || c == JointChannel::Yposition || c == JointChannel::Zposition; }

int axisOf(JointChannel c)
{
    switch (c) {
    case JointChannel::Xposition:
    case JointChannel::Xrotation: return 0;
    case JointChannel::Yposition:
    case JointChannel::Yrotation: return 1;
    default: return 2;
    }
}

BvhChannel toBvhChannel(JointChannel c)
{
    switch (c) {
    case JointChannel::Xposition: return BvhChannel::Xposition;
    case JointChannel::Yposition: return BvhChannel::Yposition;
    case JointChannel::Zposition: return BvhChannel::Zposition;
    case JointChannel::Xrotation: return BvhChannel::Xrotation;
    case JointChannel::Yrotation: return BvhChannel::Yrotation;
    default: return BvhChannel::Zrotation;
    }
}

/// How one joint's rotation is written: its rotation channels' axes completed to three distinct
/// axes (the added ones must stay at zero angle).
struct RotationPlan {
    std::array<int, 3> axes{0, 1, 2};
    int written = 0; ///< how many of `axes` are channels of the joint
};

Result<RotationPlan> rotationPlan(const SkeletonJoint& joint)
{
    RotationPlan plan;
    std::array<bool, 3> used{false, false, false};
    for (JointChannel c : joint.channels) {
        if (isPositionChannel(c)) continue;
        const int axis = axisOf(c);
        if (used[std::size_t(axis)])
            return makeError(ErrorCode::Unsupported, "joint '" + joint.name + "': its rotation channels repeat an axis, which BVH export does not write");
        used[std::size_t(axis)] = true;
        plan.axes[std::size_t(plan.written++)] = axis;
    }
    // Complete with the remaining axes, cyclically after the last one used.
    int next = plan.written > 0 ? plan.axes[std::size_t(plan.written - 1)] : 2;
    for (int k = plan.written; k < 3; ++k) {
        do next = (next + 1) % 3;
        while (used[std::size_t(next)]);
        used[std::size_t(next)] = true;
        plan.axes[std::size_t(k)] = next;
    }
    return plan;
}

} // namespace

Eigen::Vector3d eulerAngles(const Eigen::Matrix3d& r, const std::array<int, 3>& axes, const std::optional<Eigen::Vector3d>& previous)
{
    const int i = axes[0], j = axes[1], k = axes[2];
    // Parity: +1 for the cyclic orders (xyz, yzx, zxy), -1 for the others.
    const double s = (j - i + 3) % 3 == 1 ? 1.0 : -1.0;
    const double cosB = std::hypot(r(i, i), r(i, j));
    const double b = std::atan2(s * r(i, k), cosB);
    double a = 0.0;
    if (cosB > 1e-10) a = std::atan2(-s * r(j, k), r(k, k));
    else if (previous) a = (*previous)[0]; // gimbal lock: a and c turn together; keep a
    // c from what is left: R_k(c) = R_j(-b) R_i(-a) R (exact also at gimbal lock).
    const Eigen::Matrix3d rest = axisRotation(j, -b) * axisRotation(i, -a) * r;
    const int p = (k + 1) % 3, q = (k + 2) % 3;
    const double c = std::atan2(rest(q, p), rest(p, p));
    Eigen::Vector3d first(wrapped(a), b, wrapped(c));
    if (!previous) return first;
    Eigen::Vector3d second(a + kPi, kPi - b, c + kPi);
    for (int n = 0; n < 3; ++n) {
        first[n] = nearestTurn(first[n], (*previous)[n]);
        second[n] = nearestTurn(second[n], (*previous)[n]);
    }
    return (first - *previous).cwiseAbs().sum() <= (second - *previous).cwiseAbs().sum() ? first : second;
}

Result<BvhFile> skeletalMotionToBvh(const SkeletalMotion& motion, double rateHz, const std::string& source)
{
    if (auto valid = validateSkeletalMotion(motion); !valid) return valid.error();
    if (!plausibleRate(rateHz)) return makeError(ErrorCode::InvalidArgument, "BVH export: " + rateExpectation());
    const Skeleton& skeleton = *motion.skeleton;
    const Eigen::Index frames = motion.frameCount();
    if (frames < 1) return makeError(ErrorCode::InvalidArgument, skeleton.name + ": BVH export needs at least one frame");
    const Eigen::Quaterniond source_R_world = skeleton.source.world_R_source.conjugate();
    const double unitsPerCm = 1.0 / skeleton.source.cmPerUnit;
    const auto toSource = [&](const Eigen::Vector3d& world) -> Eigen::Vector3d { return source_R_world * (unitsPerCm * world); };
    const Eigen::Matrix3d C = skeleton.source.world_R_source.toRotationMatrix();

    BvhFile file;
    file.source = source;
    file.motion.frameTime = 1.0 / rateHz;
    const std::size_t slots = skeleton.joints.size();
    std::vector<bool> moving(slots, false);
    for (int j : motion.movingJoints) moving[std::size_t(j)] = true;
    std::vector<RotationPlan> plans(slots);
    int channel = 0;
    for (std::size_t j = 0; j < slots; ++j) {
        const SkeletonJoint& joint = skeleton.joints[j];
        BvhJoint out;
        out.name = joint.name;
        out.parent = joint.parent;
        out.endSite = joint.endSite;
        out.firstChannel = channel;
        bool hasPosition = false;
        for (JointChannel c : joint.channels) {
            out.channels.push_back(toBvhChannel(c));
            hasPosition = hasPosition || isPositionChannel(c);
        }
        channel += int(joint.channels.size());
        // A joint without position channels has its translation as OFFSET: it must not move.
        if (!hasPosition && moving[j])
            return makeError(ErrorCode::Unsupported, skeleton.name + ": joint '" + joint.name +
                                                         "' moves but has no position channels in the source skeleton");
        out.offset = toSource(hasPosition ? joint.offset : motion.staticTranslations[j]);
        auto plan = rotationPlan(joint);
        if (!plan) return makeError(plan.error().code, skeleton.name + ": " + plan.error().message);
        plans[j] = *plan;
        file.skeleton.joints.push_back(std::move(out));
    }
    file.skeleton.channelCount = channel;
    file.motion.values.resize(frames, channel);

    std::vector<std::optional<Eigen::Vector3d>> previous(slots);
    for (Eigen::Index f = 0; f < frames; ++f) {
        for (std::size_t j = 0; j < slots; ++j) {
            const SkeletonJoint& joint = skeleton.joints[j];
            const BvhJoint& out = file.skeleton.joints[j];
            if (joint.endSite) continue;
            const Eigen::Vector3d translation = toSource(motion.translation(f, int(j)));
            const Eigen::Matrix3d rotation = C.transpose() * motion.rotation(f, int(j)).toRotationMatrix() * C;
            const RotationPlan& plan = plans[j];
            const Eigen::Vector3d angles = eulerAngles(rotation, plan.axes, previous[j]);
            previous[j] = angles;
            for (int n = plan.written; n < 3; ++n)
                if (std::fabs(wrapped(angles[n])) > kRotationTolerance)
                    return makeError(ErrorCode::Unsupported,
                                     skeleton.name + ": frame " + std::to_string(f) + ", joint '" + joint.name + "': the rotation turns " +
                                         std::to_string(std::fabs(wrapped(angles[n])) * 180.0 / kPi) +
                                         " deg about an axis the joint has no rotation channel for");
            Eigen::Vector3d expectedOffset = out.offset; // axes without a position channel keep OFFSET
            int rotationIndex = 0;
            for (std::size_t n = 0; n < joint.channels.size(); ++n) {
                const JointChannel c = joint.channels[n];
                double value = 0.0;
                if (isPositionChannel(c)) {
                    const int axis = axisOf(c);
                    value = translation[axis] - (skeleton.positionMode == PositionChannelMode::AddToOffset ? out.offset[axis] : 0.0);
                    expectedOffset[axis] = translation[axis];
                } else {
                    value = angles[rotationIndex++] * 180.0 / kPi;
                }
                file.motion.values(f, out.firstChannel + Eigen::Index(n)) = value;
            }
            if ((expectedOffset - translation).norm() * skeleton.source.cmPerUnit > kTranslationToleranceCm)
                return makeError(ErrorCode::Unsupported, skeleton.name + ": frame " + std::to_string(f) + ", joint '" + joint.name +
                                                             "': its translation changes along an axis it has no position channel for");
        }
    }
    return file;
}

Status writeSkeletonBvh(const Take& take, const std::filesystem::path& file)
{
    if (!take.skeleton) return makeError(ErrorCode::InvalidArgument, file.string() + ": " + take.displayName() + " has no skeleton");
    if (auto valid = validateTake(take); !valid) return makeError(valid.error().code, file.string() + ": " + valid.error().message);
    auto bvh = skeletalMotionToBvh(*take.skeleton, take.rateHz, take.labels.source);
    if (!bvh) return makeError(bvh.error().code, file.string() + ": " + bvh.error().message);
    return writeFileAtomically(file, formatBvh(*bvh));
}

} // namespace bunraku::analysis::io
