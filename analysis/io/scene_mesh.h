#pragma once
/// The skinned meshes of a scene file as the file gives them (its units and axes, each mesh in
/// its own space), before scene_take.cpp binds them to the take's skeleton
/// (analysis/core/skeleton_mesh.h). glTF's are read here from the document and its buffers
/// (assimp never sees them: gltf_slim.h); FBX's and Collada's through assimp in scene_take.cpp.
/// Private to analysis/io.

#include "analysis/core/result.h"

#include <nlohmann/json_fwd.hpp>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis::io {

/// One skinned mesh: a vertex goes to sum_k w_k world(bone_k) * offsets[bone_k] * position.
struct FileSkin {
    std::string name;
    std::vector<Eigen::Vector3f> positions; ///< the mesh's space, file units
    std::vector<Eigen::Vector3f> normals;   ///< per vertex; zero where the file has none (made from the triangles)
    std::vector<std::uint32_t> indices;     ///< triangles
    /// Per vertex the four largest influences: indices into boneNames (-1 unused) and weights
    /// (as the file gives them, not yet normalised).
    std::vector<std::array<std::int32_t, 4>> bones;
    std::vector<Eigen::Vector4f> weights;
    std::vector<std::string> boneNames;      ///< the nodes of the bones
    std::vector<Eigen::Matrix4d> offsets;    ///< per bone: mesh space -> bone space at bind
    std::size_t extraInfluences = 0;         ///< influences beyond a vertex's four largest, dropped
    /// Where the mesh's space stands in the file's world at bind (FBX, Collada: the global rest
    /// transform of the node holding it, which assimp's offsets include); unset for glTF, whose
    /// mesh space is the bind space of the skin: the reference bone's rest x offset then.
    std::optional<Eigen::Matrix4d> meshToWorld;
};

struct FileSkins {
    std::vector<FileSkin> skins;
    std::vector<std::string> notes; ///< meshes dropped and why
    int unskinnedMeshes = 0;        ///< meshes without a skin (props), not read
};

/// Sizes the per-vertex arrays for `vertices` vertices (no influence yet).
void resizeInfluences(FileSkin& skin, std::size_t vertices);
/// Adds a bone's weight on a vertex, keeping its four largest.
void addInfluence(FileSkin& skin, std::size_t vertex, int bone, float weight);

/// The skinned meshes of a glTF document (nodes with a mesh and a skin; triangle primitives),
/// `buffers` the bytes of each of its buffers (empty views where unknown). A mesh whose data is
/// unusable (an accessor outside its buffer, a joint index outside its skin, a sparse accessor, a
/// primitive that is not triangles) is dropped with a note naming it; nothing allocated beyond
/// what the buffers hold.
FileSkins readGltfSkins(const nlohmann::json& document, const std::vector<std::string_view>& buffers);

/// Standard base64 (data URIs); nullopt-like empty result and `ok` false on a bad character.
std::string decodeBase64(std::string_view text, bool& ok);

} // namespace bunraku::analysis::io
