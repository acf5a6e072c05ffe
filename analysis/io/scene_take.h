#pragma once
/// Takes from animated scene files - FBX (.fbx), glTF 2.0 (.glb, .gltf) and Collada (.dae) -
/// read through assimp (only scene_take.cpp includes it). The file's animated skeleton
/// (hierarchy, names, rest offsets, end sites) and its per-frame joint rotations and
/// translations become a BvhFile in BVH's own convention - y up, the performer facing +Z,
/// centimetres, every joint's frame parallel to the world's at rest - so the take goes through
/// the BVH import (bvh_import.h: part map, calibration, Skeleton and SkeletalMotion) exactly as
/// a BVH file does. Conventions, and what is kept or dropped: docs/FORMATS.md.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/io/bvh.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::analysis::io {

/// The largest scene file read (bytes), checked before reading.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t(1) << 30;
/// The most values (frames x channels) a scene take is sampled into: a duration and rate that
/// ask for more are refused before anything is allocated (2 hours at 60 Hz of a 65-joint
/// Mixamo rig is 28 million).
inline constexpr std::int64_t kMaxSceneSamples = std::int64_t(1) << 26;
/// The rate a file without one of its own and with non-uniform keys is sampled at by default (Hz).
inline constexpr double kDefaultSceneRateHz = 30.0;

enum class SceneFormat { Fbx, Gltf, Collada };

/// The format of a file by its extension (.fbx, .glb, .gltf, .dae; any case), or false.
bool isSceneTakeFile(const std::filesystem::path& file);

struct SceneTakeOptions {
    /// Which animation: its name, or its 0-based index; empty for the first.
    std::string animation;
    /// Sampling rate (Hz) when the file has no rate of its own (glTF, Collada) and its keys are
    /// not uniform in time; otherwise the file's rate is used.
    double rateHz = kDefaultSceneRateHz;
};

/// What the reader found and converted, for `info` and the dialogs.
struct SceneTakeInfo {
    SceneFormat format = SceneFormat::Fbx;
    std::string formatName;              ///< "FBX", "glTF", "Collada"
    std::vector<std::string> animations; ///< every animation's name ("" when unnamed)
    int animation = 0;                   ///< the index read
    std::string unit;                    ///< the file's length unit: "cm", "m", "mm", "in" or "N cm"
    double cmPerUnit = 1.0;              ///< what one file unit is in cm
    std::string upAxis;                  ///< the file's up axis: "+y", "+z", "-x", ...
    std::string rateSource;              ///< "file" (FBX time mode), "keys" (uniform key times) or "option"
    double rateHz = 0.0;                 ///< the rate sampled at
    double startTime = 0.0;              ///< the first key's time (s) = frame 0
    int helperNodesFolded = 0;           ///< FBX pivot nodes ($AssimpFbx$) folded into their joints
    int meshes = 0;                      ///< meshes in the file
    /// The skinned mesh kept for the skeleton (Skeleton::mesh; all the file's skinned meshes
    /// merged): its vertices, triangles and the joints it is weighted to (0 and empty: none).
    std::size_t meshVertices = 0;
    std::size_t meshTriangles = 0;
    std::vector<std::string> meshBones;
    /// What of the meshes was dropped or changed, and why (one line each).
    std::vector<std::string> meshNotes;
    bool scaleDropped = false;           ///< a joint had a non-unit scale (kept in positions, not in the skeleton)
};

struct SceneTake {
    /// y up, +Z forward, cm; joint frames world-aligned at rest; rate of the samples. Its `mesh`:
    /// the file's skinned meshes bound to these joints (docs/FORMATS.md), null without any.
    BvhFile bvh;
    SceneTakeInfo info;
};

/// Reads a scene file's take: a regular file of at most kMaxSceneFileBytes. Errors are one line
/// naming the file: unreadable or malformed files (assimp's reason), files without an animation
/// (meshes but no animation, or no animated node), an unknown --animation, more samples than
/// kMaxSceneSamples. Progress is the fraction of frames sampled; a stop request ends it (Cancelled).
Result<SceneTake> readSceneTake(const std::filesystem::path& file, const SceneTakeOptions& options = {}, const RunControl& control = {});
/// The same from bytes in memory; `extension` (".fbx", ".glb", ".gltf", ".dae") tells the format
/// and `sourceName` names it in messages. A .gltf in memory cannot reach buffers in other files.
Result<SceneTake> parseSceneTake(const std::string& bytes, const std::string& extension, const std::string& sourceName,
                                 const SceneTakeOptions& options = {}, const RunControl& control = {});
/// The names of the file's animations ("" for an unnamed one), in file order, for dialogs.
Result<std::vector<std::string>> listSceneAnimations(const std::filesystem::path& file);

/// "FBX (.fbx);glTF (.glb .gltf);Collada (.dae)" style list of the extensions: ".fbx .glb .gltf .dae".
const std::vector<std::string>& sceneTakeExtensions();

} // namespace bunraku::analysis::io
