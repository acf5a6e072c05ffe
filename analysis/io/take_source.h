#pragma once
/// What a path names, read as `bunraku info` and `convert` read it: a corpus folder, or a
/// one-take corpus made of a take file of any supported format (CSV, FASTRAK, BVH, and FBX,
/// glTF, Collada as the BVH they convert to), with what the reading found out about a skeletal
/// file (units, up axis, part map, the scene's animations and mesh) and its description as JSON.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/io/scene_take.h"
#include "analysis/io/take_reader.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace bunraku::analysis::io {

/// A skeletal file whose puppet parts cannot be mapped: an error, or (`info` describes any
/// valid BVH) an empty corpus with TakeSource::mapError saying why.
enum class UnmappedSkeleton { Error, Describe };

struct TakeSource {
    Corpus corpus;
    bool isCorpus = false;
    std::string format; ///< corpus, csv, fastrak, bvh, fbx, gltf or collada
    std::unique_ptr<BvhFile> bvh; ///< a skeletal file, parsed once
    std::shared_ptr<const PartMap> map; ///< the BVH part map used
    std::string mapError;
    BvhUnitsGuess units;
    double cmPerUnit = 1.0;
    BvhUpAxis upAxis = BvhUpAxis::Y;
    std::optional<SceneTakeInfo> scene; ///< FBX, glTF, Collada: what was converted
};

/// The folder's corpus (NotFound without corpus.json), else the file's take read with `options`
/// (NotFound when nothing is at `path`).
Result<TakeSource> readTakeSource(const std::filesystem::path& path, const ImportOptions& options,
                                  UnmappedSkeleton unmapped = UnmappedSkeleton::Error);

/// The part map for reports: {"head": {"joint": ..., "found_by": ...}, ..., "side": ...}.
nlohmann::json partMapJson(const PartMap& map);
/// The skeletal file's own description: hierarchy, channel orders, frames, rate, units and axes,
/// the part map (or why there is none) and a scene file's animations, units and mesh.
nlohmann::json skeletalFileJson(const TakeSource& source);
/// The same as lines of text (`bunraku info`): a scene's animation and mesh, the BVH's counts, rate,
/// units, part map and its joint hierarchy with each joint's channels.
std::string skeletalFileText(const TakeSource& source);

} // namespace bunraku::analysis::io
