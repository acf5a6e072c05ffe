#pragma once
/// The motion axis as channels. Two views of the same world_T_axis:
///  - the thesis's 6 DOF (Table 5.2), for display and graphs: centre x, y, z (cm), equivalent
///    rotation axis x and y components, equivalent rotation angle (deg). Decision: the angle is
///    signed in (-180, 180] and the axis has z >= 0, so the 6 numbers determine the rotation
///    (axis z = sqrt(1 - x^2 - y^2)); at angle 0 the axis is reported as (0, 0, 1).
///  - axis coordinates, for phase and amplitude: centre x, y, z (cm) and the rotation vector
///    angle * axis (deg) made continuous in time. Decision: the thesis's axis components are
///    undefined at small angles (the puppet at rest), so scaling or matching them is
///    ill-posed; the rotation vector carries the same rotation smoothly through zero.

#include "analysis/axis/inertia_axis.h"
#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

inline constexpr int kAxisDofCount = 6;

/// axis.x axis.y axis.z (cm), axis.axis_x axis.axis_y (unit), axis.angle (deg).
std::vector<Channel> axisChannels();
/// axis.x axis.y axis.z (cm), axis.rot_x axis.rot_y axis.rot_z (deg): the axis coordinates.
std::vector<Channel> axisCoordinateChannels();

/// The thesis's 6 channels of one world_T_axis.
Eigen::Matrix<double, 1, 6> axisChannelValues(const RigidTransform& world_T_axis);
/// The inverse of axisChannelValues (axis x, y clamped to the unit disc).
RigidTransform axisFromChannelValues(const Eigen::Matrix<double, 1, 6>& values);

/// The axis take: part "axis", the thesis's 6 channels per frame, the source's rate and labels
/// (source "axis of <source>"). Graphs and exports treat it as any take.
Take axisTake(const MotionAxis& axis);
/// world_T_axis per frame from an axis take (NotFound when a channel is missing).
Result<std::vector<RigidTransform>> axisPosesFromTake(const Take& take);

/// frames x 6 axis coordinates: centre (cm) and rotation vector (deg), continuous over time (a
/// rotation-vector jump of 360 deg is taken back).
Eigen::MatrixXd axisCoordinates(const std::vector<RigidTransform>& world_T_axis);
/// world_T_axis from one row of axis coordinates.
RigidTransform axisFromCoordinates(const Eigen::Ref<const Eigen::RowVectorXd>& coordinates);

} // namespace bunraku::analysis
