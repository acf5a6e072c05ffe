#include "analysis/core/skeleton.h"
#include "analysis/core/puppet_layout.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;

namespace {

/// root -> spine (10 cm up) -> arm (5 cm along +y) -> End Site (5 cm along +y).
std::shared_ptr<Skeleton> chainSkeleton()
{
    auto skeleton = std::make_shared<Skeleton>();
    skeleton->name = "chain";
    skeleton->joints = {
        {"root", -1, Eigen::Vector3d(0, 0, 0), {JointChannel::Xposition, JointChannel::Yposition, JointChannel::Zposition,
                                                JointChannel::Zrotation, JointChannel::Yrotation, JointChannel::Xrotation}, false},
        {"spine", 0, Eigen::Vector3d(0, 0, 10), {JointChannel::Zrotation, JointChannel::Yrotation, JointChannel::Xrotation}, false},
        {"arm", 1, Eigen::Vector3d(0, 5, 0), {JointChannel::Zrotation, JointChannel::Yrotation, JointChannel::Xrotation}, false},
        {"arm_End", 2, Eigen::Vector3d(0, 5, 0), {}, true},
    };
    return skeleton;
}

Eigen::Quaterniond aboutZ(double degrees) { return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ())); }

} // namespace

TEST_CASE("a rest motion places every joint at its offsets down the chain")
{
    const auto motion = makeRestMotion(chainSkeleton(), 3);
    REQUIRE(motion.frameCount() == 3);
    REQUIRE(validateSkeletalMotion(motion).ok());
    const auto poses = motion.worldPoses(2);
    CHECK((poses[3].translation - Eigen::Vector3d(0, 10, 10)).norm() < 1e-12);
}

TEST_CASE("world poses compose local rotations and moving translations")
{
    auto motion = makeRestMotion(chainSkeleton(), 2);
    motion.movingJoints = {0};
    motion.movingTranslations = Eigen::MatrixXd::Zero(2, 3);
    motion.movingTranslations.row(1) << 100, 0, 0;
    motion.rotation(1, 1) = aboutZ(90); // the spine turns the arm from +y to -x
    const auto poses = motion.worldPoses(1);
    CHECK((poses[0].translation - Eigen::Vector3d(100, 0, 0)).norm() < 1e-12);
    CHECK((poses[2].translation - Eigen::Vector3d(95, 0, 10)).norm() < 1e-12);
    CHECK((poses[3].translation - Eigen::Vector3d(90, 0, 10)).norm() < 1e-12);
    CHECK((motion.translation(1, 0) - Eigen::Vector3d(100, 0, 0)).norm() < 1e-12);
    CHECK((motion.translation(1, 2) - Eigen::Vector3d(0, 5, 0)).norm() < 1e-12);
}

TEST_CASE("a bound part's pose is the joint's pose times its calibration")
{
    auto skeleton = chainSkeleton();
    skeleton->parts.push_back({"arm", 2, RigidTransform{aboutZ(-90), Eigen::Vector3d(0, 2, 0)}});
    auto motion = makeRestMotion(skeleton, 1);
    motion.rotation(0, 1) = aboutZ(90);
    const auto part = motion.partPose(0, "arm");
    REQUIRE(part.has_value());
    const auto world = motion.worldPoses(0)[2] * skeleton->parts[0].joint_T_part;
    CHECK((part->translation - world.translation).norm() < 1e-12);
    CHECK(part->rotation.angularDistance(world.rotation) < 1e-12);
    CHECK((part->translation - Eigen::Vector3d(-7, 0, 10)).norm() < 1e-12);
    CHECK(!motion.partPose(0, "head").has_value());
}

TEST_CASE("skeletons and motions with broken structure are refused with the joint named")
{
    auto skeleton = chainSkeleton();
    skeleton->joints[2].parent = 3;
    auto error = validateSkeleton(*skeleton);
    REQUIRE(!error.ok());
    CHECK(error.error().message.find("'arm'") != std::string::npos);

    auto duplicate = chainSkeleton();
    duplicate->joints[2].name = "spine";
    CHECK(!validateSkeleton(*duplicate).ok());

    auto motion = makeRestMotion(chainSkeleton(), 2);
    motion.rotations[5].coeffs() *= 2.0;
    auto bad = validateSkeletalMotion(motion);
    REQUIRE(!bad.ok());
    CHECK(bad.error().message.find("frame 1") != std::string::npos);
}

TEST_CASE("a take's skeleton must have the take's frame count")
{
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(4, kPuppetChannelCount);
    take.skeleton = std::make_shared<SkeletalMotion>(makeRestMotion(chainSkeleton(), 3));
    CHECK(!validateTake(take).ok());
    take.skeleton = std::make_shared<SkeletalMotion>(makeRestMotion(chainSkeleton(), 4));
    CHECK(validateTake(take).ok());
}
