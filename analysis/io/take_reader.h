#pragma once
/// One entry point to import a take from any supported file, chosen by extension:
/// .csv (take_csv.h), .bvh (bvh_import.h, puppet parts), .txt/.fastrak/.fst (fastrak.h), and
/// .fbx/.glb/.gltf/.dae (scene_take.h, then the BVH import).

#include "analysis/io/bvh_import.h"
#include "analysis/io/fastrak.h"
#include "analysis/io/scene_take.h"
#include "analysis/io/take_csv.h"

#include <filesystem>

namespace bunraku::analysis::io {

enum class TakeFileFormat { Csv, Bvh, Fastrak, Scene, Unknown };

/// By extension, case-insensitive.
TakeFileFormat takeFileFormat(const std::filesystem::path& file);

enum class BvhTakeLayout { PuppetParts, AllJoints };

struct ImportOptions {
    TakeCsvOptions csv;
    BvhImportOptions bvh;
    BvhTakeLayout bvhLayout = BvhTakeLayout::PuppetParts;
    FastrakOptions fastrak;
    /// FBX, glTF and Collada: which animation, the rate without one in the file.
    SceneTakeOptions scene;
};

/// The BVH import options a scene take (scene_take.h) is imported with: `options` with its
/// axes, units and position mode those of the converted BvhFile (y up, cm, positions replace
/// offsets), the part map, side, labels and calibration frame kept.
BvhImportOptions sceneBvhOptions(const BvhImportOptions& options);

/// The file's skeleton and motion as BVH (bvh.h), for any format that has one: a .bvh file read,
/// or a scene file converted (scene_take.h, with what was converted in `info` when given).
/// Unsupported for other formats.
Result<BvhFile> readSkeletalFile(const std::filesystem::path& file, const ImportOptions& options = {}, const RunControl& control = {},
                                 SceneTakeInfo* info = nullptr);

/// Reads a take of any supported format; Unsupported error for unknown extensions. A BVH or
/// scene file's reading and import report their progress to `control` and stop when it asks
/// (Cancelled). A scene file is imported as its converted BvhFile with sceneBvhOptions.
Result<Take> readTakeFile(const std::filesystem::path& file, const ImportOptions& options = {}, const RunControl& control = {});
/// Writes a take as .csv or .bvh by extension (atomic). A take with a skeleton goes to BVH on
/// that skeleton (bvh_skeleton_export.h), one without in the part layout (bvh_export.h).
Status writeTakeFile(const Take& take, const std::filesystem::path& file);

} // namespace bunraku::analysis::io
