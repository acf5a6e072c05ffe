#pragma once
/// BVH to workbench takes: a joint map chooses which joints become the puppet's 4 parts, and a
/// fixed axis change plus a unit scale bring the file's world into the workbench convention
/// (right-handed, z up, x towards the partner = the performer's forward, cm). docs/FORMATS.md.

#include "analysis/core/skeleton.h"
#include "analysis/core/skeleton_anatomy.h"
#include "analysis/core/take.h"
#include "analysis/io/bvh.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis::io {

/// Joint names for head, shoulder, arm, hand (puppet part order).
struct JointMap {
    std::array<std::string, 4> joints;
};

/// Parses "head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R" (any subset; unnamed parts
/// keep `base`'s joint). Errors name the bad item.
Result<JointMap> parseJointMap(const std::string& text, const JointMap& base = {});
/// Reads a JSON joint map: {"head": "Head", "shoulder": "Chest", "arm": "...", "hand": "..."}.
Result<JointMap> readJointMapJson(const std::filesystem::path& file, const JointMap& base = {});
/// The automatic part map of the skeleton (bvh_joint_map.h: names, then topology; right side;
/// the rest pose's geometry), or nullopt when it finds no joint for some part.
std::optional<JointMap> defaultJointMap(const BvhSkeleton& skeleton);

/// The file's up axis. Y up: the performer faces +Z (the BVH custom). Z up: the file is taken
/// to be in workbench axes already (x forward, as bvh_export.h writes).
enum class BvhUpAxis { Auto, Y, Z };

struct BvhImportOptions {
    /// Parts named here take these joints; the others (all, when unset) come from the automatic
    /// part map (bvh_joint_map.h).
    std::optional<JointMap> jointMap;
    BvhUpAxis upAxis = BvhUpAxis::Auto;
    /// Centimetres per file unit (1 for cm, 100 for metres, 2.54 for inches).
    double unitScale = 1.0;
    /// When true, unitScale is replaced by guessBvhUnits' choice (metres, millimetres or cm).
    bool guessUnits = false;
    BvhKinematicsOptions kinematics;
    TakeLabels labels;
    /// The limbs the puppet's arm and hand follow (`--side left`).
    BodySide side = BodySide::Right;
    /// The frame whose pose calibrates the part frames (skeleton_calibration.h).
    Eigen::Index calibrationFrame = 0;
};

/// What the skeleton's size says about the file's length unit.
struct BvhUnitsGuess {
    std::string unit = "cm";  ///< "m", "mm", "cm" or "in"
    double cmPerUnit = 1.0;   ///< 100, 0.1, 1 or 2.54
    double height = 0.0;      ///< the joints' extent along the up axis at the first frame, file units
    std::string note;         ///< why, for reports
};
/// A performer's joints span about 1.2-2 m standing: an extent below 5 units is metres, from
/// 500 to 5000 millimetres, anything else centimetres. An extent of 40-100 units is a small
/// figure in cm (a puppet, a child) or a person in inches: a take of 2 s or more whose root
/// travels more than the figure's height tells them apart by its pace (a walk's Froude number
/// v^2 / (g L), L = 0.53 of the height, stays near 0.25: below 0.1 in centimetres it is inches);
/// otherwise cm, noted.
BvhUnitsGuess guessBvhUnits(const BvhFile& file, BvhUpAxis upAxis = BvhUpAxis::Auto);
/// The unit scale an import with `options` uses (guessBvhUnits when guessUnits is set).
double bvhUnitScale(const BvhFile& file, const BvhImportOptions& options);

/// The up axis actually used: Auto picks Z when the joints of the first frame (or of the rest
/// pose without frames) spread further along Z than along Y, else Y.
BvhUpAxis resolveUpAxis(const BvhFile& file, BvhUpAxis requested);
/// world_R_file of the fixed axis change. Y up: (x, y, z)_file -> (z, x, y)_world, i.e. file +Z
/// (forward) -> world +x, file +X (left) -> world +y, file +Y (up) -> world +z. Z up: identity.
Eigen::Quaterniond bvhAxisChange(BvhUpAxis upAxis);

/// world_T_joint of every joint (workbench axes and cm) at one frame. The part frames are
/// re-expressed in world axes too: world_T_joint = C * file_T_joint * C^-1 with scaled translation.
std::vector<RigidTransform> bvhWorkbenchPoses(const BvhFile& file, Eigen::Index frame, BvhUpAxis upAxis,
                                              double unitScale, const BvhKinematicsOptions& kinematics = {});

/// 1 / frameTime, snapped to the nearest whole number of Hz when within 1e-4 of it (files write
/// 30 fps as "Frame Time: 0.0333333").
double bvhRateHz(double frameTime);

/// The file's whole skeleton and motion in workbench axes and cm (analysis/core/skeleton.h):
/// offsets and local poses re-expressed as C * file_T_joint * C^-1 with scaled translations,
/// the source's channels and axes kept for writing it back. When `joints` is given the puppet
/// parts are bound to those joints with the anatomical calibration of
/// analysis/core/skeleton_calibration.h (reference frame and side from `options`). The control
/// is told the fraction of joints converted and stops the import between two joints.
Result<std::shared_ptr<const SkeletalMotion>> bvhToSkeletalMotion(const BvhFile& file, const BvhImportOptions& options = {},
                                                                  const std::array<int, 4>* joints = nullptr, const RunControl& control = {});

struct PartMap; // bvh_joint_map.h

/// A puppet take read from a BVH file and what the import decided.
struct BvhPuppetImport {
    Take take;
    std::shared_ptr<const PartMap> map; ///< the joints of the four parts and how they were found
    double cmPerUnit = 1.0;             ///< the unit scale used
    BvhUpAxis upAxis = BvhUpAxis::Y;    ///< the up axis used
};
/// bvhToPuppetTake with the decisions it made, for reports; progress and stop as bvhToSkeletalMotion.
Result<BvhPuppetImport> importBvhPuppet(const BvhFile& file, const BvhImportOptions& options = {}, const RunControl& control = {});

/// The 24-channel puppet take (head.x ... hand.roll), angles continuous, rate 1/Frame Time:
/// each part the calibrated frame of its joint (skeleton_calibration.h), the joints chosen by
/// the part map (options.jointMap, then the automatic map), the skeleton kept with the take.
Result<Take> bvhToPuppetTake(const BvhFile& file, const BvhImportOptions& options = {});
/// One 6-DOF part per joint (End Sites excluded), named as in the file, angles continuous.
Result<Take> bvhToJointTake(const BvhFile& file, const BvhImportOptions& options = {});

} // namespace bunraku::analysis::io
