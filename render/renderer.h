#pragma once
/// The 3D view's OpenGL 3.3 core renderer (thesis 6: the workbench's live replacement for the
/// LightWave scenes). It draws into whatever framebuffer is bound: a QOpenGLWidget's, or the
/// OffscreenRenderer's framebuffer object for tests, screenshots and frame sequences.
///
/// Cost model: setScene uploads every buffer once (a slot whose TakeSlot::sources are unchanged
/// keeps what was built for it); setFrame / setTime only recompute the poses
/// on the CPU, and render() sends them as uniforms: no GPU buffer is (re)allocated per frame.
/// Every method that touches OpenGL needs the context it was initialised in to be current.

#include "analysis/body/body_pose.h"
#include "analysis/core/result.h"
#include "render/camera.h"
#include "render/framing.h"
#include "render/gpu_mesh.h"
#include "render/shadow_map.h"
#include "render/scene.h"
#include "render/skinned_puppet.h"

#include <QImage>
#include <QOpenGLExtraFunctions>
#include <QPoint>
#include <QSize>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QOpenGLContext;
class QOpenGLShaderProgram;
class QOpenGLFramebufferObject;

namespace bunraku::render {

/// What lies under a screen point.
struct PickResult {
    int takeSlot = 0;  ///< 0 = the first take, 1 = the second
    int partIndex = 0; ///< index into BodyDescription::parts; -1 for a bone of the skeleton
    /// The body part's name; for a bone, the puppet part its joint carries ("hand"), or "".
    std::string partName;
    int joint = -1;    ///< a bone's joint (index into Skeleton::joints), -1 for the puppet
    std::string jointName;
};

class Renderer {
public:
    Renderer();
    ~Renderer(); ///< frees GL objects only if release() was not called and a context is current
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Compiles the shaders (:/shaders/scene.*); needs a current OpenGL 3.3 core context.
    analysis::Status initialize();
    bool isInitialized() const { return m_gl != nullptr; }
    /// Frees every GL object; call with the context current before it goes away.
    void release();

    /// Validates (validateScene) and uploads the scene: puppet meshes, orbits, grid, markers.
    /// Resets the frame to 0. Layout options that shape buffers (grid, point sizes) are read here.
    analysis::Status setScene(const SceneContent& scene, const LayoutOptions& layout = {});
    bool hasScene() const;
    int takeCount() const;
    /// The slots the last setScene built; the others it kept from the scene before (TakeSlot::sources).
    int slotsBuilt() const { return m_slotsBuilt; }

    void setVisibility(const SceneVisibility& visibility) { m_visibility = visibility; }
    /// Draft frames (a view moving: playback, a scrub, a drag) filter the shadows with 4
    /// comparisons instead of a search and 16, and leave the partner out of the shadow pass; the
    /// still frame drawn after them is the full stage.
    void setDraft(bool draft) { m_draft = draft; }
    bool draft() const { return m_draft; }
    const SceneVisibility& visibility() const { return m_visibility; }
    /// Separation and centring only (buffers are not rebuilt).
    void setLayout(const LayoutOptions& layout) { m_layout = layout; }
    const LayoutOptions& layout() const { return m_layout; }

    /// Shows frame `frame` of every take (clamped to each take's length).
    void setFrame(Eigen::Index frame);
    /// Shows the frame nearest `seconds` in every take.
    void setTime(double seconds);
    Eigen::Index frame(int takeSlot) const;

    /// Draws the scene into the bound framebuffer over a viewport of `size` pixels.
    void render(const Camera& camera, QSize size);
    /// The body part under `pixel` (from the top-left), by an ID pass into a private
    /// framebuffer; nullopt over the background or when the puppet is hidden.
    std::optional<PickResult> pick(const Camera& camera, QSize size, QPoint pixel);
    /// The ID pass as an image: red = 1 + partIndex + 32 * takeSlot, 0 for the background; a
    /// bone of the skeleton has red = 32 + 32 * takeSlot and green + 256 * blue = 1 + its joint.
    QImage partIdImage(const Camera& camera, QSize size);
    /// Decodes one pixel of partIdImage.
    std::optional<PickResult> decodePartId(QRgb pixel) const;

