#pragma once
/// Rigid poses of parts: the workbench convention is intrinsic Z-Y'-X'' Euler angles in degrees
/// (yaw about z, then pitch about the new y, then roll about the newest x), so
/// world_R_part = Rz(yaw) * Ry(pitch) * Rx(roll), and a translation in cm.

#include "analysis/core/take.h"

#include <Eigen/Geometry>

#include <vector>

namespace bunraku::analysis {

/// A rigid transform a_T_b: maps points in frame b to frame a.
struct RigidTransform {
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();

    Eigen::Vector3d apply(const Eigen::Vector3d& point) const { return rotation * point + translation; }
    RigidTransform operator*(const RigidTransform& b_T_c) const
    {
        return RigidTransform{(rotation * b_T_c.rotation).normalized(), rotation * b_T_c.translation + translation};
    }
    RigidTransform inverse() const
    {
        const Eigen::Quaterniond inv = rotation.conjugate();
        return RigidTransform{inv, -(inv * translation)};
    }
    Eigen::Isometry3d isometry() const
    {
        Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
        m.linear() = rotation.toRotationMatrix();
        m.translation() = translation;
        return m;
    }
};

/// Angles in degrees of the intrinsic Z-Y'-X'' sequence.
struct YawPitchRoll {
    double yaw = 0.0;
    double pitch = 0.0;
    double roll = 0.0;
};

/// world_R_part = Rz(yaw) Ry(pitch) Rx(roll), angles in degrees.
Eigen::Quaterniond rotationFromYawPitchRoll(const YawPitchRoll& angles);
/// The inverse of rotationFromYawPitchRoll with pitch in [-90, 90] and yaw, roll in (-180, 180].
/// At pitch = +-90 (gimbal lock) roll is set to 0 and yaw carries the whole remaining turn.
YawPitchRoll yawPitchRollFromRotation(const Eigen::Quaterniond& rotation);
/// Of the equivalent angle triples of `angles` (adding 360s, and the pitch-mirrored solution
/// yaw+180, 180-pitch, roll+180), the one closest to `previous`: for writing poses back into
/// continuous (unwrapped) channels.
YawPitchRoll nearestEquivalent(const YawPitchRoll& angles, const YawPitchRoll& previous);

/// world_T_part of the part whose 6 channels (x y z yaw pitch roll) start at `firstChannel`.
RigidTransform partPose(const Take& take, Eigen::Index frame, Eigen::Index firstChannel);
/// Writes world_T_part into the 6 channels at `firstChannel`; angles are chosen continuous with
/// the frame before when there is one.
void setPartPose(Take& take, Eigen::Index frame, Eigen::Index firstChannel, const RigidTransform& world_T_part);

} // namespace bunraku::analysis
