#pragma once
/// The demo puppet's kinematic rig: 16 motion parameters (a whole-body pose about the waist
/// held by the puppeteer, and head, arm and hand joints) mapped by forward kinematics onto the
/// 24 sensor channels (4 parts x x y z yaw pitch roll, cm and degrees, z up, x towards the
/// partner, y to the puppet's left). Keeping every part on one rigid chain keeps the hand near
/// the arm and the head above the shoulder whatever the gains do.

#include <Eigen/Core>

#include <array>
#include <string_view>

namespace bunraku::analysis::synth {

/// The generator's motion parameters; displacements and gains are per parameter.
enum class RigParameter {
    BodyX,      ///< cm, waist translation towards the partner
    BodyY,      ///< cm, waist translation to the left
    BodyZ,      ///< cm, waist translation up
    BodyYaw,    ///< deg, whole body about the vertical (positive turns left)
    BodyPitch,  ///< deg, bow about the waist (positive leans forward and down)
    BodyRoll,   ///< deg, sideways lean
    HeadYaw,    ///< deg, head relative to the shoulder (positive looks left, away from the hand)
    HeadPitch,  ///< deg, nod (positive looks down)
    HeadRoll,   ///< deg, head tilt
    ArmYaw,     ///< deg, right upper arm relative to the shoulder (positive swings inwards)
    ArmPitch,   ///< deg, arm elevation (positive points further down)
    ArmRoll,    ///< deg, arm twist
    ArmReach,   ///< cm, extension of the forearm (elbow straightening)
    HandYaw,    ///< deg, wrist relative to the arm
    HandPitch,  ///< deg, wrist flexion (positive tips the fingers down)
    HandRoll,   ///< deg, forearm rotation (positive turns the palm up and out: the release)
};
inline constexpr int kRigParameterCount = 16;

inline constexpr std::array<std::string_view, kRigParameterCount> kRigParameterNames{
    "body.x",   "body.y",    "body.z",   "body.yaw", "body.pitch", "body.roll", "head.yaw",   "head.pitch",
    "head.roll", "arm.yaw", "arm.pitch", "arm.roll", "arm.reach",  "hand.yaw",  "hand.pitch", "hand.roll"};

inline constexpr int rigIndex(RigParameter p) { return int(p); }

/// The rest pose's parameters (all zero except the arm and hand's natural carriage).
Eigen::VectorXd restParameters();

/// Forward kinematics: the 24 channel values (head, shoulder, arm, hand; x y z yaw pitch roll)
/// of one parameter vector. Orientations are intrinsic Z-Y'-X'' angles with pitch in
/// (-90, 90) and yaw, roll in (-180, 180].
Eigen::Matrix<double, 1, 24> rigChannels(const Eigen::VectorXd& parameters);

} // namespace bunraku::analysis::synth