    // CPU-side placement (what render() uses), for picking by the caller, tests and overlays.
    /// world_T_take of a slot under this camera (slotRoot; the separation of two takes grows
    /// with the figures' height when a skeleton taller than the puppet is drawn).
    glm::mat4 takeRoot(int takeSlot, const Camera& camera) const;
    /// Displayed world_T_part of every body part at the current frame (take root included).
    std::vector<glm::mat4> displayedPartTransforms(int takeSlot, const Camera& camera) const;
    /// Displayed world_T_axis at the current frame, nullopt without an axis.
    std::optional<glm::mat4> displayedAxisTransform(int takeSlot, const Camera& camera) const;
    /// Displayed sensor positions (cm) at `frame`, one per 6-DOF part of the take.
    std::vector<glm::vec3> displayedSensorPositions(int takeSlot, Eigen::Index frame, const Camera& camera) const;
    /// Displayed world_T_joint of every skeleton joint at the current frame (take root included);
    /// empty when the take has no skeleton.
    std::vector<glm::mat4> displayedJointTransforms(int takeSlot, const Camera& camera) const;
    /// Whether take `takeSlot`'s puppet is dressed in its simulated kimono now (TakeSlot::kimono
    /// fits the take and body, and the cloth of the current frame is ready).
    bool clothDrawn(int takeSlot) const;
    /// Whether take `takeSlot`'s puppet / skeleton is drawn under the current visibility.
    bool puppetDrawn(int takeSlot) const;
    bool skeletonDrawn(int takeSlot) const;
    /// Height (cm) of the floor grid: just under the lowest point of the figures drawn (the
    /// puppets, the skeletons) at frame 0.
    float floorHeight() const;
    /// Half the side (cm) of the square floor and grid around the origin: LayoutOptions'
    /// gridHalfExtent, or more so that every take's path (a walk) lies on the floor before it
    /// fades (at 55 % of it), up to 50 m.
    float floorHalfExtent() const { return m_floorHalfExtent; }
    /// A camera that frames the scene: angle 340 deg (the puppet's left front), elevation 15 deg,
    /// looking at the figures' middle height, far enough back for one or two puppets, or for
    /// skeletons of any height (sized from the take).
    Camera framingCamera() const;
    /// The box (world, cm, under `camera`'s side-by-side placement) around what is drawn now:
    /// the puppets' parts, the orbits (or the sensors when the puppet is hidden), the partner
    /// marker and the motion axis, over the frames and takes `query` asks for; only the parts
    /// of `query.part` when given. Empty without a scene (or when the part is not drawn).
    Bounds displayedBounds(const Camera& camera, const BoundsQuery& query = {}) const;

private:
    struct Slot;
    struct SkeletonFigure;
    struct PuppetFigure;
    struct PartnerFigure;
    /// The uploaded modelled puppet fitted like `body`: reused when the next scene's body has the
    /// same fits (a scene is replaced on every step of a drag).
    std::shared_ptr<PuppetFigure> puppetFigure(const analysis::BodyDescription& body,
                                               std::vector<std::shared_ptr<PuppetFigure>>& reusable);
    /// The partner skinned from `puppet` in `pose`: reused when the next scene's is the same.
    std::shared_ptr<PartnerFigure> partnerFigure(const PuppetFigure& puppet,
                                                 const std::array<analysis::RigidTransform, analysis::kPuppetJointCount>& pose,
                                                 std::vector<std::shared_ptr<PartnerFigure>>& reusable);
    /// The puppet's figure a slot draws (its own fitted one, or the scene's); null without the
    /// modelled puppet (a body of other parts, or meshes loaded from files).
    const PuppetFigure* slotPuppet(const Slot& slot) const;
    /// The displayed box of the modelled puppet's joints of `part` (all parts when empty) at `frame`.
    void addPuppetBounds(Bounds& bounds, const Slot& slot, Eigen::Index frame, const glm::mat4& root,
                         const std::function<bool(const std::string&, const std::string&)>& wanted) const;
    /// The uploaded skeleton of a take: reused when the next scene shows the same skeleton with
    /// the same bones (a scene is replaced on every step of a drag).
    std::shared_ptr<SkeletonFigure> skeletonFigure(const analysis::SkeletalMotion& motion,
                                                   std::vector<std::shared_ptr<SkeletonFigure>>& reusable);
    void updatePoses(Slot& slot) const;
    /// The slot's cloth at its frame (positions and normals for the GPU); not ready when the slot
    /// has none or its player fails (the skinned kimono is drawn then).
    void updateCloth(Slot& slot) const;
    /// Dresses the slot's modelled puppet in `kimono` when it was simulated for this take and
    /// body: its player, its GPU buffers (reused from `reusable` for the same cloth) and the
    /// orbits of its measured points.
    void attachKimono(Slot& slot, const std::shared_ptr<const analysis::KimonoSimulation>& kimono, int slotIndex,
                      std::vector<std::pair<std::shared_ptr<const analysis::KimonoCloth>, std::shared_ptr<ClothGpu>>>& reusable);
    /// Height (cm) the view is framed for: a puppet's, or the tallest skeleton drawn.
    float framedHeight() const;
    /// What a pass draws: colours, part IDs (picking), or depths seen from the key light.
    enum class Pass { Colour, PartIds, Shadow };
    void drawScene(const Camera& camera, QSize size, bool partIds);
    /// The figures of every slot (puppets, skeletons, the partner except in the ID pass).
    void drawFigures(const Camera& camera, const glm::mat4& viewProjection, const glm::vec3& eye, Pass pass);
    /// Draws the figures into the shadow map from the key light and returns the light's
    /// clip_T_world; nullopt when shadows are off, nothing casts, or the driver lacks the map.
    std::optional<glm::mat4> drawShadowMap(const Camera& camera, QSize size);
    void drawPuppet(const Slot& slot, int takeSlot, const glm::mat4& root, const glm::mat4& viewProjection,
                    const glm::vec3& eye, bool partIds);
    /// The performer's body of a slot's skeleton, or with `fileMesh` the file's own mesh (made
    /// and uploaded on first use); false when it cannot be made (the caller draws the capsules).
    bool drawBody(const Slot& slot, int takeSlot, const glm::mat4& root, const glm::mat4& viewProjection, const glm::vec3& eye,
                  bool partIds, bool fileMesh);
    /// world_T_take of the partner of `slot` (thesis 6: the person greeted or served): the take's
    /// modelled puppet as it stands at frame 0, turned about its centre to face the take from
    /// partnerDistance ahead; without a modelled puppet, the cone's frame on the floor there.
    glm::mat4 partnerTransform(const Slot& slot, const glm::mat4& root) const;
    /// Whether the partner of a take is drawn: shown, and not inside the other take's figure.
    bool partnerShown(int takeSlot, const Camera& camera) const;

