#pragma once
/// The modelled Bunraku puppet (thesis 2.1): one continuous, skinned surface generated in code.
///
/// How it is made (resources/README.md, docs/ARCHITECTURE.md): the puppet is a signed distance
/// field - rounded boxes, ellipsoids, tapered capsules and an elliptic frustum blended by smooth
/// unions (puppet_shapes.cpp) - polygonised by surface nets (surface_nets.h) into one
/// watertight mesh. It has the female puppet's parts: the kashira (head) with brow, nose and
/// lips, white gofun skin and a black shimada hairstyle with a comb and hairpins, the neck, the
/// kata-ita (shoulder board) and the dō-wa (waist hoop) under a kimono with collars and an obi
/// tied at the back, long furisode sleeves hanging from the arms, carved hands with fingers, and
/// no legs. Eyes, brows and lips are painted regions (PuppetRegion::Face) whose paint the
/// renderer evaluates per pixel from the vertex's model position; the kimono's flowers likewise.
///
/// Skinning: every vertex has up to four joints with weights summing to one. The joints are the
/// body description's six parts (head, shoulder, right arm and hand, mirrored left arm and hand)
/// and three more that hang: the kimono joint sits at the dō-wa and turns with the shoulder's
/// heading only, so the skirt below the dō-wa hangs under it in a bow instead of swinging up
/// with the torso; a sleeve joint sits on its arm's bone and turns with the arm's heading only,
/// so a long sleeve hangs below the arm whether it is raised or lowered. Weights are smooth
/// across the neck (along the neck), the shoulders and the wrists (along the arm's bone), below
/// the dō-wa (by height) and down a sleeve (by the depth below the bone). Poses are blended as dual
/// quaternions (dual_quaternion.h; the GPU does the same in resources/shaders/skinned.vert).
///
/// Frames: model space is the shoulder part's frame at rest (x forward, y to the puppet's left,
/// z up, cm); `bindPoses` are the parts' frames in it (model_T_joint), the rest pose of the demo
/// corpus's rig (analysis/synth/puppet_rig.cpp) with the head upright.

#include "analysis/body/body_description.h"
#include "analysis/core/pose.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bunraku::analysis {

enum class PuppetJoint { Head, Shoulder, RightArm, RightHand, LeftArm, LeftHand, Kimono, RightSleeve, LeftSleeve };
inline constexpr int kPuppetJointCount = 9;
/// The body part each joint moves with (the kimono hangs from the shoulder's dō-wa, a sleeve
/// from its arm).
inline constexpr std::array<const char*, kPuppetJointCount> kPuppetJointParts{
    "head", "shoulder", "right_arm", "right_hand", "left_arm", "left_hand", "shoulder", "right_arm", "left_arm"};
inline constexpr std::array<const char*, kPuppetJointCount> kPuppetJointNames{
    "head", "shoulder", "right_arm", "right_hand", "left_arm", "left_hand", "kimono", "right_sleeve", "left_sleeve"};

/// Where the renderer paints per pixel from `paintPositions`.
enum class PuppetRegion : std::uint8_t { None = 0, Face = 1, Kimono = 2, Obi = 3 };

