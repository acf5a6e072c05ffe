#pragma once
/// glTF 2.0 binary (.glb) export of a skeletal motion: the joints as a node hierarchy with a
/// skin, one triangle mesh skinned to them (rigidly, each vertex bound to one joint, or smoothly,
/// up to four joints per vertex), and one animation with the take's times. glTF is y up, metres, the asset facing +Z: the workbench's axes map
/// as x (forward) -> +Z, y (left) -> +X, z (up) -> +Y, and cm / 100. Written with Debian's
/// tinygltf. docs/FORMATS.md.

#include "analysis/core/skeleton.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::analysis::io {

/// A triangle mesh carried rigidly by one joint: vertices in that joint's frame (workbench
/// axes, cm), normals unit length, colours RGB in [0, 1].
struct JointMesh {
    int joint = -1; ///< index into Skeleton::joints (not an End Site)
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals;
    std::vector<Eigen::Vector3f> colours;
    std::vector<std::uint32_t> indices; ///< 3 per triangle
};

/// A triangle mesh skinned to up to four joints per vertex (the modelled puppet), in its bind
/// pose: vertices in the frame the bind poses are given in (workbench axes, cm).
struct SkinnedMesh {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals;
    std::vector<Eigen::Vector3f> colours;       ///< RGB in [0, 1]
    std::vector<std::array<int, 4>> joints;     ///< indices into Skeleton::joints (not End Sites)
    std::vector<Eigen::Vector4f> weights;       ///< >= 0, summing to 1 (renormalised when written)
    std::vector<std::uint32_t> indices;         ///< 3 per triangle
    /// world_T_joint of every joint of the skeleton in the bind pose (Skeleton::joints order; End
    /// Sites' entries unused): the inverse bind matrices.
    std::vector<RigidTransform> bindPoses;
};

/// Rigid meshes as one skinned mesh bound in the first frame's pose (each vertex on its joint
/// with weight 1). Errors as skeletalMotionToGlb does for the meshes.
Result<SkinnedMesh> rigidlySkinnedMesh(const SkeletalMotion& motion, const std::vector<JointMesh>& meshes);

/// A mesh that moves by morph targets, not by a skin (glTF's vertex animation; the simulated
/// kimono): its vertices at key times, in the world (workbench axes, cm). The file holds the first
/// key as the mesh and every later key k as morph target k - 1, with an animation channel
/// "weights" whose sampler gives target k - 1 the weight 1 at key k's time and every other target
/// 0 (LINEAR): a client's linear interpolation of the weights between two neighbouring keys is the
/// linear interpolation of their positions.
struct MorphAnimatedMesh {
    std::string name = "kimono_cloth";                     ///< the node's and the mesh's name
    std::vector<Eigen::Vector3f> normals;                  ///< at the first key, unit length
    std::vector<Eigen::Vector3f> colours;                  ///< RGB in [0, 1]
    std::vector<std::uint32_t> indices;                    ///< 3 per triangle
    std::vector<double> keyTimes;                          ///< s, increasing, from >= 0
    std::vector<std::vector<Eigen::Vector3f>> keyPositions; ///< one per key: every vertex, cm, world
};

struct GltfExportOptions {
    /// The animation's, the scene's and the mesh's name: short (Blender cuts names at 63 bytes).
    std::string name = "take";
    /// How the take was made (a derived take's recipe), kept as `extras.description` of the scene
    /// and the animation; none when empty.
    std::string description;
    std::string generator = "Bunraku Motion Workbench";
    /// Also written when set: a mesh of its own, on a node of its own at the scene's root (no
    /// transform), animated by morph-target weights in the same animation.
    std::shared_ptr<const MorphAnimatedMesh> animatedMesh;
};

/// Checks a morph-animated mesh (the error says what is wrong): at least one key, every key the
/// same number of vertices as the normals and colours, finite positions, increasing finite times
/// from 0 on, triangles whose indices are in range.
Status validateMorphAnimatedMesh(const MorphAnimatedMesh& mesh);

/// glTF's axes from the workbench's (a rotation; positions are also scaled by 0.01).
Eigen::Quaterniond gltfAxisChange();

/// The .glb bytes: one node per joint (End Sites are left out: they carry no motion), named as
/// in the skeleton, its rest transform the pose of the first frame; a skin over those joints
/// with inverse bind matrices of the first frame; one mesh with every JointMesh (attributes
/// POSITION, NORMAL, COLOR_0, JOINTS_0, WEIGHTS_0), bound through the skin; one animation
/// sampled at frame / rateHz seconds: every joint's rotation, and the translation of joints
/// whose translation moves; `options.animatedMesh` when set (MorphAnimatedMesh). Errors for an
/// invalid motion, a rate out of range, no mesh, a mesh on an End Site or a missing joint, or an
/// invalid animated mesh.
Result<std::string> skeletalMotionToGlb(const SkeletalMotion& motion, double rateHz, const std::vector<JointMesh>& meshes,
                                        const GltfExportOptions& options = {});

/// The same with a mesh skinned smoothly: the skin's inverse bind matrices are `mesh.bindPoses`,
/// JOINTS_0 / WEIGHTS_0 the mesh's four influences (a glTF client blends them linearly). Errors
/// for a mesh whose arrays differ in length, an index, joint or weight out of range, or a
/// bind pose missing.
Result<std::string> skinnedMotionToGlb(const SkeletalMotion& motion, double rateHz, const SkinnedMesh& mesh,
                                       const GltfExportOptions& options = {});

/// Writes skeletalMotionToGlb atomically.
Status writeSkeletalGlb(const SkeletalMotion& motion, double rateHz, const std::vector<JointMesh>& meshes,
                        const std::filesystem::path& file, const GltfExportOptions& options = {});

/// Writes skinnedMotionToGlb atomically.
Status writeSkinnedGlb(const SkeletalMotion& motion, double rateHz, const SkinnedMesh& mesh, const std::filesystem::path& file,
                       const GltfExportOptions& options = {});

} // namespace bunraku::analysis::io