    void setModel(const glm::mat4& model);
    void setColour(const glm::vec3& colour, bool vertexColour, bool lit);
    QOpenGLFramebufferObject& pickFramebuffer(QSize size);
    void releaseSceneBuffers();

    QOpenGLContext* m_context = nullptr;
    QOpenGLExtraFunctions* m_gl = nullptr;
    std::unique_ptr<QOpenGLShaderProgram> m_program;
    std::unique_ptr<QOpenGLShaderProgram> m_skinProgram; ///< skinned.vert + scene.frag
    std::unique_ptr<QOpenGLShaderProgram> m_bodyProgram; ///< skinned.vert for a skeleton's joints + scene.frag
    /// The body program's uniform locations, looked up once (in kBodyUniformNames' order).
    enum BodyUniform { BodyModel, BodyViewProjection, BodyNormalMatrix, BodyColour, BodyUseVertexColour, BodyLit, BodyLightPosition,
                       BodyPartIdBase, BodyBoneIds, BodyKeyDirection, BodyJointReal, BodyJointDual, BodyLinearBlend, BodyUniformCount };
    std::array<int, BodyUniformCount> m_bodyUniforms{};
    std::unique_ptr<QOpenGLFramebufferObject> m_pickFramebuffer;
    struct Uniforms {
        int model = -1, viewProjection = -1, normalMatrix = -1, colour = -1, useVertexColour = -1, lit = -1,
            lightPosition = -1, partIdBase = -1, keyDirection = -1, floor = -1, floorRadius = -1, background = -1,
            shadows = -1, shadowMap = -1, shadowDepth = -1, lightViewProjection = -1, shadowUvPerCm = -1, shadowCmPerDepth = -1,
            shadowDraft = -1;
    } m_uniforms;
    struct SkinUniforms {
        int model = -1, viewProjection = -1, normalMatrix = -1, colour = -1, useVertexColour = -1, lit = -1,
            lightPosition = -1, partIdBase = -1, keyDirection = -1, jointReal = -1, jointDual = -1, partOfJoint = -1;
    } m_skinUniforms;
    ShadowMap m_shadowMap;
    std::vector<float> m_shadowKey; ///< what the shadow map was drawn for (drawShadowMap)
    bool m_draft = false;
    int m_sceneGeneration = 0;      ///< counts setScene calls
    int m_slotsBuilt = 0;           ///< slots the last setScene built (slotsBuilt)
    /// What the slots of the scene drawn were built from (TakeSlot::sources), and the body source,
    /// meshes and layout of that scene: a slot of the next scene with the same keeps its Slot.
    std::vector<std::vector<std::shared_ptr<const void>>> m_slotSources;
    std::shared_ptr<const void> m_bodySource;
    bool m_sceneHadMeshes = false;
    LayoutOptions m_builtLayout;
    std::shared_ptr<PuppetFigure> m_puppet; ///< the scene body's modelled puppet, or null

    analysis::BodyDescription m_body;
    std::vector<std::string> m_partNames;
    std::vector<GpuMesh> m_partMeshes; ///< one per body part, in the part frame
    std::vector<Bounds> m_partBounds;  ///< one per body part: its mesh's box in the part frame
    std::vector<Slot> m_slots;
    GpuMesh m_grid;
    GpuMesh m_floor;  ///< a square under the grid, shaded by the key light and its shadows
    float m_floorHalfExtent = 0.0f; ///< cm: the grid's half extent, grown to hold every take's path
    GpuMesh m_box;    ///< unit cube for the axis bars
    GpuMesh m_sphere; ///< unit sphere for the orbits' moving points
    GpuMesh m_partner;
    SceneVisibility m_visibility;
    LayoutOptions m_layout;
};

} // namespace bunraku::render
