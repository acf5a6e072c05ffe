#include "analysis/core/skeleton_calibration.h"

#include "analysis/core/puppet_layout.h"

#include <Eigen/Geometry>

namespace bunraku::analysis {
namespace {

/// The smallest rotation taking the unit vector `from` onto `to` (a half turn about `fallbackAxis`
/// when they are opposite).
Eigen::Quaterniond smallestRotation(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const Eigen::Vector3d& fallbackAxis)
{
    if (from.dot(to) < -1.0 + 1e-9) return Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, fallbackAxis.normalized()));
    return Eigen::Quaterniond::FromTwoVectors(from, to).normalized();
}

} // namespace

Result<std::array<RigidTransform, 4>> anatomicalPartFrames(const SkeletonLandmarks& l, BodySide side, const std::string& skeletonName)
{
    const std::string name = skeletonName.empty() ? std::string("skeleton") : skeletonName;
    const auto fail = [&](const std::string& what) {
        return makeError(ErrorCode::Numerical, name + ": cannot calibrate the puppet parts: " + what);
    };
    const Eigen::Vector3d trunk = l.neckBase - l.hips;
    if (trunk.norm() < 1e-6) return fail("the hips and the base of the neck coincide");
    const Eigen::Vector3d z = trunk.normalized();
    // Towards the performer's left: from the right shoulder to the left one.
    Eigen::Vector3d across;
    if (l.otherShoulderFound) {
        across = l.otherShoulder - l.boundShoulder;
        if (side == BodySide::Left) across = -across;
    } else {
        // One arm only: away from the spine line on the bound side.
        const Eigen::Vector3d out = l.boundShoulder - l.neckBase;
        across = side == BodySide::Right ? Eigen::Vector3d(-out) : out;
    }
    Eigen::Vector3d y = across - across.dot(z) * z;
    if (y.norm() < 1e-6) return fail("the shoulders lie on the line of the spine");
    y.normalize();
    const Eigen::Vector3d x = y.cross(z);
    Eigen::Matrix3d world_R_shoulder;
    world_R_shoulder << x, y, z;
    const Eigen::Quaterniond shoulder(world_R_shoulder);

    const Eigen::Vector3d headUp = l.headTop - l.neck;
    const Eigen::Vector3d forearm = l.wrist - l.elbow;
    const Eigen::Vector3d palm = l.fingerTip - l.wrist;
    if (headUp.norm() < 1e-6) return fail("the head has no length");
    if (forearm.norm() < 1e-6) return fail("the arm joint and the hand joint coincide");
    if (palm.norm() < 1e-6) return fail("the hand has no length");
    const Eigen::Quaterniond head = smallestRotation(z, headUp.normalized(), x) * shoulder;
    const Eigen::Quaterniond arm = smallestRotation(x, forearm.normalized(), z) * shoulder;
    const Eigen::Vector3d armX = arm * Eigen::Vector3d::UnitX();
    const Eigen::Quaterniond hand = smallestRotation(armX, palm.normalized(), arm * Eigen::Vector3d::UnitZ()) * arm;
    return std::array<RigidTransform, 4>{RigidTransform{head.normalized(), l.head}, RigidTransform{shoulder.normalized(), l.chest},
                                         RigidTransform{arm.normalized(), l.elbow}, RigidTransform{hand.normalized(), l.wrist}};
}

Result<std::vector<PartBinding>> calibratePartBindings(const SkeletalMotion& motion, const PartJoints& parts,
                                                       const CalibrationOptions& options)
{
    auto landmarks = findLandmarks(motion, parts, options.referenceFrame);
    if (!landmarks) return landmarks.error();
    auto frames = anatomicalPartFrames(*landmarks, options.side, motion.skeleton->name);
    if (!frames) return frames.error();
    const auto poses = motion.worldPoses(options.referenceFrame);
    std::vector<PartBinding> bindings;
    for (std::size_t p = 0; p < 4; ++p) {
        const RigidTransform& world_T_joint = poses[std::size_t(parts[p])];
        RigidTransform joint_T_part = world_T_joint.inverse() * (*frames)[p];
        joint_T_part.translation.setZero(); // the part's origin is its joint (exactly)
        joint_T_part.rotation.normalize();
        bindings.push_back(PartBinding{std::string(kPuppetParts[p]), parts[p], joint_T_part});
    }
    return bindings;
}

SkeletalMotion withPartBindings(const SkeletalMotion& motion, std::vector<PartBinding> bindings)
{
    auto skeleton = std::make_shared<Skeleton>(*motion.skeleton);
    skeleton->parts = std::move(bindings);
    SkeletalMotion out = motion;
    out.skeleton = std::move(skeleton);
    return out;
}

} // namespace bunraku::analysis
