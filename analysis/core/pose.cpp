#include "analysis/core/pose.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bunraku::analysis {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double wrapTo180(double degrees)
{
    double w = std::remainder(degrees, 360.0);
    if (w <= -180.0) w += 360.0;
    return w;
}

/// The value equal to `angle` modulo 360 closest to `reference`.
double closestTurn(double angle, double reference) { return reference + std::remainder(angle - reference, 360.0); }

} // namespace

Eigen::Quaterniond rotationFromYawPitchRoll(const YawPitchRoll& a)
{
    return (Eigen::AngleAxisd(a.yaw * kDeg, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(a.pitch * kDeg, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(a.roll * kDeg, Eigen::Vector3d::UnitX()))
        .normalized();
}

YawPitchRoll yawPitchRollFromRotation(const Eigen::Quaterniond& rotation)
{
    // R = Rz(y) Ry(p) Rx(r): R(2,0) = -sin p, R(1,0)/R(0,0) = tan y, R(2,1)/R(2,2) = tan r.
    const Eigen::Matrix3d R = rotation.normalized().toRotationMatrix();
    YawPitchRoll a;
    const double sp = std::clamp(-R(2, 0), -1.0, 1.0);
    const double cp = std::hypot(R(0, 0), R(1, 0));
    a.pitch = std::atan2(sp, cp) / kDeg;
    if (cp > 1e-9) {
        a.yaw = std::atan2(R(1, 0), R(0, 0)) / kDeg;
        a.roll = std::atan2(R(2, 1), R(2, 2)) / kDeg;
    } else {
        // Gimbal lock: only yaw -+ roll is defined; put it all in yaw.
        a.roll = 0.0;
        a.yaw = std::atan2(-R(0, 1), R(1, 1)) / kDeg;
    }
    a.yaw = wrapTo180(a.yaw);
    a.roll = wrapTo180(a.roll);
    return a;
}

YawPitchRoll nearestEquivalent(const YawPitchRoll& angles, const YawPitchRoll& previous)
{
    auto distance = [&](const YawPitchRoll& c) {
        return std::abs(c.yaw - previous.yaw) + std::abs(c.pitch - previous.pitch) + std::abs(c.roll - previous.roll);
    };
    YawPitchRoll first{closestTurn(angles.yaw, previous.yaw), closestTurn(angles.pitch, previous.pitch),
                       closestTurn(angles.roll, previous.roll)};
    YawPitchRoll second{closestTurn(angles.yaw + 180.0, previous.yaw), closestTurn(180.0 - angles.pitch, previous.pitch),
                        closestTurn(angles.roll + 180.0, previous.roll)};
    return distance(second) < distance(first) ? second : first;
}

RigidTransform partPose(const Take& take, Eigen::Index frame, Eigen::Index c)
{
    const auto row = take.values.row(frame);
    RigidTransform pose;
    pose.translation = Eigen::Vector3d(row(c), row(c + 1), row(c + 2));
    pose.rotation = rotationFromYawPitchRoll(YawPitchRoll{row(c + 3), row(c + 4), row(c + 5)});
    return pose;
}

void setPartPose(Take& take, Eigen::Index frame, Eigen::Index c, const RigidTransform& world_T_part)
{
    YawPitchRoll a = yawPitchRollFromRotation(world_T_part.rotation);
    if (frame > 0) {
        const auto prev = take.values.row(frame - 1);
        a = nearestEquivalent(a, YawPitchRoll{prev(c + 3), prev(c + 4), prev(c + 5)});
    }
    auto row = take.values.row(frame);
    row(c) = world_T_part.translation.x();
    row(c + 1) = world_T_part.translation.y();
    row(c + 2) = world_T_part.translation.z();
    row(c + 3) = a.yaw;
    row(c + 4) = a.pitch;
    row(c + 5) = a.roll;
}

} // namespace bunraku::analysis
