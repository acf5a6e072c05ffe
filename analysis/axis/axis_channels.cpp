#include "analysis/axis/axis_channels.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace bunraku::analysis {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
}

std::vector<Channel> axisChannels()
{
    return {{"axis", "x", "cm"},      {"axis", "y", "cm"},      {"axis", "z", "cm"},
            {"axis", "axis_x", "1"}, {"axis", "axis_y", "1"}, {"axis", "angle", "deg"}};
}

std::vector<Channel> axisCoordinateChannels()
{
    return {{"axis", "x", "cm"},      {"axis", "y", "cm"},      {"axis", "z", "cm"},
            {"axis", "rot_x", "deg"}, {"axis", "rot_y", "deg"}, {"axis", "rot_z", "deg"}};
}

Eigen::Matrix<double, 1, 6> axisChannelValues(const RigidTransform& world_T_axis)
{
    Eigen::Matrix<double, 1, 6> values;
    values.head<3>() = world_T_axis.translation.transpose();
    const Eigen::AngleAxisd angleAxis(world_T_axis.rotation.normalized());
    double angle = angleAxis.angle(); // [0, pi]
    Eigen::Vector3d direction = angleAxis.axis();
    if (angle < 1e-12) {
        angle = 0.0;
        direction = Eigen::Vector3d::UnitZ();
    } else if (direction.z() < 0.0) {
        direction = -direction;
        angle = -angle;
    }
    values[3] = direction.x();
    values[4] = direction.y();
    values[5] = angle / kDegree;
    return values;
}

RigidTransform axisFromChannelValues(const Eigen::Matrix<double, 1, 6>& values)
{
    Eigen::Vector2d planar(values[3], values[4]);
    if (planar.squaredNorm() > 1.0) planar.normalize();
    const Eigen::Vector3d direction(planar.x(), planar.y(), std::sqrt(std::max(0.0, 1.0 - planar.squaredNorm())));
    RigidTransform pose;
    pose.translation = values.head<3>().transpose();
    pose.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(values[5] * kDegree, direction.normalized())).normalized();
    return pose;
}

Take axisTake(const MotionAxis& axis)
{
    Take take;
    take.rateHz = axis.rateHz;
    take.channels = axisChannels();
    take.labels = axis.labels;
    take.labels.source = "axis of " + (axis.labels.source.empty() ? axis.labels.function : axis.labels.source);
    take.values.resize(axis.frameCount(), kAxisDofCount);
    for (Eigen::Index frame = 0; frame < axis.frameCount(); ++frame)
        take.values.row(frame) = axisChannelValues(axis.world_T_axis[std::size_t(frame)]);
    return take;
}

Result<std::vector<RigidTransform>> axisPosesFromTake(const Take& take)
{
    std::vector<Eigen::Index> columns;
    for (const Channel& channel : axisChannels()) {
        const auto column = take.channelIndex(channel.part, channel.dof);
        if (!column) return makeError(ErrorCode::NotFound, "take " + take.displayName() + " has no channel " + channel.name());
        columns.push_back(*column);
    }
    std::vector<RigidTransform> poses(std::size_t(take.frameCount()));
    for (Eigen::Index frame = 0; frame < take.frameCount(); ++frame) {
        Eigen::Matrix<double, 1, 6> values;
        for (int k = 0; k < kAxisDofCount; ++k) values[k] = take.values(frame, columns[std::size_t(k)]);
        poses[std::size_t(frame)] = axisFromChannelValues(values);
    }
    return poses;
}

Eigen::MatrixXd axisCoordinates(const std::vector<RigidTransform>& world_T_axis)
{
    Eigen::MatrixXd coordinates(Eigen::Index(world_T_axis.size()), kAxisDofCount);
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (std::size_t frame = 0; frame < world_T_axis.size(); ++frame) {
        const Eigen::AngleAxisd angleAxis(world_T_axis[frame].rotation.normalized());
        Eigen::Vector3d rotation = angleAxis.angle() * angleAxis.axis();
        if (frame > 0 && angleAxis.angle() > 1e-9) {
            // the equivalent rotation vectors are (angle + 2 pi k) axis: take the one nearest the previous
            const double turn = 2.0 * std::numbers::pi;
            const double k = std::round((previous.dot(angleAxis.axis()) - angleAxis.angle()) / turn);
            rotation = (angleAxis.angle() + k * turn) * angleAxis.axis();
        }
        previous = rotation;
        coordinates.row(Eigen::Index(frame)).head<3>() = world_T_axis[frame].translation.transpose();
        coordinates.row(Eigen::Index(frame)).tail<3>() = rotation.transpose() / kDegree;
    }
    return coordinates;
}

RigidTransform axisFromCoordinates(const Eigen::Ref<const Eigen::RowVectorXd>& coordinates)
{
    RigidTransform pose;
    pose.translation = coordinates.head<3>().transpose();
    const Eigen::Vector3d rotation = coordinates.tail<3>().transpose() * kDegree;
    const double angle = rotation.norm();
    pose.rotation = angle < 1e-15 ? Eigen::Quaterniond::Identity()
                                  : Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation / angle)).normalized();
    return pose;
}

} // namespace bunraku::analysis
