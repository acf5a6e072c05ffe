#pragma once
/// What the renderer's files share (renderer.cpp: set-up, scenes and poses; renderer_layout.cpp:
/// placement, bounds and framing, no GL calls; renderer_draw.cpp: the passes - shadow, colour,
/// part IDs - and picking): its constants and the per-scene data behind render::Renderer.
/// Private to render/.

#include "render/renderer.h"

#include "analysis/body/performer_body.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/cloth/kimono_mesh.h"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::render {

inline constexpr int kIdsPerSlot = 32; // part IDs: 1 + partIndex + 32 * slot, in the red channel
inline constexpr int kSkeletonId = kIdsPerSlot - 1; // partIndex 31 (no body part has it): a bone
/// Height (cm) a puppet is framed for (framingCamera's distances were chosen for it).
inline constexpr float kPuppetFramedHeight = 90.0f;
inline const glm::vec3 kBackground(0.94f, 0.95f, 0.97f);
inline const glm::vec3 kPartnerColour(0.42f, 0.48f, 0.58f);
inline const glm::vec3 kFloorColour(0.86f, 0.85f, 0.83f);
/// Texels per side of the key light's depth map, and the width (cm) its filter softens a
/// shadow's edge over.
inline constexpr int kShadowMapSize = 1024;
/// cm the partner keeps clear of the furthest reach of a take that travels towards it.
inline constexpr float kPartnerClearance = 60.0f;
/// cm: the largest floor (a grid line every 20 cm: at most 2 x 250 lines each way).
inline constexpr float kMaxFloorHalfExtent = 5000.0f;

inline glm::vec3 sensorPosition(const analysis::Take& take, Eigen::Index frame, Eigen::Index firstChannel)
{
    return {float(take.values(frame, firstChannel)), float(take.values(frame, firstChannel + 1)),
            float(take.values(frame, firstChannel + 2))};
}


/// The modelled puppet of one body on the GPU (render/skinned_puppet.h).
struct Renderer::PuppetFigure {
    std::vector<Eigen::Matrix4d> fits; ///< the body's part fits it was made for
    std::shared_ptr<const analysis::PuppetMesh> mesh;
    SkinnedPuppetGpu gpu;
    /// Per joint the box of the vertices it moves most, in the joint's frame.
    std::array<Bounds, analysis::kPuppetJointCount> jointBounds;

    void release(QOpenGLExtraFunctions& gl) { gpu.release(gl); }
};

/// The partner: the take's puppet as it stands at frame 0, skinned once on the CPU (it never
/// moves) and drawn as a plain mesh, in take coordinates.
struct Renderer::PartnerFigure {
    std::shared_ptr<const analysis::PuppetMesh> mesh; ///< the puppet it was skinned from
    std::array<analysis::RigidTransform, analysis::kPuppetJointCount> joints; ///< the pose it was skinned in
    GpuMesh gpu;

    bool matches(const analysis::PuppetMesh* other, const std::array<analysis::RigidTransform, analysis::kPuppetJointCount>& pose) const
    {
        if (mesh.get() != other) return false;
        for (std::size_t j = 0; j < pose.size(); ++j)
            if (!joints[j].rotation.coeffs().isApprox(pose[j].rotation.coeffs(), 0.0) || joints[j].translation != pose[j].translation) return false;
        return true;
    }
    void release(QOpenGLExtraFunctions& gl) { gpu.release(gl); }
};

struct Renderer::Slot {
    analysis::Take take;
    analysis::BodyDescription body; ///< the scene's body, or the take's own
    std::vector<GpuMesh> meshes;    ///< the take's own body's meshes; empty: the scene's
    analysis::BodyBinding binding;
    std::vector<analysis::RigidTransform> world_T_axis;
    glm::vec3 centre{0.0f};
    std::vector<Eigen::Index> sensorFirstChannel; ///< one per 6-DOF part of the take
    std::vector<GpuMesh> orbits;                  ///< one tube per sensor, take coordinates
    float orbitRadius = 0.4f;                     ///< cm, the tubes' (orbitTubeRadius)
    Eigen::Index frame = 0;
    std::vector<glm::mat4> take_T_part; ///< at `frame`, one per body part
    std::shared_ptr<PuppetFigure> puppet; ///< the take's own fitted puppet; null: the scene's
    std::array<analysis::RigidTransform, analysis::kPuppetJointCount> take_T_skinJoint; ///< at `frame`
    std::array<analysis::RigidTransform, analysis::kPuppetJointCount> partnerSkinJoint; ///< at frame 0
    std::shared_ptr<PartnerFigure> partner; ///< null without a modelled puppet (the cone then)
    std::shared_ptr<SkeletonFigure> skeleton; ///< the performer's skeleton, when the take has one
    std::vector<glm::mat4> take_T_joint;  ///< at `frame`, one per joint
    Bounds path;             ///< take coordinates: the sensors over the take and the figure at frame 0
    glm::vec3 partnerSpot{0.0f}; ///< take coordinates, on z = 0: where the partner stands
    float puppetLowest = 0.0f, puppetHighest = 0.0f;     ///< cm, at frame 0
    float skeletonLowest = 0.0f, skeletonHighest = 0.0f; ///< cm, at frame 0
    float fileMeshLowest = 0.0f, fileMeshHighest = 0.0f; ///< cm, the file's mesh at frame 0 (when the take has one)
    /// The simulated kimono (TakeSlot::kimono) when it fits this take and body; its player
    /// (the cloth at `frame`, stepped on during playback), the particles' positions and normals
    /// at `frame` (take coordinates) and whether they reached the GPU.
    std::shared_ptr<const analysis::KimonoSimulation> kimono;
    std::unique_ptr<analysis::KimonoPlayer> kimonoPlayer;
    std::vector<float> clothVertices;
    bool clothReady = false;
    mutable bool clothUploaded = false;
    std::shared_ptr<ClothGpu> cloth;     ///< shared with the next scene when it shows the same cloth
    std::vector<GpuMesh> kimonoOrbits;   ///< the measured points' paths, take coordinates
};

struct Renderer::SkeletonFigure {
    std::shared_ptr<const analysis::Skeleton> skeleton;
    std::vector<Eigen::Vector3d> bones; ///< the static translations the meshes were built for
    std::vector<int> movingJoints;
    std::vector<GpuMesh> meshes;        ///< one per Skeleton::joints, in the joint frame
    std::vector<std::string> jointNames;
    std::vector<std::string> jointParts; ///< the puppet part each joint carries, or ""
    float jointRadius = 0.0f;
    /// The performer's body (FigureStyle::Body), made on first use; null when it cannot be
    /// made (then the capsules are drawn).
    std::shared_ptr<const analysis::PerformerBody> body;
    SkinnedPuppetGpu bodyGpu;
    bool bodyTried = false;
    /// The file's own mesh (FigureStyle::FileMesh, Skeleton::mesh), made on first use; null
    /// when the skeleton has none that can be drawn (then the capsules are drawn).
    std::shared_ptr<const analysis::PerformerBody> fileMesh;
    SkinnedPuppetGpu fileMeshGpu;
    bool fileMeshTried = false;
    /// cm: no vertex of the file's mesh is further than this from a joint it is weighted to
    /// (bounds: the joints' box grown by it holds the mesh in any pose); 0 without a mesh.
    float fileMeshReach = 0.0f;

    void release(QOpenGLExtraFunctions& gl)
    {
        for (GpuMesh& mesh : meshes) mesh.release(gl);
        bodyGpu.release(gl);
        fileMeshGpu.release(gl);
    }
};


} // namespace bunraku::render
