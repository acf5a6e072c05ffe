#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace bunraku::analysis;

namespace {
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.angularDistance(b) * 180.0 / std::numbers::pi;
}
} // namespace

TEST_CASE("yaw pitch roll compose as intrinsic Z-Y'-X''", "[pose]")
{
    // Yaw 90: x axis of the part points along world y.
    const auto yaw = rotationFromYawPitchRoll({90, 0, 0});
    CHECK((yaw * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm() < 1e-12);
    // Pitch 90 about y: x axis points down (-z), right-handed.
    const auto pitch = rotationFromYawPitchRoll({0, 90, 0});
    CHECK((pitch * Eigen::Vector3d::UnitX() + Eigen::Vector3d::UnitZ()).norm() < 1e-12);
    // Intrinsic order: yaw 90 then pitch 90 about the new y (= world -x): x goes to -z still.
    const auto both = rotationFromYawPitchRoll({90, 90, 0});
    CHECK((both * Eigen::Vector3d::UnitX() + Eigen::Vector3d::UnitZ()).norm() < 1e-12);
    CHECK((both * Eigen::Vector3d::UnitY() + Eigen::Vector3d::UnitX()).norm() < 1e-12);
}

TEST_CASE("angles survive a round trip through a rotation, including gimbal-adjacent pitch", "[pose]")
{
    const double pitch = GENERATE(-90.0, -89.999, -89.9, -45.0, 0.0, 30.0, 89.9, 89.999, 90.0);
    const double yaw = GENERATE(-179.5, -60.0, 0.0, 120.0, 180.0);
    const double roll = GENERATE(-170.0, 0.0, 45.0);
    const auto q = rotationFromYawPitchRoll({yaw, pitch, roll});
    const auto back = yawPitchRollFromRotation(q);
    // The rotation is what must survive; the angles are unique away from the lock.
    CHECK(angleBetween(rotationFromYawPitchRoll(back), q) < 1e-6);
    CHECK(back.pitch >= -90.0);
    CHECK(back.pitch <= 90.0);
    if (std::abs(pitch) < 89.0) {
        CHECK(std::abs(std::remainder(back.yaw - yaw, 360.0)) < 1e-9);
        CHECK(std::abs(back.pitch - pitch) < 1e-9);
        CHECK(std::abs(std::remainder(back.roll - roll, 360.0)) < 1e-9);
    }
}

TEST_CASE("writing poses back keeps angle channels continuous across +-180", "[pose]")
{
    Take take;
    take.channels = sixDofChannels("head");
    take.values = Eigen::MatrixXd::Zero(40, 6);
    for (int f = 0; f < 40; ++f) {
        RigidTransform pose;
        pose.translation = Eigen::Vector3d(f, 2.0 * f, -f);
        pose.rotation = rotationFromYawPitchRoll({150.0 + 3.0 * f, 10.0, -175.0 - 2.0 * f});
        setPartPose(take, f, 0, pose);
    }
    for (int f = 1; f < 40; ++f) {
        CHECK(std::abs(take.values(f, 3) - take.values(f - 1, 3)) < 10.0);
        CHECK(std::abs(take.values(f, 5) - take.values(f - 1, 5)) < 10.0);
    }
    CHECK(take.values(39, 3) == Approx(150.0 + 3.0 * 39).margin(1e-9));
    CHECK(take.values(39, 5) == Approx(-175.0 - 2.0 * 39).margin(1e-9));
    const auto pose = partPose(take, 39, 0);
    CHECK((pose.translation - Eigen::Vector3d(39, 78, -39)).norm() < 1e-12);
}

TEST_CASE("rigid transforms compose and invert", "[pose]")
{
    RigidTransform a{rotationFromYawPitchRoll({30, -20, 10}), {1, 2, 3}};
    RigidTransform b{rotationFromYawPitchRoll({-70, 5, 60}), {-4, 0.5, 2}};
    const Eigen::Vector3d p(0.3, -1.2, 2.5);
    CHECK(((a * b).apply(p) - a.apply(b.apply(p))).norm() < 1e-12);
    CHECK((a.inverse().apply(a.apply(p)) - p).norm() < 1e-12);
    CHECK(((a * b).isometry() * p - (a.isometry() * b.isometry()) * p).norm() < 1e-12);
}
