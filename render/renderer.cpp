#include "render/renderer.h"

#include "analysis/body/dual_quaternion.h"
#include "analysis/body/performer_body.h"
#include "analysis/core/puppet_layout.h"
#include "render/orbit_geometry.h"
#include "render/puppet_geometry.h"
#include "render/skeleton_geometry.h"

#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <limits>

namespace bunraku::render {

namespace {

constexpr int kIdsPerSlot = 32; // part IDs: 1 + partIndex + 32 * slot, in the red channel
constexpr int kSkeletonId = kIdsPerSlot - 1; // partIndex 31 (no body part has it): a bone
/// Height (cm) a puppet is framed for (framingCamera's distances were chosen for it).
constexpr float kPuppetFramedHeight = 90.0f;
const glm::vec3 kBackground(0.94f, 0.95f, 0.97f);
const glm::vec3 kPartnerColour(0.42f, 0.48f, 0.58f);
const glm::vec3 kFloorColour(0.86f, 0.85f, 0.83f);
/// Texels per side of the key light's depth map, and the width (cm) its filter softens a
/// shadow's edge over.
constexpr int kShadowMapSize = 1024;
/// cm the partner keeps clear of the furthest reach of a take that travels towards it.
constexpr float kPartnerClearance = 60.0f;
/// cm: the largest floor (a grid line every 20 cm: at most 2 x 250 lines each way).
constexpr float kMaxFloorHalfExtent = 5000.0f;

glm::vec3 sensorPosition(const analysis::Take& take, Eigen::Index frame, Eigen::Index firstChannel)
{
    return {float(take.values(frame, firstChannel)), float(take.values(frame, firstChannel + 1)),
            float(take.values(frame, firstChannel + 2))};
}

Mesh partnerMesh()
{
    // Where the partner stands: a disc on the floor and a slim cone, small beside the puppet.
    Mesh mesh = transformed(cylinderMesh(14.0f, 1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 0.5f)));
    mesh.append(transformed(frustumMesh(5.0f, 0.5f, 45.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 23.5f))));
    paint(mesh, kPartnerColour);
    return mesh;
}

Mesh floorMesh(float halfExtent)
{
    Mesh mesh;
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
        mesh.vertices.push_back(Vertex{glm::vec3(corner * halfExtent, 0.0f), up, kFloorColour});
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

} // namespace

/// The modelled puppet of one body on the GPU (render/skinned_puppet.h).
struct Renderer::PuppetFigure {
    std::vector<Eigen::Matrix4d> fits; ///< the body's part fits it was made for
    std::shared_ptr<const analysis::PuppetMesh> mesh;
    SkinnedPuppetGpu gpu;
    /// Per joint the box of the vertices it moves most, in the joint's frame.
    std::array<Bounds, analysis::kPuppetJointCount> jointBounds;

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
    std::shared_ptr<SkeletonFigure> skeleton; ///< the performer's skeleton, when the take has one
    std::vector<glm::mat4> take_T_joint;  ///< at `frame`, one per joint
    Bounds path;             ///< take coordinates: the sensors over the take and the figure at frame 0
    glm::vec3 partnerSpot{0.0f}; ///< take coordinates, on z = 0: where the partner stands
    float puppetLowest = 0.0f, puppetHighest = 0.0f;     ///< cm, at frame 0
    float skeletonLowest = 0.0f, skeletonHighest = 0.0f; ///< cm, at frame 0
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

    void release(QOpenGLExtraFunctions& gl)
    {
        for (GpuMesh& mesh : meshes) mesh.release(gl);
        bodyGpu.release(gl);
    }
};

Renderer::Renderer() = default;

Renderer::~Renderer()
{
    if (m_gl != nullptr && QOpenGLContext::currentContext() == m_context) release();
}

