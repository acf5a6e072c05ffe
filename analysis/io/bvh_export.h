#pragma once
/// BVH export of a take whose parts are 6-DOF (x y z yaw pitch roll): a skeleton with a root
/// named kBvhExportRootName at the origin (6 channels, always 0) and every part a 6-channel
/// child joint of it
/// (Xposition Yposition Zposition Zrotation Yrotation Xrotation), zero OFFSET, so each part's
/// channels are its world pose exactly. Z up, x forward, cm, degrees. Re-imports (scale 1) to the
/// same world poses: BvhUpAxis::Auto recognises the root name as Z up.

#include "analysis/core/take.h"
#include "analysis/io/bvh.h"

#include <filesystem>

namespace bunraku::analysis::io {

inline constexpr const char* kBvhExportRootName = "bunraku_world_z_up";

/// The BVH structure of a take (every 6-DOF part of it, see sixDofParts).
Result<BvhFile> takeToBvh(const Take& take);
/// Writes the take as BVH atomically.
Status writeTakeBvh(const Take& take, const std::filesystem::path& file);

} // namespace bunraku::analysis::io
