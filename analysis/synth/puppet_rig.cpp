#include "analysis/synth/puppet_rig.h"

#include "analysis/core/pose.h"

#include <Eigen/Geometry>

namespace bunraku::analysis::synth {
namespace {

/// Rest geometry in cm: the waist pivot the puppeteer holds, and the offsets of each joint and
/// sensor in its parent's frame (a female puppet of about 70 cm seen from the transmitter).
const Eigen::Vector3d kWaistAtRest(0.0, 0.0, 20.0);
const Eigen::Vector3d kShoulderInBody(0.0, 0.0, 20.0);  ///< shoulder sensor on the torso
const Eigen::Vector3d kNeckInShoulder(1.0, 0.0, 8.0);
const Eigen::Vector3d kHeadInHead(3.0, 0.0, 7.0);       ///< head sensor in the head frame
const Eigen::Vector3d kRightShoulderJoint(0.0, -9.0, -1.0);
constexpr double kArmSensorAlong = 10.0;                ///< along the arm, plus half the reach
constexpr double kWristAlong = 20.0;                    ///< along the arm, plus the reach
const Eigen::Vector3d kHandInHand(4.0, 0.0, 0.0);

RigidTransform transform(const Eigen::Vector3d& translation, double yaw, double pitch, double roll)
{
    return RigidTransform{rotationFromYawPitchRoll(YawPitchRoll{yaw, pitch, roll}), translation};
}

void writePart(Eigen::Matrix<double, 1, 24>& row, int part, const RigidTransform& world_T_part)
{
    const YawPitchRoll a = yawPitchRollFromRotation(world_T_part.rotation);
    row.segment<3>(part * 6) = world_T_part.translation.transpose();
    row(part * 6 + 3) = a.yaw;
    row(part * 6 + 4) = a.pitch;
    row(part * 6 + 5) = a.roll;
}

} // namespace

Eigen::VectorXd restParameters()
{
    Eigen::VectorXd p = Eigen::VectorXd::Zero(kRigParameterCount);
    p(rigIndex(RigParameter::HeadPitch)) = 5.0;
    p(rigIndex(RigParameter::ArmYaw)) = -20.0;
    p(rigIndex(RigParameter::ArmPitch)) = 35.0;
    p(rigIndex(RigParameter::HandYaw)) = 10.0;
    p(rigIndex(RigParameter::HandPitch)) = -25.0;
    p(rigIndex(RigParameter::HandRoll)) = -30.0;
    return p;
}

Eigen::Matrix<double, 1, 24> rigChannels(const Eigen::VectorXd& p)
{
    auto at = [&](RigParameter q) { return p(rigIndex(q)); };
    const Eigen::Vector3d waist =
        kWaistAtRest + Eigen::Vector3d(at(RigParameter::BodyX), at(RigParameter::BodyY), at(RigParameter::BodyZ));
    const RigidTransform world_T_body =
        transform(waist, at(RigParameter::BodyYaw), at(RigParameter::BodyPitch), at(RigParameter::BodyRoll));
    const RigidTransform world_T_shoulder = world_T_body * RigidTransform{Eigen::Quaterniond::Identity(), kShoulderInBody};
    const RigidTransform world_T_head =
        world_T_shoulder *
        transform(kNeckInShoulder, at(RigParameter::HeadYaw), at(RigParameter::HeadPitch), at(RigParameter::HeadRoll)) *
        RigidTransform{Eigen::Quaterniond::Identity(), kHeadInHead};
    const RigidTransform world_T_upperArm =
        world_T_shoulder *
        transform(kRightShoulderJoint, at(RigParameter::ArmYaw), at(RigParameter::ArmPitch), at(RigParameter::ArmRoll));
    const double reach = at(RigParameter::ArmReach);
    const RigidTransform world_T_arm =
        world_T_upperArm * RigidTransform{Eigen::Quaterniond::Identity(), Eigen::Vector3d(kArmSensorAlong + 0.5 * reach, 0, 0)};
    const RigidTransform world_T_hand =
        world_T_upperArm *
        transform(Eigen::Vector3d(kWristAlong + reach, 0, 0), at(RigParameter::HandYaw), at(RigParameter::HandPitch),
                  at(RigParameter::HandRoll)) *
        RigidTransform{Eigen::Quaterniond::Identity(), kHandInHand};

    Eigen::Matrix<double, 1, 24> row;
    writePart(row, 0, world_T_head);
    writePart(row, 1, world_T_shoulder);
    writePart(row, 2, world_T_arm);
    writePart(row, 3, world_T_hand);
    return row;
}

} // namespace bunraku::analysis::synth