analysis::Status Renderer::initialize()
{
    using analysis::ErrorCode;
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (context == nullptr) return analysis::makeError(ErrorCode::Unsupported, "no current OpenGL context");
    const QSurfaceFormat format = context->format();
    if (!context->isOpenGLES() && std::make_pair(format.majorVersion(), format.minorVersion()) < std::make_pair(3, 3))
        return analysis::makeError(ErrorCode::Unsupported,
                                   "OpenGL 3.3 core is needed, the context has " + std::to_string(format.majorVersion()) +
                                       "." + std::to_string(format.minorVersion()));
    auto program = std::make_unique<QOpenGLShaderProgram>();
    if (!program->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/shaders/scene.vert")) ||
        !program->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/shaders/scene.frag")) ||
        !program->link())
        return analysis::makeError(ErrorCode::Unsupported, "shader build failed: " + program->log().toStdString());
    m_uniforms.model = program->uniformLocation("u_model");
    m_uniforms.viewProjection = program->uniformLocation("u_viewProjection");
    m_uniforms.normalMatrix = program->uniformLocation("u_normalMatrix");
    m_uniforms.colour = program->uniformLocation("u_colour");
    m_uniforms.useVertexColour = program->uniformLocation("u_useVertexColour");
    m_uniforms.lit = program->uniformLocation("u_lit");
    m_uniforms.lightPosition = program->uniformLocation("u_lightPosition");
    m_uniforms.partIdBase = program->uniformLocation("u_partIdBase");
    m_uniforms.keyDirection = program->uniformLocation("u_keyDirection");
    m_uniforms.floor = program->uniformLocation("u_floor");
    m_uniforms.floorRadius = program->uniformLocation("u_floorRadius");
    m_uniforms.background = program->uniformLocation("u_background");
    m_uniforms.shadows = program->uniformLocation("u_shadows");
    m_uniforms.shadowMap = program->uniformLocation("u_shadowMap");
    m_uniforms.lightViewProjection = program->uniformLocation("u_lightViewProjection");
    m_uniforms.shadowDepth = program->uniformLocation("u_shadowDepth");
    m_uniforms.shadowUvPerCm = program->uniformLocation("u_shadowUvPerCm");
    m_uniforms.shadowCmPerDepth = program->uniformLocation("u_shadowCmPerDepth");
    auto skin = std::make_unique<QOpenGLShaderProgram>();
    if (!skin->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/shaders/skinned.vert")) ||
        !skin->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/shaders/scene.frag")) || !skin->link())
        return analysis::makeError(ErrorCode::Unsupported, "shader build failed: " + skin->log().toStdString());
    m_skinUniforms.model = skin->uniformLocation("u_model");
    m_skinUniforms.viewProjection = skin->uniformLocation("u_viewProjection");
    m_skinUniforms.normalMatrix = skin->uniformLocation("u_normalMatrix");
    m_skinUniforms.colour = skin->uniformLocation("u_colour");
    m_skinUniforms.useVertexColour = skin->uniformLocation("u_useVertexColour");
    m_skinUniforms.lit = skin->uniformLocation("u_lit");
    m_skinUniforms.lightPosition = skin->uniformLocation("u_lightPosition");
    m_skinUniforms.partIdBase = skin->uniformLocation("u_partIdBase");
    m_skinUniforms.keyDirection = skin->uniformLocation("u_keyDirection");
    m_skinUniforms.jointReal = skin->uniformLocation("u_jointReal");
    m_skinUniforms.jointDual = skin->uniformLocation("u_jointDual");
    m_skinUniforms.partOfJoint = skin->uniformLocation("u_partOfJoint");
    // The performer's body: skinned.vert again, for the skeleton's joints.
    QFile skinnedSource(QStringLiteral(":/shaders/skinned.vert"));
    if (!skinnedSource.open(QIODevice::ReadOnly)) return analysis::makeError(ErrorCode::Unsupported, "shader :/shaders/skinned.vert not found");
    QByteArray bodySource = skinnedSource.readAll();
    const qsizetype versionEnd = bodySource.indexOf('\n') + 1;
    bodySource.insert(versionEnd, "#define BODY_JOINTS " + QByteArray::number(analysis::kMaxBodyJoints) + "\n");
    auto body = std::make_unique<QOpenGLShaderProgram>();
    if (!body->addShaderFromSourceCode(QOpenGLShader::Vertex, bodySource) ||
        !body->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/shaders/scene.frag")) || !body->link())
        return analysis::makeError(ErrorCode::Unsupported, "shader build failed: " + body->log().toStdString());
    for (const char* name : {"u_model", "u_viewProjection", "u_normalMatrix", "u_colour", "u_useVertexColour", "u_lit", "u_lightPosition",
                             "u_partIdBase", "u_boneIds", "u_keyDirection", "u_jointReal", "u_jointDual"})
        m_bodyUniforms[name] = body->uniformLocation(name);
    m_program = std::move(program);
    m_skinProgram = std::move(skin);
    m_bodyProgram = std::move(body);
    m_context = context;
    m_gl = context->extraFunctions();

    m_box.upload(*m_gl, boxMesh(glm::vec3(1.0f)));
    m_sphere.upload(*m_gl, ellipsoidMesh(glm::vec3(1.0f), 16, 10));
    m_partner.upload(*m_gl, partnerMesh());
    // The shadow map's sampler reads texture unit 1 in both programs (unit 0 stays free).
    m_program->bind();
    m_gl->glUniform1i(m_uniforms.shadowMap, 1);
    m_gl->glUniform1i(m_uniforms.shadowDepth, 2);
    m_program->release();
    for (QOpenGLShaderProgram* skinned : {m_skinProgram.get(), m_bodyProgram.get()}) {
        skinned->bind();
        m_gl->glUniform1i(skinned->uniformLocation("u_shadowMap"), 1);
        m_gl->glUniform1i(skinned->uniformLocation("u_shadowDepth"), 2);
        skinned->release();
    }
    return analysis::okStatus();
}

void Renderer::releaseSceneBuffers()
{
    for (GpuMesh& mesh : m_partMeshes) mesh.release(*m_gl);
    m_partMeshes.clear();
    if (m_puppet) m_puppet->release(*m_gl);
    m_puppet.reset();
    for (Slot& slot : m_slots) {
        if (slot.puppet) slot.puppet->release(*m_gl);
        for (GpuMesh& orbit : slot.orbits) orbit.release(*m_gl);
        for (GpuMesh& mesh : slot.meshes) mesh.release(*m_gl);
        if (slot.skeleton) slot.skeleton->release(*m_gl);
    }
    m_slots.clear();
    m_grid.release(*m_gl);
    m_floor.release(*m_gl);
}

void Renderer::release()
{
    if (m_gl == nullptr) return;
    releaseSceneBuffers();
    m_box.release(*m_gl);
    m_sphere.release(*m_gl);
    m_partner.release(*m_gl);
    m_shadowMap.release(*m_gl);
    m_shadowKey.clear();
    m_pickFramebuffer.reset();
    m_program.reset();
    m_skinProgram.reset();
    m_bodyProgram.reset();
    m_gl = nullptr;
    m_context = nullptr;
}

analysis::Status Renderer::setScene(const SceneContent& scene, const LayoutOptions& layout)
{
    if (m_gl == nullptr)
        return analysis::makeError(analysis::ErrorCode::InvalidArgument, "the renderer is not initialised");
    if (auto status = validateScene(scene); !status.ok()) return status;
    ++m_sceneGeneration;
    m_shadowKey.clear();
    std::vector<std::shared_ptr<SkeletonFigure>> reusable;
    for (Slot& slot : m_slots)
        if (slot.skeleton) reusable.push_back(std::move(slot.skeleton));
    std::vector<std::shared_ptr<PuppetFigure>> reusablePuppets;
    if (m_puppet) reusablePuppets.push_back(std::move(m_puppet));
    for (Slot& slot : m_slots)
        if (slot.puppet) reusablePuppets.push_back(std::move(slot.puppet));
    releaseSceneBuffers();
    m_layout = layout;
    m_body = scene.body;
    m_partNames.clear();
    for (const auto& part : m_body.parts) m_partNames.push_back(part.name);

    // The modelled, skinned puppet stands for a body with its six parts; a body of other parts,
    // or one with meshes loaded from files, is drawn from its own primitives and meshes.
    const bool modelled = scene.partMeshes.empty() && analysis::bodyHasPuppetParts(m_body);
    if (modelled) m_puppet = puppetFigure(m_body, reusablePuppets);
    const std::vector<Mesh> meshes = modelled ? std::vector<Mesh>{} : buildPuppetMeshes(m_body, scene.partMeshes);
    m_partMeshes.resize(meshes.size());
    for (std::size_t i = 0; i < meshes.size(); ++i) m_partMeshes[i].upload(*m_gl, meshes[i]);
    m_partBounds.assign(meshes.size(), Bounds{});
    for (std::size_t i = 0; i < meshes.size(); ++i)
        for (const Vertex& vertex : meshes[i].vertices) m_partBounds[i].add(vertex.position);

    for (std::size_t s = 0; s < scene.takes.size(); ++s) {
        const TakeSlot& source = scene.takes[s];
        Slot slot;
        slot.take = source.take;
        slot.body = source.body ? *source.body : m_body;
        if (modelled && source.body) slot.puppet = puppetFigure(slot.body, reusablePuppets);
        const std::vector<Mesh> ownMeshes = source.body && !modelled ? buildPuppetMeshes(slot.body) : std::vector<Mesh>{};
        for (const Mesh& mesh : ownMeshes) {
            GpuMesh gpu;
            gpu.upload(*m_gl, mesh);
            slot.meshes.push_back(std::move(gpu));
        }
        const std::vector<Mesh>& slotMeshes = source.body ? ownMeshes : meshes;
        slot.binding = analysis::bindBody(slot.body, slot.take).value();
        slot.world_T_axis = source.world_T_axis;
        slot.centre = takeCentre(slot.take, m_body.mirrorFramePart.empty() ? "shoulder" : m_body.mirrorFramePart);
        const auto sensors = analysis::sixDofParts(slot.take);
        std::vector<std::vector<glm::vec3>> paths(sensors.size());
        Bounds pathBounds;
        for (std::size_t k = 0; k < sensors.size(); ++k) {
            slot.sensorFirstChannel.push_back(sensors[k].firstChannel);
            paths[k].reserve(std::size_t(slot.take.frameCount()));
            for (Eigen::Index f = 0; f < slot.take.frameCount(); ++f) {
                paths[k].push_back(sensorPosition(slot.take, f, sensors[k].firstChannel));
                pathBounds.add(paths[k].back());
            }
        }
        // Tubes sized from the figure and the orbits' span, so they read beside a puppet and
        // along a long walk.
        const auto firstPoses = analysis::worldPartPoses(m_body, slot.binding, slot.take, 0);
        if (modelled) addPuppetBounds(pathBounds, slot, 0, glm::mat4(1.0f), {});
        for (std::size_t p = 0; p < firstPoses.size() && p < m_partBounds.size(); ++p)
            for (const glm::vec3& corner : {m_partBounds[p].lower, m_partBounds[p].upper})
                if (!m_partBounds[p].empty()) pathBounds.add(glm::vec3(toMatrix(firstPoses[p]) * glm::vec4(corner, 1.0f)));
        slot.orbitRadius = orbitTubeRadius(pathBounds.extent());
        // The partner stands partnerDistance ahead (+x) of the take's centre, or beyond the
        // take's furthest reach ahead when the take travels there (a walk towards +x).
        slot.partnerSpot = slot.centre + glm::vec3(m_layout.partnerDistance, 0.0f, 0.0f);
        if (!pathBounds.empty()) slot.partnerSpot.x = std::max(slot.partnerSpot.x, pathBounds.upper.x + kPartnerClearance);
        slot.path = pathBounds;
        for (std::size_t k = 0; k < sensors.size(); ++k) {
            GpuMesh orbit;
            orbit.upload(*m_gl, orbitTubeMesh(paths[k], slot.orbitRadius, orbitColour(int(s), int(k))));
            slot.orbits.push_back(std::move(orbit));
        }
        // The floor: under the lowest vertex of the figures at the first frame.
        const auto extent = [](const std::vector<Mesh>& figure, const std::vector<glm::mat4>& world_T_mesh, float& low, float& high) {
            low = std::numeric_limits<float>::max();
            high = std::numeric_limits<float>::lowest();
            for (std::size_t p = 0; p < figure.size() && p < world_T_mesh.size(); ++p)
                for (const Vertex& vertex : figure[p].vertices) {
                    const float z = (world_T_mesh[p] * glm::vec4(vertex.position, 1.0f)).z;
                    low = std::min(low, z);
                    high = std::max(high, z);
                }
            if (low > high) low = high = 0.0f;
        };
        std::vector<glm::mat4> partPoses;
        for (const auto& pose : analysis::worldPartPoses(slot.body, slot.binding, slot.take, 0)) partPoses.push_back(toMatrix(pose));
        extent(slotMeshes, partPoses, slot.puppetLowest, slot.puppetHighest);
        if (modelled) {
            if (const PuppetFigure* puppet = slotPuppet(slot))
                slot.partnerSkinJoint = analysis::puppetJointPoses(*puppet->mesh, slot.body, analysis::worldPartPoses(slot.body, slot.binding, slot.take, 0));
            Bounds figure;
            addPuppetBounds(figure, slot, 0, glm::mat4(1.0f), {});
            slot.puppetLowest = figure.lower.z;
            slot.puppetHighest = figure.upper.z;
        }
        if (slot.take.skeleton) {
            slot.skeleton = skeletonFigure(*slot.take.skeleton, reusable);
            // Joint spheres are the figure's extremes (bones are thinner).
            slot.skeletonLowest = std::numeric_limits<float>::max();
            slot.skeletonHighest = std::numeric_limits<float>::lowest();
            for (const auto& pose : slot.take.skeleton->worldPoses(0)) {
                slot.skeletonLowest = std::min(slot.skeletonLowest, float(pose.translation.z()) - slot.skeleton->jointRadius);
                slot.skeletonHighest = std::max(slot.skeletonHighest, float(pose.translation.z()) + slot.skeleton->jointRadius);
            }
        }
        m_slots.push_back(std::move(slot));
    }
    for (auto& unused : reusable)
        if (unused && unused.use_count() == 1) unused->release(*m_gl);
    for (auto& unused : reusablePuppets)
        if (unused && unused.use_count() == 1) unused->release(*m_gl);
    // The floor reaches past every take's path (a walk), whichever side the camera puts a take.
    m_floorHalfExtent = m_layout.gridHalfExtent;
    for (const Slot& slot : m_slots) {
        if (slot.path.empty()) continue;
        const glm::vec3 origin = m_layout.centreTakes ? slot.centre : glm::vec3(0.0f);
        const float reach = std::max({std::abs(slot.path.lower.x - origin.x), std::abs(slot.path.upper.x - origin.x),
                                      std::abs(slot.path.lower.y - origin.y), std::abs(slot.path.upper.y - origin.y),
                                      std::abs(slot.partnerSpot.x - origin.x)});
        const float separation = m_slots.size() > 1 ? 0.5f * m_layout.separation * framedHeight() / kPuppetFramedHeight : 0.0f;
        // The floor fades from 55 % of its half extent: the path stays on the unfaded part.
        m_floorHalfExtent = std::max(m_floorHalfExtent, (reach + separation + 40.0f) / 0.55f);
    }
    m_floorHalfExtent = std::min(std::ceil(m_floorHalfExtent / m_layout.gridSpacing) * m_layout.gridSpacing, kMaxFloorHalfExtent);
    m_grid.upload(*m_gl, gridMesh(m_floorHalfExtent, m_layout.gridSpacing));
    m_floor.upload(*m_gl, floorMesh(m_floorHalfExtent));
    setFrame(0);
    return analysis::okStatus();
}

std::shared_ptr<Renderer::PuppetFigure> Renderer::puppetFigure(const analysis::BodyDescription& body,
                                                               std::vector<std::shared_ptr<PuppetFigure>>& reusable)
{
    std::vector<Eigen::Matrix4d> fits;
    for (const auto& part : body.parts) fits.push_back(part.fit.matrix());
    for (const auto& figure : reusable)
        if (figure->fits == fits) return figure;
    auto figure = std::make_shared<PuppetFigure>();
    figure->fits = fits;
    const analysis::PuppetMesh& shipped = analysis::shippedPuppetMesh();
    const bool identity = std::all_of(fits.begin(), fits.end(), [](const Eigen::Matrix4d& m) { return m.isIdentity(0.0); });
    figure->mesh = identity ? std::shared_ptr<const analysis::PuppetMesh>(&shipped, [](const analysis::PuppetMesh*) {})
                            : std::make_shared<const analysis::PuppetMesh>(analysis::fittedPuppetMesh(shipped, body));
    figure->gpu.upload(*m_gl, *figure->mesh);
    const analysis::PuppetMesh& mesh = *figure->mesh;
    std::array<analysis::RigidTransform, analysis::kPuppetJointCount> joint_T_model;
    for (int j = 0; j < analysis::kPuppetJointCount; ++j) joint_T_model[std::size_t(j)] = mesh.bindPoses[std::size_t(j)].inverse();
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const int j = mesh.dominantJoint(v);
        const Eigen::Vector3d local = joint_T_model[std::size_t(j)].apply(mesh.positions[v].cast<double>());
        figure->jointBounds[std::size_t(j)].add(glm::vec3(float(local.x()), float(local.y()), float(local.z())));
    }
    reusable.push_back(figure);
    return figure;
}

bool Renderer::drawBody(const Slot& slot, int takeSlot, const glm::mat4& root, const glm::mat4& viewProjection, const glm::vec3& eye,
                        bool partIds)
{
    SkeletonFigure& figure = *slot.skeleton;
    if (!figure.bodyTried) {
        figure.bodyTried = true;
        auto made = analysis::performerBody(*slot.take.skeleton);
        if (made.ok()) {
            figure.body = std::make_shared<const analysis::PerformerBody>(std::move(made).value());
            figure.bodyGpu.upload(*m_gl, figure.body->mesh);
        }
    }
    if (!figure.body) return false;
    QOpenGLExtraFunctions& gl = *m_gl;
    m_bodyProgram->bind();
    const auto at = [this](const char* name) { return m_bodyUniforms.at(name); };
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(root)));
    gl.glUniformMatrix4fv(at("u_model"), 1, GL_FALSE, glm::value_ptr(root));
    gl.glUniformMatrix3fv(at("u_normalMatrix"), 1, GL_FALSE, glm::value_ptr(normalMatrix));
    gl.glUniformMatrix4fv(at("u_viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    gl.glUniform3f(at("u_lightPosition"), eye.x, eye.y, eye.z);
    const glm::vec3 key = keyLightDirection();
    gl.glUniform3f(at("u_keyDirection"), key.x, key.y, key.z);
    gl.glUniform4f(at("u_colour"), 1.0f, 1.0f, 1.0f, 1.0f);
    gl.glUniform1i(at("u_useVertexColour"), 1);
    gl.glUniform1i(at("u_lit"), 1);
    gl.glUniform1i(at("u_partIdBase"), partIds ? kSkeletonId + 1 + kIdsPerSlot * takeSlot : -1);
    gl.glUniform1i(at("u_boneIds"), 1);
    const auto skinning = analysis::bodySkinningTransforms(*figure.body, slot.take.skeleton->worldPoses(slot.frame));
    std::vector<glm::vec4> real(skinning.size()), dual(skinning.size());
    for (std::size_t j = 0; j < skinning.size(); ++j) {
        const analysis::DualQuaternion q = analysis::DualQuaternion::fromRigid(skinning[j]);
        real[j] = glm::vec4(float(q.real.x()), float(q.real.y()), float(q.real.z()), float(q.real.w()));
        dual[j] = glm::vec4(float(q.dual.x()), float(q.dual.y()), float(q.dual.z()), float(q.dual.w()));
    }
    gl.glUniform4fv(at("u_jointReal"), GLsizei(real.size()), glm::value_ptr(real[0]));
    gl.glUniform4fv(at("u_jointDual"), GLsizei(dual.size()), glm::value_ptr(dual[0]));
    figure.bodyGpu.draw(gl);
    m_program->bind();
    return true;
}

const Renderer::PuppetFigure* Renderer::slotPuppet(const Slot& slot) const
{
    return slot.puppet ? slot.puppet.get() : m_puppet.get();
}

void Renderer::addPuppetBounds(Bounds& bounds, const Slot& slot, Eigen::Index frame, const glm::mat4& root,
                               const std::function<bool(const std::string&, const std::string&)>& wanted) const
{
    const PuppetFigure* figure = slotPuppet(slot);
    if (!figure) return;
    const auto joints = analysis::puppetJointPoses(*figure->mesh, slot.body, analysis::worldPartPoses(slot.body, slot.binding, slot.take, frame));
    const auto partOf = analysis::puppetJointPartIndices(slot.body);
    for (int j = 0; j < analysis::kPuppetJointCount; ++j) {
        const Bounds& box = figure->jointBounds[std::size_t(j)];
        const int p = partOf[std::size_t(j)];
        if (box.empty() || p < 0) continue;
        if (wanted && !wanted(slot.body.parts[std::size_t(p)].name, slot.body.parts[std::size_t(p)].drivenBy)) continue;
        const glm::mat4 world_T_joint = root * toMatrix(joints[std::size_t(j)]);
        for (int corner = 0; corner < 8; ++corner)
            bounds.add(glm::vec3(world_T_joint * glm::vec4((corner & 1) ? box.upper.x : box.lower.x, (corner & 2) ? box.upper.y : box.lower.y,
                                                           (corner & 4) ? box.upper.z : box.lower.z, 1.0f)));
    }
}

std::shared_ptr<Renderer::SkeletonFigure> Renderer::skeletonFigure(const analysis::SkeletalMotion& motion,
                                                                   std::vector<std::shared_ptr<SkeletonFigure>>& reusable)
{
    for (const auto& figure : reusable)
        if (figure->skeleton == motion.skeleton && figure->movingJoints == motion.movingJoints && figure->bones == motion.staticTranslations)
            return figure;
    auto figure = std::make_shared<SkeletonFigure>();
    figure->skeleton = motion.skeleton;
    figure->bones = motion.staticTranslations;
    figure->movingJoints = motion.movingJoints;
    figure->jointRadius = skeletonJointRadius(motion);
    const std::vector<Mesh> meshes = buildSkeletonMeshes(motion);
    figure->meshes.resize(meshes.size());
    for (std::size_t j = 0; j < meshes.size(); ++j) figure->meshes[j].upload(*m_gl, meshes[j]);
    for (std::size_t j = 0; j < motion.skeleton->joints.size(); ++j) {
        figure->jointNames.push_back(motion.skeleton->joints[j].name);
        figure->jointParts.push_back(jointPart(*motion.skeleton, int(j)));
    }
    reusable.push_back(figure);
    return figure;
}

void Renderer::updatePoses(Slot& slot) const
{
    const auto poses = analysis::worldPartPoses(slot.body, slot.binding, slot.take, slot.frame);
    slot.take_T_part.resize(poses.size());
    for (std::size_t p = 0; p < poses.size(); ++p) slot.take_T_part[p] = toMatrix(poses[p]);
    if (const PuppetFigure* figure = slotPuppet(slot)) slot.take_T_skinJoint = analysis::puppetJointPoses(*figure->mesh, slot.body, poses);
    slot.take_T_joint.clear();
    if (slot.take.skeleton)
        for (const auto& pose : slot.take.skeleton->worldPoses(slot.frame)) slot.take_T_joint.push_back(toMatrix(pose));
}

void Renderer::setFrame(Eigen::Index frame)
{
    for (Slot& slot : m_slots) {
        slot.frame = std::clamp<Eigen::Index>(frame, 0, slot.take.frameCount() - 1);
        updatePoses(slot);
    }
}

void Renderer::setTime(double seconds)
{
    for (Slot& slot : m_slots) {
        slot.frame = frameAtTime(slot.take, seconds);
        updatePoses(slot);
    }
}

bool Renderer::hasScene() const { return !m_slots.empty(); }

int Renderer::takeCount() const { return int(m_slots.size()); }

Eigen::Index Renderer::frame(int takeSlot) const { return m_slots.at(std::size_t(takeSlot)).frame; }

glm::mat4 Renderer::takeRoot(int takeSlot, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    LayoutOptions layout = m_layout;
    layout.separation *= framedHeight() / kPuppetFramedHeight;
    return slotRoot(slot.centre, takeSlot, int(m_slots.size()), camera, layout);
}

std::vector<glm::mat4> Renderer::displayedPartTransforms(int takeSlot, const Camera& camera) const
{
    const glm::mat4 root = takeRoot(takeSlot, camera);
    std::vector<glm::mat4> result;
    for (const glm::mat4& take_T_part : m_slots.at(std::size_t(takeSlot)).take_T_part) result.push_back(root * take_T_part);
    return result;
}

std::optional<glm::mat4> Renderer::displayedAxisTransform(int takeSlot, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    if (slot.world_T_axis.empty()) return std::nullopt;
    return takeRoot(takeSlot, camera) * toMatrix(slot.world_T_axis[std::size_t(slot.frame)]);
}

std::vector<glm::vec3> Renderer::displayedSensorPositions(int takeSlot, Eigen::Index frame, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    const glm::mat4 root = takeRoot(takeSlot, camera);
    const Eigen::Index f = std::clamp<Eigen::Index>(frame, 0, slot.take.frameCount() - 1);
    std::vector<glm::vec3> result;
    for (const Eigen::Index first : slot.sensorFirstChannel)
        result.push_back(glm::vec3(root * glm::vec4(sensorPosition(slot.take, f, first), 1.0f)));
    return result;
}

std::vector<glm::mat4> Renderer::displayedJointTransforms(int takeSlot, const Camera& camera) const
{
    const glm::mat4 root = takeRoot(takeSlot, camera);
    std::vector<glm::mat4> result;
    for (const glm::mat4& take_T_joint : m_slots.at(std::size_t(takeSlot)).take_T_joint) result.push_back(root * take_T_joint);
    return result;
}

bool Renderer::skeletonDrawn(int takeSlot) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    return m_visibility.puppet && slot.take.skeleton && m_visibility.figures[std::size_t(takeSlot)] != FigureStyle::Puppet;
}

