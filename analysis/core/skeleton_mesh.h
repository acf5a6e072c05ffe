#pragma once
/// The skinned mesh a file carries for its skeleton (a Mixamo or glTF character's own body),
/// read by analysis/io/scene_take.h and kept with the take's Skeleton (Skeleton::mesh), so the
/// 3D view can show the performer's own body moved by any take on that skeleton (the "File's
/// mesh" figure). Workbench frame (z up, cm), like the skeleton.
///
/// Skinning (what the file formats mean: glTF's and FBX's linear blend skinning): a vertex at
/// `position` in the bind pose goes to  sum_k w_k  world_T_joint(j_k) * inverse(bindPoses[j_k]) * position,
/// the joints' rigid transforms blended linearly (skinSkeletonMesh on the CPU, the shader's
/// linear mode on the GPU).

#include "analysis/core/pose.h"
#include "analysis/core/result.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bunraku::analysis {

struct Skeleton;

/// The most vertices (all meshes of a file together) a skeleton mesh keeps; a file with more has
/// its mesh dropped (a note says so).
inline constexpr std::size_t kMaxSkeletonMeshVertices = std::size_t(1) << 22;
/// The most triangles.
inline constexpr std::size_t kMaxSkeletonMeshTriangles = std::size_t(1) << 23;

struct SkeletonMesh {
    std::vector<Eigen::Vector3f> positions; ///< cm, the bind pose, world
    std::vector<Eigen::Vector3f> normals;   ///< unit, the bind pose, world
    std::vector<std::uint32_t> indices;     ///< triangles
    /// Per vertex up to four indices into Skeleton::joints, and their weights (sum 1, largest
    /// first, unused slots weight 0 on joint 0).
    std::vector<std::array<std::uint16_t, 4>> joints;
    std::vector<Eigen::Vector4f> weights;
    /// Per Skeleton::joints: world_T_joint in the bind pose (identity for joints no vertex uses).
    std::vector<RigidTransform> bindPoses;
    /// The names of Skeleton::joints the mesh was made for (a skeleton of other joints cannot
    /// carry it: meshFitsSkeleton).
    std::vector<std::string> jointNames;
    int fileMeshes = 0; ///< the file's meshes merged into this one

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    /// Indices of the joints some vertex is weighted to, ascending.
    std::vector<int> bonesUsed() const;
};

/// Checks sizes agree, indices and joints are in range, values finite, weights non-negative and
/// summing to 1, bind poses unit.
Status validateSkeletonMesh(const SkeletonMesh& mesh);

/// True when the mesh was made for a skeleton of exactly these joint names.
bool meshFitsSkeleton(const SkeletonMesh& mesh, const Skeleton& skeleton);

/// The skinning transforms world_T_joint * inverse(bind), one per joint.
std::vector<RigidTransform> skeletonMeshSkinning(const SkeletonMesh& mesh, const std::vector<RigidTransform>& world_T_joint);

/// The vertices skinned on the CPU at the joints' world poses (one per Skeleton::joints), by
/// linear blending (as the files mean it, and the shader does): cm, world.
std::vector<Eigen::Vector3d> skinSkeletonMesh(const SkeletonMesh& mesh, const std::vector<RigidTransform>& world_T_joint);

/// The mesh in another frame: p' = world_R_source (scale p); bind poses conjugated the same way.
SkeletonMesh transformedSkeletonMesh(const SkeletonMesh& mesh, const Eigen::Quaterniond& world_R_source, double scale);

} // namespace bunraku::analysis
