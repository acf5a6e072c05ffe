#include "analysis/body/body_fit.h"

#include "analysis/skeleton/puppet_rig_fit.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_anatomy.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace bunraku::analysis {
namespace {

/// p -> to + rotation * scale * (p - from), in a part frame.
struct PartMapping {
    Eigen::Vector3d from = Eigen::Vector3d::Zero();
    Eigen::Vector3d to = Eigen::Vector3d::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d scale = Eigen::Vector3d::Ones(); ///< along the puppet part's x, y, z

    Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return to + rotation * scale.cwiseProduct(p - from); }
};

Result<PartMapping> mapping(const Eigen::Vector3d& puppetA, const Eigen::Vector3d& puppetB, const Eigen::Vector3d& skeletonA,
                            const Eigen::Vector3d& skeletonB, const std::string& what)
{
    const Eigen::Vector3d p = puppetB - puppetA;
    const Eigen::Vector3d s = skeletonB - skeletonA;
    if (p.norm() < 1e-9 || s.norm() < 1e-9 || !s.allFinite())
        return makeError(ErrorCode::Numerical, "cannot fit the puppet's " + what + ": its landmarks coincide");
    PartMapping m;
    m.from = puppetA;
    m.to = skeletonA;
    m.rotation = Eigen::Quaterniond::FromTwoVectors(p, s).normalized();
    m.scale = Eigen::Vector3d::Constant(s.norm() / p.norm());
    return m;
}

Primitive mapped(const Primitive& primitive, const PartMapping& m)
{
    Primitive out = primitive;
    const Eigen::Matrix3d rotation = primitive.part_T_primitive.rotation.toRotationMatrix();
    Eigen::Vector3d factor;
    for (int k = 0; k < 3; ++k) factor[k] = m.scale.cwiseProduct(rotation.col(k)).norm();
    out.part_T_primitive.translation = m.apply(primitive.part_T_primitive.translation);
    out.part_T_primitive.rotation = (m.rotation * primitive.part_T_primitive.rotation).normalized();
    switch (primitive.shape) {
    case PrimitiveShape::Box:
    case PrimitiveShape::Ellipsoid: out.size = primitive.size.cwiseProduct(factor); break;
    case PrimitiveShape::Cylinder:
    case PrimitiveShape::Frustum: {
        const double across = std::sqrt(factor.x() * factor.y());
        out.radius = primitive.radius * across;
        out.topRadius = primitive.topRadius * across;
        out.length = primitive.length * factor.z();
        break;
    }
    }
    return out;
}

std::vector<Primitive> reflected(const std::vector<Primitive>& source)
{
    const Eigen::Matrix3d flip = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
    std::vector<Primitive> out = source;
    for (Primitive& primitive : out) {
        primitive.part_T_primitive.translation.y() = -primitive.part_T_primitive.translation.y();
        const Eigen::Matrix3d rotation = flip * primitive.part_T_primitive.rotation.toRotationMatrix() * flip;
        primitive.part_T_primitive.rotation = Eigen::Quaterniond(rotation).normalized();
    }
    return out;
}

} // namespace