bool Renderer::puppetDrawn(int takeSlot) const
{
    return m_visibility.puppet && (!skeletonDrawn(takeSlot) || m_visibility.figures[std::size_t(takeSlot)] == FigureStyle::PuppetAndSkeleton);
}

float Renderer::floorHeight() const
{
    float lowest = std::numeric_limits<float>::max();
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        const bool skeleton = skeletonDrawn(int(s));
        if (!skeleton || puppetDrawn(int(s))) lowest = std::min(lowest, m_slots[s].puppetLowest);
        if (skeleton) lowest = std::min(lowest, m_slots[s].skeletonLowest);
    }
    return lowest == std::numeric_limits<float>::max() ? 0.0f : lowest - 1.0f;
}

float Renderer::framedHeight() const
{
    // A drawn skeleton, or a puppet fitted to a taller performer, is framed by its height (the
    // shipped puppet by the height the distances were chosen for); two such takes side by side
    // then stand as far apart as they are tall, so a raised arm does not reach into the other.
    const float floor = floorHeight();
    float height = kPuppetFramedHeight;
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        if (skeletonDrawn(int(s))) height = std::max(height, m_slots[s].skeletonHighest - floor);
        if (puppetDrawn(int(s))) height = std::max(height, m_slots[s].puppetHighest - floor);
    }
    return height;
}

