#pragma once
/// Triangle and line meshes on the CPU: what the renderer uploads once per scene. Vertices carry
/// a position (cm), a unit normal and an RGB colour in [0, 1]; the tessellators below build the
/// body description's primitives in their own frame (thesis 6: the puppet's parts).

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace bunraku::render {

struct Vertex {
    glm::vec3 position{0.0f}; ///< cm
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 colour{0.8f};
};

enum class MeshTopology { Triangles, Lines, LineStrip };

struct Mesh {
    MeshTopology topology = MeshTopology::Triangles;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices; ///< triangles: 3 per face; lines: 2 per segment; strip: in order

    bool empty() const { return indices.empty(); }
    /// Appends `other` (same topology), shifting its indices.
    void append(const Mesh& other);
};

/// Applies the affine transform `a_T_b` to a mesh given in frame b (normals by its inverse
/// transpose, renormalised).
Mesh transformed(const Mesh& mesh, const glm::mat4& a_T_b);
/// Sets every vertex colour.
void paint(Mesh& mesh, const glm::vec3& colour);

/// Axis-aligned box centred on the origin with full edge lengths `size` (cm); flat normals.
Mesh boxMesh(const glm::vec3& size);
/// Closed cylinder along z, centred on the origin.
Mesh cylinderMesh(float radius, float length, int segments = 24);
/// Closed truncated cone along z: `bottomRadius` at z = -length/2, `topRadius` at +length/2.
Mesh frustumMesh(float bottomRadius, float topRadius, float length, int segments = 24);
/// Ellipsoid centred on the origin with semi-axes `radii` (cm); smooth normals.
Mesh ellipsoidMesh(const glm::vec3& radii, int slices = 24, int stacks = 16);
/// Square grid of lines in the z = 0 plane, centred on the origin: lines every `spacing` cm out
/// to +-`halfExtent`.
Mesh gridMesh(float halfExtent, float spacing);
/// A polyline through `points` (a line strip).
Mesh polylineMesh(const std::vector<glm::vec3>& points, const glm::vec3& colour);

} // namespace bunraku::render
