#pragma once
/// The layout of the puppet's articulated rig (analysis/skeleton/puppet_rig_fit.h fits it to
/// takes of the 24 puppet channels): its joints' names and parents and where the puppet's parts
/// sit on them. In core so that a reader recognises a rig the workbench wrote (docs/FORMATS.md).

#include "analysis/core/skeleton.h"

#include <array>
#include <optional>
#include <vector>

namespace bunraku::analysis {

/// Joint names of the fitted rig (docs/FORMATS.md): the root carries the shoulder part; the arm
/// part sits at a joint of its own that never turns (its sensor on the arm), so that a BVH or
/// glTF file of the rig holds every part.
inline constexpr const char* kRigRootJoint = "torso";
inline constexpr const char* kRigNeckJoint = "neck";
inline constexpr const char* kRigShoulderJoint = "shoulder_joint";
inline constexpr const char* kRigArmSensorJoint = "arm_sensor";
inline constexpr const char* kRigWristJoint = "wrist";

/// The fitted rig's skeleton name: a rig is the puppet's own body, not a performer's skeleton
/// (the puppet is drawn and exported as itself, not fitted to it).
inline constexpr const char* kPuppetRigName = "puppet rig";
/// True for a skeleton laid out as fitPuppetRig makes it (joints torso, neck, neck_End,
/// shoulder_joint, arm_sensor, wrist, wrist_End with its parents), whatever its name: a rig read
/// back from a file the workbench wrote is the rig.
bool isPuppetRig(const Skeleton& skeleton);
/// The part bindings of a skeleton laid out as the rig (each part at its joint; the head's and
/// the hand's sensors at their End Sites), as fitPuppetRig binds them; nothing for another
/// skeleton. A rig read from a file is bound with these instead of a performer's calibration.
std::optional<std::vector<PartBinding>> puppetRigBindings(const Skeleton& skeleton);


namespace rig {
/// Slots of the rig's joints in Skeleton::joints.
inline constexpr int kRootSlot = 0;
inline constexpr int kNeckSlot = 1;
inline constexpr int kHeadEndSlot = 2;
inline constexpr int kShoulderSlot = 3;
inline constexpr int kArmSensorSlot = 4;
inline constexpr int kWristSlot = 5;
inline constexpr int kHandEndSlot = 6;
inline constexpr int kSlots = 7;

/// Name and parent of every slot, and whether it is an End Site.
struct Slot {
    const char* name;
    int parent;
    bool endSite;
};
inline constexpr std::array<Slot, kSlots> kLayout{{{kRigRootJoint, -1, false},
                                                   {kRigNeckJoint, kRootSlot, false},
                                                   {"neck_End", kNeckSlot, true},
                                                   {kRigShoulderJoint, kRootSlot, false},
                                                   {kRigArmSensorJoint, kShoulderSlot, false},
                                                   {kRigWristJoint, kArmSensorSlot, false},
                                                   {"wrist_End", kWristSlot, true}}};
/// Joint slot of each part (kPuppetParts order: head, shoulder, arm, hand).
inline constexpr std::array<int, 4> kPartSlot{kNeckSlot, kRootSlot, kArmSensorSlot, kWristSlot};
} // namespace rig

} // namespace bunraku::analysis
