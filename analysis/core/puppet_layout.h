#pragma once
/// The Bunraku puppet layout of thesis chapter 2: 4 parts (head, shoulder, arm, hand) x 6 DOF
/// (x, y, z in cm; yaw, pitch, roll in degrees), 24 channels, channel = part * 6 + dof.
/// World frame: right-handed, z up, x towards the partner. Orientation: intrinsic Z-Y'-X''.

#include "analysis/core/take.h"

#include <array>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

inline constexpr int kPuppetPartCount = 4;
inline constexpr int kDofCount = 6;
inline constexpr int kPuppetChannelCount = kPuppetPartCount * kDofCount;

inline constexpr std::array<std::string_view, kPuppetPartCount> kPuppetParts{"head", "shoulder", "arm", "hand"};
inline constexpr std::array<std::string_view, kDofCount> kDofNames{"x", "y", "z", "yaw", "pitch", "roll"};

enum class Dof { X = 0, Y = 1, Z = 2, Yaw = 3, Pitch = 4, Roll = 5 };

inline constexpr int puppetChannel(int part, Dof dof) { return part * kDofCount + int(dof); }
inline constexpr bool isAngleDof(int dof) { return dof >= 3; }

/// The 6 channels of one part, in the order x y z yaw pitch roll, units cm and deg.
std::vector<Channel> sixDofChannels(std::string_view part);
/// The 24 channels head.x ... hand.roll.
std::vector<Channel> puppetChannels();
/// True when the take's channels are exactly the 24 puppet channels in order.
bool hasPuppetLayout(const Take& take);
/// Every part whose 6 channels x..roll appear consecutively in the take, with its first column.
struct SixDofPart {
    std::string part;
    Eigen::Index firstChannel = 0;
};
std::vector<SixDofPart> sixDofParts(const Take& take);
/// The take's points: parts with consecutive x, y, z channels that are not a 6-DOF part's (e.g.
/// the kimono's measured points, `sleeve_right_tip.x/.y/.z`), in channel order. Preprocessing
/// turns and moves them with the body.
std::vector<SixDofPart> pointParts(const Take& take);

} // namespace bunraku::analysis
