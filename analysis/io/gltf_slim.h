#pragma once
/// A glTF file slimmed to what a take reads before assimp sees it (scene_take.cpp).

#include "analysis/core/result.h"

#include <filesystem>
#include <string>

namespace bunraku::analysis::io {

enum class GltfEncoding { Binary, Text };

struct FileSkins; // scene_mesh.h

/// The glTF file without what a take does not use - meshes, skins, materials, textures, images,
/// cameras - in the same encoding: assimp 5.2 crashes on some of it (a skin without
/// inverseBindMatrices, which glTF allows; found by fuzz_scene_take) and reads less. `meshes`
/// gets the file's mesh count. A text file's buffers in other files are read from `folder`
/// (relative names without "..", regular files of at most kMaxSceneFileBytes) and embedded as
/// data URIs, so assimp reads nothing but these bytes; without a folder they are an error.
/// Errors name `source` and say what was expected. With `skins`, the skinned meshes are read
/// first (scene_mesh.h; a mesh that cannot be read is dropped with a note, never an error).
Result<std::string> slimGltf(const std::string& bytes, GltfEncoding encoding, const std::filesystem::path* folder,
                             const std::string& source, int& meshes, FileSkins* skins = nullptr);

} // namespace bunraku::analysis::io