Camera Renderer::framingCamera() const
{
    Camera camera;
    camera.angleDeg = 340.0f;
    camera.elevationDeg = 15.0f;
    const float floor = floorHeight();
    const float height = framedHeight();
    camera.target = {0.0f, 0.0f, floor + 0.5f * height};
    camera.distance = (m_slots.size() > 1 ? 300.0f : 230.0f) * height / kPuppetFramedHeight;
    return camera;
}

Bounds Renderer::displayedBounds(const Camera& camera, const BoundsQuery& query) const
{
    const Eigen::Index sampled = std::max(1, query.sampledFrames);
    Bounds bounds;
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        if (query.takeSlot >= 0 && query.takeSlot != int(s)) continue;
        const Slot& slot = m_slots[s];
        const glm::mat4 root = takeRoot(int(s), camera);
        std::vector<Eigen::Index> frames{slot.frame};
        if (query.span == FramingSpan::WholeTake) {
            frames.clear();
            const Eigen::Index count = slot.take.frameCount();
            const Eigen::Index step = std::max<Eigen::Index>(1, count / sampled);
            for (Eigen::Index f = 0; f < count; f += step) frames.push_back(f);
            frames.push_back(count - 1);
        }
        const auto wanted = [&](const std::string& name, const std::string& drivenBy) {
            return query.part.empty() || name == query.part || drivenBy == query.part;
        };
        if (puppetDrawn(int(s)) && slotPuppet(slot)) {
            for (const Eigen::Index f : frames) addPuppetBounds(bounds, slot, f, root, wanted);
        } else if (puppetDrawn(int(s))) {
            for (const Eigen::Index f : frames) {
                const auto poses = analysis::worldPartPoses(m_body, slot.binding, slot.take, f);
                for (std::size_t p = 0; p < poses.size() && p < m_partBounds.size(); ++p) {
                    if (!wanted(m_body.parts[p].name, m_body.parts[p].drivenBy) || m_partBounds[p].empty()) continue;
                    const glm::mat4 world_T_part = root * toMatrix(poses[p]);
                    const Bounds& box = m_partBounds[p];
                    for (int corner = 0; corner < 8; ++corner)
                        bounds.add(glm::vec3(world_T_part * glm::vec4((corner & 1) ? box.upper.x : box.lower.x,
                                                                      (corner & 2) ? box.upper.y : box.lower.y,
                                                                      (corner & 4) ? box.upper.z : box.lower.z, 1.0f)));
                }
            }
        }
        // The skeleton: every joint (a sphere of the joint radius; the bones run between them;
        // the body's trunk is up to 7.5 % of the height thick).
        if (skeletonDrawn(int(s)) && slot.skeleton) {
            const float radius = m_visibility.figures[s] == FigureStyle::Body
                                     ? std::max(slot.skeleton->jointRadius, 0.08f * (slot.skeletonHighest - slot.skeletonLowest))
                                     : slot.skeleton->jointRadius;
            for (const Eigen::Index f : frames) {
                const auto poses = slot.take.skeleton->worldPoses(f);
                for (std::size_t j = 0; j < poses.size(); ++j) {
                    const std::string& part = j < slot.skeleton->jointParts.size() ? slot.skeleton->jointParts[j] : std::string();
                    const std::string& name = j < slot.skeleton->jointNames.size() ? slot.skeleton->jointNames[j] : std::string();
                    if (!wanted(name, part)) continue;
                    const glm::vec3 joint(root * glm::vec4(float(poses[j].translation.x()), float(poses[j].translation.y()),
                                                           float(poses[j].translation.z()), 1.0f));
                    bounds.add(joint - glm::vec3(radius));
                    bounds.add(joint + glm::vec3(radius));
                }
            }
        }
        // The orbits, or the sensors standing for a hidden puppet.
        if (m_visibility.orbitsDrawn() || !m_visibility.puppet) {
            for (const Eigen::Index first : slot.sensorFirstChannel) {
                if (!wanted(slot.take.channels[std::size_t(first)].part, {})) continue;
                for (const Eigen::Index f : frames) bounds.add(glm::vec3(root * glm::vec4(sensorPosition(slot.take, f, first), 1.0f)));
            }
        }
        if (!query.part.empty()) continue;
        if (partnerShown(int(s), camera) && !query.figuresOnly) {
            // The take's puppet as it stands at frame 0, or partnerMesh: a disc of radius 14 cm
            // under a cone 46 cm high.
            const glm::mat4 world_T_partner = partnerTransform(slot, root);
            if (slotPuppet(slot)) {
                addPuppetBounds(bounds, slot, 0, world_T_partner, {});
            } else {
                for (const glm::vec3 corner : {glm::vec3(-14.0f, -14.0f, 0.0f), glm::vec3(14.0f, 14.0f, 46.0f)})
                    bounds.add(glm::vec3(world_T_partner * glm::vec4(corner, 1.0f)));
            }
        }
        if (m_visibility.axis && !slot.world_T_axis.empty()) {
            for (const Eigen::Index f : frames) {
                const glm::mat4 world_T_axis = root * toMatrix(slot.world_T_axis[std::size_t(f)]);
                for (int axis = 0; axis < 3; ++axis) {
                    glm::vec4 tip(0.0f, 0.0f, 0.0f, 1.0f);
                    tip[axis] = m_layout.axisBarLength;
                    bounds.add(glm::vec3(world_T_axis * tip));
                }
                bounds.add(glm::vec3(world_T_axis[3]));
            }
        }
    }
    return bounds;
}

