#pragma once
/// BVH to workbench takes: a joint map chooses which joints become the puppet's 4 parts, and a
/// fixed axis change plus a unit scale bring the file's world into the workbench convention
/// (right-handed, z up, x towards the partner = the performer's forward, cm). docs/FORMATS.md.

#include "analysis/core/skeleton.h"
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
/// The first built-in map (Bandai, CMU, Mixamo, generic) whose 4 joints all exist.
std::optional<JointMap> defaultJointMap(const BvhSkeleton& skeleton);

/// The file's up axis. Y up: the performer faces +Z (the BVH custom). Z up: the file is taken
/// to be in workbench axes already (x forward, as bvh_export.h writes).
enum class BvhUpAxis { Auto, Y, Z };

struct BvhImportOptions {
    /// When unset, defaultJointMap is used; parts left empty are filled from it too.
    std::optional<JointMap> jointMap;
    BvhUpAxis upAxis = BvhUpAxis::Auto;
    /// Centimetres per file unit (1 for cm, 100 for metres, 2.54 for inches).
    double unitScale = 1.0;
    BvhKinematicsOptions kinematics;
    TakeLabels labels;
};

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
/// the source's channels and axes kept for writing it back. `parts` binds the puppet parts of
/// `joints` (when given) with the identity calibration.
Result<std::shared_ptr<const SkeletalMotion>> bvhToSkeletalMotion(const BvhFile& file, const BvhImportOptions& options = {},
                                                                  const std::array<int, 4>* joints = nullptr);

/// The 24-channel puppet take (head.x ... hand.roll), angles continuous, rate 1/Frame Time.
Result<Take> bvhToPuppetTake(const BvhFile& file, const BvhImportOptions& options = {});
/// One 6-DOF part per joint (End Sites excluded), named as in the file, angles continuous.
Result<Take> bvhToJointTake(const BvhFile& file, const BvhImportOptions& options = {});

} // namespace bunraku::analysis::io
