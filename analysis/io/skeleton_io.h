#pragma once
/// A take's skeleton in a corpus folder (docs/FORMATS.md, "Skeleton files"): the skeleton as
/// JSON (`<take>.skeleton.json`: hierarchy, names, offsets, source channels and axes, the
/// static translations and the part bindings with their calibration) and its motion as CSV
/// (`<take>.motion.csv`: per frame the moving joints' translations in cm and every joint's
/// rotation as a unit quaternion w x y z). Every number is written with the shortest text that
/// reads back to the same double, so a skeleton read back is bit for bit the one written.

#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

namespace bunraku::analysis::io {

inline constexpr const char* kSkeletonFormatName = "bunraku-skeleton";
inline constexpr int kSkeletonFormatVersion = 1;

/// The skeleton file's JSON text.
std::string skeletonJson(const Skeleton& skeleton, const std::vector<int>& movingJoints,
                         const std::vector<Eigen::Vector3d>& staticTranslations);

/// Both files' texts: the skeleton's JSON and the motion's CSV (validateSkeletalMotion first).
Result<std::pair<std::string, std::string>> formatSkeletalMotion(const SkeletalMotion& motion, double rateHz);

/// Writes both files atomically (validateSkeletalMotion first). `rateHz` times the CSV's rows.
Status writeSkeletalMotion(const SkeletalMotion& motion, double rateHz, const std::filesystem::path& skeletonFile,
                           const std::filesystem::path& motionFile);

/// Reads both files; the motion's rate must be `rateHz`. Errors name the file (and line or JSON
/// path) and what was expected; the result passes validateSkeletalMotion.
Result<std::shared_ptr<const SkeletalMotion>> readSkeletalMotion(const std::filesystem::path& skeletonFile,
                                                                 const std::filesystem::path& motionFile, double rateHz);

} // namespace bunraku::analysis::io