void Renderer::setModel(const glm::mat4& model)
{
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    m_gl->glUniformMatrix4fv(m_uniforms.model, 1, GL_FALSE, glm::value_ptr(model));
    m_gl->glUniformMatrix3fv(m_uniforms.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
}

void Renderer::setColour(const glm::vec3& colour, bool vertexColour, bool lit)
{
    m_gl->glUniform4f(m_uniforms.colour, colour.r, colour.g, colour.b, 1.0f);
    m_gl->glUniform1i(m_uniforms.useVertexColour, vertexColour ? 1 : 0);
    m_gl->glUniform1i(m_uniforms.lit, lit ? 1 : 0);
}

std::optional<glm::mat4> Renderer::drawShadowMap(const Camera& camera, QSize size)
{
    if (!m_visibility.grid || !m_visibility.shadows || m_slots.empty()) return std::nullopt;
    BoundsQuery query;
    query.span = FramingSpan::CurrentFrame;
    const Bounds casters = displayedBounds(camera, query);
    if (casters.empty() || !m_shadowMap.ensure(*m_gl, kShadowMapSize)) return std::nullopt;
    QOpenGLExtraFunctions& gl = *m_gl;
    const glm::mat4 light = shadowViewProjection(casters, floorHeight(), keyLightDirection(), kShadowMapSize);
    // The map depends on the light's box, the figures' poses and where each take stands: kept
    // while none of them changes (the camera turning around a still frame of one take).
    std::vector<float> key(glm::value_ptr(light), glm::value_ptr(light) + 16);
    key.push_back(float(m_sceneGeneration));
    key.push_back(float(m_shadowMap.texture()));
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        const glm::mat4 root = takeRoot(int(s), camera);
        key.insert(key.end(), glm::value_ptr(root), glm::value_ptr(root) + 16);
        key.push_back(float(m_slots[s].frame));
        key.push_back(float(int(puppetDrawn(int(s))) + 2 * int(skeletonDrawn(int(s))) + 4 * int(partnerShown(int(s), camera))));
    }
    if (key == m_shadowKey) return light;
    m_shadowKey = std::move(key);
    GLint previous = 0;
    gl.glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    // The map is written, not read, in this pass: no texture unit may hold it meanwhile.
    m_shadowMap.unbindFromReading(gl, 1, 2);
    m_shadowMap.beginWriting(gl);
    m_program->bind();
    gl.glUniform1i(m_uniforms.shadows, 0);
    gl.glUniform1i(m_uniforms.floor, 0);
    gl.glUniformMatrix4fv(m_uniforms.viewProjection, 1, GL_FALSE, glm::value_ptr(light));
    drawFigures(camera, light, camera.eye(), Pass::Shadow);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    gl.glViewport(0, 0, size.width(), size.height());
    return light;
}

