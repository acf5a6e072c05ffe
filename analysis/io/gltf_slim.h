#pragma once
/// A glTF file slimmed to what a take reads before assimp sees it (scene_take.cpp).

#include "analysis/core/result.h"

#include <filesystem>
#include <string>

namespace bunraku::analysis::io {

enum class GltfEncoding { Binary, Text };

/// The glTF file without what a take does not use - meshes, skins, materials, textures, images,
/// cameras - in the same encoding: assimp 5.2 crashes on some of it (a skin without
/// inverseBindMatrices, which glTF allows; found by fuzz_scene_take) and reads less. `meshes`
/// gets the file's mesh count. A text file's buffers in other files are read from `folder`
/// (relative names without "..", regular files of at most kMaxSceneFileBytes) and embedded as
/// data URIs, so assimp reads nothing but these bytes; without a folder they are an error.
/// Errors name `source` and say what was expected.
Result<std::string> slimGltf(const std::string& bytes, GltfEncoding encoding, const std::filesystem::path* folder,
                             const std::string& source, int& meshes);

} // namespace bunraku::analysis::io