Result<BodyDescription> fitBodyToSkeleton(const BodyDescription& puppet, const SkeletalMotion& motion, const BodyFitOptions& options)
{
    if (!motion.skeleton) return makeError(ErrorCode::InvalidArgument, "fitting the body needs a skeleton");
    const Skeleton& skeleton = *motion.skeleton;
    PartJoints joints{};
    std::array<RigidTransform, 4> joint_T_part{};
    for (std::size_t p = 0; p < 4; ++p) {
        const PartBinding* binding = skeleton.binding(kPuppetParts[p]);
        if (!binding)
            return makeError(ErrorCode::NotFound, skeleton.name + ": the puppet part '" + std::string(kPuppetParts[p]) + "' is not bound");
        joints[p] = binding->joint;
        joint_T_part[p] = binding->joint_T_part;
    }
    auto landmarks = findLandmarks(motion, joints, options.referenceFrame);
    if (!landmarks) return landmarks.error();
    const SkeletonLandmarks& l = *landmarks;
    const auto poses = motion.worldPoses(options.referenceFrame);
    std::array<RigidTransform, 4> part_T_world{};
    for (std::size_t p = 0; p < 4; ++p) part_T_world[p] = (poses[std::size_t(joints[p])] * joint_T_part[p]).inverse();
    const auto in = [&](std::size_t part, const Eigen::Vector3d& world) { return part_T_world[part].apply(world); };

    const PuppetLandmarks& q = options.puppet;
    std::array<PartMapping, 4> maps;
    const std::array<std::pair<Result<PartMapping>, std::size_t>, 4> built{{
        {mapping(q.headNeck, q.headTop, in(0, l.neckBase), in(0, l.headTop), "head"), 0},
        {mapping(q.shoulderNeck, q.shoulderWaist, in(1, l.neckBase), in(1, l.hips), "torso"), 1},
        {mapping(q.armStart, q.armEnd, in(2, l.elbow), in(2, l.wrist), "arm"), 2},
        {mapping(q.handWrist, q.handTip, in(3, l.wrist), in(3, l.fingerTip), "hand"), 3},
    }};
    for (const auto& [result, part] : built) {
        if (!result) return makeError(result.error().code, skeleton.name + ": " + result.error().message);
        maps[part] = result.value();
    }
    // The torso's width and depth follow the shoulders rather than its height.
    const double width = l.otherShoulderFound ? (l.otherShoulder - l.boundShoulder).norm()
                                              : 2.0 * (l.boundShoulder - l.neckBase).norm();
    if (width > 1e-6 && q.torsoWidth > 0.0) {
        const double across = q.torsoPerShoulders * width / q.torsoWidth;
        maps[1].scale.x() = across;
        maps[1].scale.y() = across;
    }

    BodyDescription body = puppet;
    body.name = puppet.name + ", fitted to " + skeleton.name;
    for (BodyPart& part : body.parts) {
        if (part.mirrored) continue;
        const int driver = [&] {
            for (std::size_t p = 0; p < 4; ++p)
                if (kPuppetParts[p] == part.drivenBy) return int(p);
            return -1;
        }();
        if (driver < 0) continue; // driven by a take part the skeleton does not bind: left as it is
        const PartMapping& m = maps[std::size_t(driver)];
        for (Primitive& primitive : part.primitives) primitive = mapped(primitive, m);
        part.fit = Eigen::Affine3d::Identity();
        part.fit.linear() = m.rotation.toRotationMatrix() * m.scale.asDiagonal();
        part.fit.translation() = m.to - part.fit.linear() * m.from;
    }
    for (BodyPart& part : body.parts) {
        if (!part.mirrored) continue;
        const int source = body.partIndex(part.mirrorOf);
        if (source < 0) continue;
        part.primitives = reflected(body.parts[std::size_t(source)].primitives);
        const Eigen::Matrix3d flip = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
        const Eigen::Affine3d& sourceFit = body.parts[std::size_t(source)].fit;
        part.fit = Eigen::Affine3d::Identity();
        part.fit.linear() = flip * sourceFit.linear() * flip;
        part.fit.translation() = flip * sourceFit.translation();
    }
    return body;
}

BodyDescription bodyForTake(const BodyDescription& puppet, const Take& take)
{
    if (!take.skeleton || !take.skeleton->skeleton || isPuppetRig(*take.skeleton->skeleton)) return puppet;
    for (const auto part : kPuppetParts)
        if (!take.skeleton->skeleton->binding(part)) return puppet;
    auto fitted = fitBodyToSkeleton(puppet, *take.skeleton);
    return fitted ? std::move(fitted).value() : puppet;
}

} // namespace bunraku::analysis