void Renderer::drawFigures(const Camera& camera, const glm::mat4& viewProjection, const glm::vec3& eye, Pass pass)
{
    QOpenGLExtraFunctions& gl = *m_gl;
    const bool ids = pass != Pass::Colour;
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        const Slot& slot = m_slots[s];
        const glm::mat4 root = takeRoot(int(s), camera);
        if (puppetDrawn(int(s)) && slotPuppet(slot)) {
            drawPuppet(slot, int(s), root, viewProjection, eye, ids);
        } else if (puppetDrawn(int(s))) {
            const std::vector<GpuMesh>& meshes = slot.meshes.empty() ? m_partMeshes : slot.meshes;
            for (std::size_t p = 0; p < meshes.size() && p < slot.take_T_part.size(); ++p) {
                setModel(root * slot.take_T_part[p]);
                if (ids)
                    setColour(glm::vec3(float(1 + int(p) + kIdsPerSlot * int(s)) / 255.0f, 0.0f, 0.0f), false, false);
                else
                    setColour(glm::vec3(1.0f), true, true);
                meshes[p].draw(gl);
            }
        }
        if (skeletonDrawn(int(s)) && m_visibility.figures[s] == FigureStyle::Body && drawBody(slot, int(s), root, viewProjection, eye, ids)) {
            // the performer's body, skinned to the skeleton
        } else if (skeletonDrawn(int(s))) {
            for (std::size_t j = 0; j < slot.skeleton->meshes.size() && j < slot.take_T_joint.size(); ++j) {
                if (slot.skeleton->meshes[j].empty()) continue; // End Sites
                setModel(root * slot.take_T_joint[j]);
                if (ids) {
                    const int id = int(j) + 1;
                    setColour(glm::vec3(float(kSkeletonId + 1 + kIdsPerSlot * int(s)), float(id % 256), float(id / 256)) / 255.0f, false, false);
                } else {
                    setColour(glm::vec3(1.0f), true, true);
                }
                slot.skeleton->meshes[j].draw(gl);
            }
        }
        if (pass != Pass::PartIds && partnerShown(int(s), camera)) {
            const glm::mat4 world_T_partner = partnerTransform(slot, root);
            if (const PuppetFigure* puppet = slotPuppet(slot)) {
                drawPartnerPuppet(slot, *puppet, world_T_partner, viewProjection, eye, pass == Pass::Shadow);
            } else {
                setModel(world_T_partner);
                setColour(glm::vec3(1.0f), true, pass == Pass::Colour);
                m_partner.draw(gl);
            }
        }
    }
}