/// The skinned puppet as plain data (what a renderer uploads and an exporter writes).
struct PuppetMesh {
    std::vector<Eigen::Vector3f> positions;      ///< cm, model space (bind pose)
    std::vector<Eigen::Vector3f> normals;        ///< unit, model space
    std::vector<Eigen::Vector3f> colours;        ///< base RGB in [0, 1] (paint not included)
    std::vector<float> sheen;                    ///< specular strength in [0, 1] (silk, lacquer)
    std::vector<PuppetRegion> regions;           ///< painted region of each vertex
    std::vector<Eigen::Vector3f> paintPositions; ///< cm, the shipped puppet's model position (paint coordinates)
    std::vector<std::array<std::uint8_t, 4>> joints; ///< PuppetJoint indices
    std::vector<Eigen::Vector4f> weights;        ///< sum 1, unused slots 0
    std::vector<std::uint32_t> indices;          ///< triangles, counter-clockwise from outside
    std::array<RigidTransform, kPuppetJointCount> bindPoses; ///< model_T_joint at rest
    /// The kimono joint's origin (the dō-wa's centre) in the shoulder frame, cm.
    Eigen::Vector3d dowaInShoulder{0.0, 0.0, -24.0};
    /// A sleeve joint's origin in its arm's frame (the left mirrors the right), cm, and the
    /// heading (deg, about the vertical) of the right arm's bone at rest.
    Eigen::Vector3d sleeveInArm{2.0, 0.0, 0.0};
    double restArmHeadingDeg = -20.0;
    /// Grid cell of the polygonisation (cm) and small separate pieces dropped (normally 0).
    float cellSize = 0.0f;
    int droppedComponents = 0;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    /// The joint with the largest weight at vertex `v`.
    int dominantJoint(std::size_t v) const;
};

struct PuppetMeshOptions {
    float cellSize = 0.5f; ///< cm
    int threads = 0;       ///< 0: one per hardware thread
    /// Then simplified (mesh_decimation.h) to about this many triangles where the surface moves
    /// less than `maxError` (cm); 0: as polygonised.
    std::size_t targetTriangles = 12000;
    double maxError = 0.1;
    double maxEdge = 3.0; ///< cm, the longest edge a simplification may make
};

/// Generates the puppet (deterministic: the same options give the same mesh on any thread count).
PuppetMesh generatePuppetMesh(const PuppetMeshOptions& options = {});

/// The shipped puppet, generated once per process on first use (thread-safe).
const PuppetMesh& shippedPuppetMesh();

/// The signed distance of the puppet's surface at a model-space point (cm; negative inside).
float puppetSignedDistance(const Eigen::Vector3f& modelPoint);

/// model_T_joint at rest of the six part joints (head, shoulder, right arm and hand, left arm and
/// hand), as in every PuppetMesh::bindPoses, without generating the mesh.
std::array<RigidTransform, 6> puppetPartBindPoses();

/// A box (model space, cm) holding the whole solid.
struct PuppetBounds {
    Eigen::Vector3f lower, upper;
};
PuppetBounds puppetModelBounds();

/// The joint a model-space point moves with most: the largest weight of the skin rule of the
/// shape nearest it (the rule that weights the surface, so a point inside the solid belongs to
/// the joint the surface over it moves with).
PuppetJoint puppetDominantJointAt(const Eigen::Vector3f& modelPoint);

/// True when `body` has the six parts the puppet's joints move with (head, shoulder, right_arm,
/// right_hand, left_arm, left_hand), so the modelled puppet can stand for it.
bool bodyHasPuppetParts(const BodyDescription& body);

/// Index into body.parts of every joint's part (the kimono: the shoulder's); -1 when missing.
std::array<int, kPuppetJointCount> puppetJointPartIndices(const BodyDescription& body);

/// The puppet fitted like `body`: each part's `fit` (body_fit.h) applied to the vertices in that
/// part's frame, blended by the skin weights; normals follow. The shipped mesh when every fit is
/// the identity.
PuppetMesh fittedPuppetMesh(const PuppetMesh& shipped, const BodyDescription& body);

/// world_T_joint of every joint from the body parts' world poses (body order, e.g.
/// worldPartPoses): the parts' own, the kimono joint at the dō-wa turned by the shoulder's
/// heading alone (about the world's vertical), and each sleeve joint on its arm turned by the
/// arm's heading alone (the shoulder's when the arm points straight up or down).
std::array<RigidTransform, kPuppetJointCount> puppetJointPoses(const PuppetMesh& mesh, const BodyDescription& body,
                                                               const std::vector<RigidTransform>& world_T_part);

/// Skinned positions and normals on the CPU (dual quaternion blending, as the shader does).
struct SkinnedSurface {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals;
};
SkinnedSurface skinPuppet(const PuppetMesh& mesh, const std::array<RigidTransform, kPuppetJointCount>& world_T_joint);

} // namespace bunraku::analysis
