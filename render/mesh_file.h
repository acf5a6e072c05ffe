#pragma once
/// Meshes from files (glTF, OBJ and the other formats assimp reads) for users with scanned
/// puppets: one file per body part, vertices in the part (sensor) frame.

#include "analysis/core/result.h"
#include "render/mesh.h"

#include <glm/glm.hpp>

#include <filesystem>

namespace bunraku::render {

struct MeshFileOptions {
    float scale = 1.0f;              ///< file units to cm (e.g. 100 for metres)
    glm::mat4 part_T_file{1.0f};     ///< applied after scaling: places the file's frame in the part frame
    glm::vec3 colour{0.85f, 0.80f, 0.75f}; ///< used where the file has no vertex colours
};

/// All triangles of all meshes in the file, with smooth normals generated when missing; an Io or
/// Parse error names the file and assimp's message.
analysis::Result<Mesh> loadMeshFile(const std::filesystem::path& file, const MeshFileOptions& options = {});

} // namespace bunraku::render