void Renderer::drawScene(const Camera& camera, QSize size, bool partIds)
{
    QOpenGLExtraFunctions& gl = *m_gl;
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(GL_LESS);
    gl.glDisable(GL_CULL_FACE);
    gl.glDisable(GL_BLEND);
    const std::optional<glm::mat4> light = partIds ? std::nullopt : drawShadowMap(camera, size);
    gl.glViewport(0, 0, size.width(), size.height());
    const glm::vec3 background = partIds ? glm::vec3(0.0f) : kBackground;
    gl.glClearColor(background.r, background.g, background.b, partIds ? 0.0f : 1.0f);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (partIds) gl.glDisable(GL_DITHER);

    m_program->bind();
    gl.glUniform1i(m_uniforms.partIdBase, -1);
    gl.glUniform1i(m_uniforms.floor, 0);
    const glm::mat4 viewProjection = camera.viewProjection(size);
    gl.glUniformMatrix4fv(m_uniforms.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    const glm::vec3 eye = camera.eye();
    gl.glUniform3f(m_uniforms.lightPosition, eye.x, eye.y, eye.z);
    const glm::vec3 key = keyLightDirection();
    gl.glUniform3f(m_uniforms.keyDirection, key.x, key.y, key.z);

    if (m_visibility.grid && !partIds && !m_slots.empty()) {
        gl.glUniform1i(m_uniforms.floor, 1);
        gl.glUniform1f(m_uniforms.floorRadius, m_floorHalfExtent);
        gl.glUniform3f(m_uniforms.background, kBackground.r, kBackground.g, kBackground.b);
        gl.glUniform1i(m_uniforms.shadows, light ? 1 : 0);
        if (light) {
            m_shadowMap.bindForReading(gl, 1, 2);
            gl.glUniformMatrix4fv(m_uniforms.lightViewProjection, 1, GL_FALSE, glm::value_ptr(*light));
            // The light's box is 2 / |row 0| cm wide and 2 / |row 2| cm deep (rows of unit vectors).
            const glm::mat4& m = *light;
            gl.glUniform1f(m_uniforms.shadowUvPerCm, 0.5f * glm::length(glm::vec3(m[0][0], m[1][0], m[2][0])));
            gl.glUniform1f(m_uniforms.shadowCmPerDepth, 2.0f / glm::length(glm::vec3(m[0][2], m[1][2], m[2][2])));
        }
        const glm::mat4 floor = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, floorHeight()));
        setModel(floor);
        setColour(glm::vec3(1.0f), true, false);
        // The square just behind the grid's lines, which lie in its plane.
        gl.glEnable(GL_POLYGON_OFFSET_FILL);
        gl.glPolygonOffset(1.0f, 1.0f);
        m_floor.draw(gl);
        gl.glDisable(GL_POLYGON_OFFSET_FILL);
        m_grid.draw(gl);
        gl.glUniform1i(m_uniforms.floor, 0);
        gl.glUniform1i(m_uniforms.shadows, 0);
    }

    drawFigures(camera, viewProjection, eye, partIds ? Pass::PartIds : Pass::Colour);
    for (std::size_t s = 0; s < m_slots.size() && !partIds; ++s) {
        const Slot& slot = m_slots[s];
        const glm::mat4 root = takeRoot(int(s), camera);
        if (m_visibility.orbitsDrawn()) {
            // Over the puppet, like the motion axis: the sensors sit inside its parts.
            gl.glDepthRangef(0.0f, 0.0005f);
            setModel(root);
            setColour(glm::vec3(1.0f), true, true);
            for (const GpuMesh& orbit : slot.orbits) orbit.draw(gl);
            const float pointRadius = std::max(m_layout.orbitPointRadius, 2.5f * slot.orbitRadius);
            for (std::size_t k = 0; k < slot.sensorFirstChannel.size(); ++k) {
                const glm::vec3 position = sensorPosition(slot.take, slot.frame, slot.sensorFirstChannel[k]);
                setModel(root * glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(pointRadius)));
                setColour(orbitColour(int(s), int(k)), false, true);
                m_sphere.draw(gl);
            }
            gl.glDepthRangef(0.0f, 1.0f);
        }
    }

    // The motion axis is drawn over the puppet (its centre of mass lies inside the body): its
    // depths are squeezed in front of everything else, still ordered among its bars. (Cheaper
    // than clearing the depth buffer mid-frame on tiled software rasterisers.)
    if (m_visibility.axis && !partIds) {
        gl.glDepthRangef(0.0f, 0.0005f);
        const float length = m_layout.axisBarLength;
        const float thickness = m_layout.axisBarThickness;
        for (std::size_t s = 0; s < m_slots.size(); ++s) {
            const auto world_T_axis = displayedAxisTransform(int(s), camera);
            if (!world_T_axis) continue;
            for (int axis = 0; axis < 3; ++axis) {
                glm::vec3 centre(0.0f);
                glm::vec3 extent(thickness);
                centre[axis] = length * 0.5f;
                extent[axis] = length;
                setModel(*world_T_axis * glm::scale(glm::translate(glm::mat4(1.0f), centre), extent));
                setColour(axisColour(axis), false, true);
                m_box.draw(gl);
            }
        }
        gl.glDepthRangef(0.0f, 1.0f);
    }
    m_program->release();
    if (partIds) gl.glEnable(GL_DITHER);
}

void Renderer::drawPuppet(const Slot& slot, int takeSlot, const glm::mat4& root, const glm::mat4& viewProjection,
                          const glm::vec3& eye, bool partIds)
{
    QOpenGLExtraFunctions& gl = *m_gl;
    const PuppetFigure& figure = *slotPuppet(slot);
    m_skinProgram->bind();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(root)));
    gl.glUniformMatrix4fv(m_skinUniforms.model, 1, GL_FALSE, glm::value_ptr(root));
    gl.glUniformMatrix3fv(m_skinUniforms.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    gl.glUniformMatrix4fv(m_skinUniforms.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    gl.glUniform3f(m_skinUniforms.lightPosition, eye.x, eye.y, eye.z);
    const glm::vec3 key = keyLightDirection();
    gl.glUniform3f(m_skinUniforms.keyDirection, key.x, key.y, key.z);
    gl.glUniform4f(m_skinUniforms.colour, 1.0f, 1.0f, 1.0f, 1.0f);
    gl.glUniform1i(m_skinUniforms.useVertexColour, 1);
    gl.glUniform1i(m_skinUniforms.lit, 1);
    gl.glUniform1i(m_skinUniforms.partIdBase, partIds ? 1 + kIdsPerSlot * takeSlot : -1);
    const JointDualQuaternions q = jointDualQuaternions(*figure.mesh, slot.take_T_skinJoint);
    gl.glUniform4fv(m_skinUniforms.jointReal, analysis::kPuppetJointCount, glm::value_ptr(q.real[0]));
    gl.glUniform4fv(m_skinUniforms.jointDual, analysis::kPuppetJointCount, glm::value_ptr(q.dual[0]));
    const auto partOf = analysis::puppetJointPartIndices(slot.body);
    gl.glUniform1iv(m_skinUniforms.partOfJoint, analysis::kPuppetJointCount, partOf.data());
    figure.gpu.draw(gl);
    m_program->bind();
}

glm::mat4 Renderer::partnerTransform(const Slot& slot, const glm::mat4& root) const
{
    const glm::vec3 partner = slot.partnerSpot;
    const glm::mat4 onFloor = root * glm::translate(glm::mat4(1.0f), glm::vec3(partner.x, partner.y, floorHeight()));
    if (!slotPuppet(slot)) return onFloor;
    // The take's puppet as it stands at frame 0, turned about its centre to face the take, as
    // tall as the figure drawn (a performer's skeleton is taller than the puppet fitted to it).
    const int index = int(&slot - m_slots.data());
    const float puppetHeight = slot.puppetHighest - slot.puppetLowest;
    const float height = puppetDrawn(index) ? puppetHeight : slot.skeletonHighest - slot.skeletonLowest;
    const float scale = puppetHeight > 1.0f && height > 1.0f ? height / puppetHeight : 1.0f;
    return glm::scale(glm::rotate(onFloor, glm::pi<float>(), glm::vec3(0.0f, 0.0f, 1.0f)), glm::vec3(scale)) *
           glm::translate(glm::mat4(1.0f), glm::vec3(-slot.centre.x, -slot.centre.y, -slot.puppetLowest));
}

bool Renderer::partnerShown(int takeSlot, const Camera& camera) const
{
    if (!m_visibility.partner) return false;
    // Two takes stand side by side along the screen's right: seen from the side, one take's
    // partner would stand inside the other take's figure, and is left out.
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    const glm::vec3 partner(takeRoot(takeSlot, camera) * glm::vec4(slot.partnerSpot, 1.0f));
    for (std::size_t other = 0; other < m_slots.size(); ++other) {
        if (int(other) == takeSlot) continue;
        const glm::vec3 figure(takeRoot(int(other), camera) * glm::vec4(m_slots[other].centre, 1.0f));
        if (glm::length(glm::vec2(partner - figure)) < 0.5f * framedHeight()) return false;
    }
    return true;
}

void Renderer::drawPartnerPuppet(const Slot& slot, const PuppetFigure& figure, const glm::mat4& world_T_model,
                                 const glm::mat4& viewProjection, const glm::vec3& eye, bool depthOnly)
{
    QOpenGLExtraFunctions& gl = *m_gl;
    m_skinProgram->bind();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world_T_model)));
    gl.glUniformMatrix4fv(m_skinUniforms.model, 1, GL_FALSE, glm::value_ptr(world_T_model));
    gl.glUniformMatrix3fv(m_skinUniforms.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    gl.glUniformMatrix4fv(m_skinUniforms.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    gl.glUniform3f(m_skinUniforms.lightPosition, eye.x, eye.y, eye.z);
    const glm::vec3 key = keyLightDirection();
    gl.glUniform3f(m_skinUniforms.keyDirection, key.x, key.y, key.z);
    // One colour (the partner is not a take): the puppet's shape and paint in slate.
    gl.glUniform4f(m_skinUniforms.colour, kPartnerColour.r, kPartnerColour.g, kPartnerColour.b, 1.0f);
    gl.glUniform1i(m_skinUniforms.useVertexColour, 0);
    gl.glUniform1i(m_skinUniforms.lit, depthOnly ? 0 : 1);
    gl.glUniform1i(m_skinUniforms.partIdBase, -1);
    const JointDualQuaternions rest = jointDualQuaternions(*figure.mesh, slot.partnerSkinJoint);
    gl.glUniform4fv(m_skinUniforms.jointReal, analysis::kPuppetJointCount, glm::value_ptr(rest.real[0]));
    gl.glUniform4fv(m_skinUniforms.jointDual, analysis::kPuppetJointCount, glm::value_ptr(rest.dual[0]));
    figure.gpu.draw(gl);
    m_program->bind();
}

void Renderer::render(const Camera& camera, QSize size)
{
    if (m_gl == nullptr || size.isEmpty()) return;
    drawScene(camera, size, false);
}

QOpenGLFramebufferObject& Renderer::pickFramebuffer(QSize size)
{
    if (!m_pickFramebuffer || m_pickFramebuffer->size() != size) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        format.setInternalTextureFormat(GL_RGBA8);
        m_pickFramebuffer = std::make_unique<QOpenGLFramebufferObject>(size, format);
    }
    return *m_pickFramebuffer;
}

QImage Renderer::partIdImage(const Camera& camera, QSize size)
{
    if (m_gl == nullptr || size.isEmpty()) return {};
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    QOpenGLFramebufferObject& framebuffer = pickFramebuffer(size);
    framebuffer.bind();
    drawScene(camera, size, true);
    QImage image = framebuffer.toImage();
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    return image;
}

std::optional<PickResult> Renderer::pick(const Camera& camera, QSize size, QPoint pixel)
{
    if (m_gl == nullptr || size.isEmpty() || !QRect(QPoint(0, 0), size).contains(pixel)) return std::nullopt;
    GLint previous = 0;
    m_gl->glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    QOpenGLFramebufferObject& framebuffer = pickFramebuffer(size);
    framebuffer.bind();
    drawScene(camera, size, true);
    unsigned char rgba[4] = {0, 0, 0, 0};
    m_gl->glReadPixels(pixel.x(), size.height() - 1 - pixel.y(), 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    m_gl->glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    return decodePartId(qRgba(rgba[0], rgba[1], rgba[2], rgba[3]));
}

std::optional<PickResult> Renderer::decodePartId(QRgb pixel) const
{
    const int id = qRed(pixel);
    if (id == 0) return std::nullopt;
    PickResult result;
    result.takeSlot = (id - 1) / kIdsPerSlot;
    result.partIndex = (id - 1) % kIdsPerSlot;
    if (result.takeSlot >= int(m_slots.size())) return std::nullopt;
    if (result.partIndex == kSkeletonId) {
        const Slot& slot = m_slots[std::size_t(result.takeSlot)];
        const int joint = qGreen(pixel) + 256 * qBlue(pixel) - 1;
        if (!slot.skeleton || joint < 0 || joint >= int(slot.skeleton->jointNames.size())) return std::nullopt;
        result.partIndex = -1;
        result.joint = joint;
        result.jointName = slot.skeleton->jointNames[std::size_t(joint)];
        result.partName = slot.skeleton->jointParts[std::size_t(joint)];
        return result;
    }
    if (result.partIndex >= int(m_partNames.size())) return std::nullopt;
    result.partName = m_partNames[std::size_t(result.partIndex)];
    return result;
}

} // namespace bunraku::render
