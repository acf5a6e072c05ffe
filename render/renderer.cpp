#include "render/renderer_internal.h"

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
    m_uniforms.shadowDraft = program->uniformLocation("u_shadowDraft");
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
    static const char* const kBodyUniformNames[BodyUniformCount] = {
        "u_model",        "u_viewProjection", "u_normalMatrix", "u_colour",    "u_useVertexColour", "u_lit",        "u_lightPosition",
        "u_partIdBase",   "u_boneIds",        "u_keyDirection", "u_jointReal", "u_jointDual",       "u_linearBlend"};
    for (int u = 0; u < BodyUniformCount; ++u) m_bodyUniforms[std::size_t(u)] = body->uniformLocation(kBodyUniformNames[u]);
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
    m_slotSources.clear(); // nothing is kept from buffers released
    m_slotsBuilt = 0;
    for (GpuMesh& mesh : m_partMeshes) mesh.release(*m_gl);
    m_partMeshes.clear();
    if (m_puppet) m_puppet->release(*m_gl);
    m_puppet.reset();
    for (Slot& slot : m_slots) {
        if (slot.puppet) slot.puppet->release(*m_gl);
        for (GpuMesh& orbit : slot.orbits) orbit.release(*m_gl);
        for (GpuMesh& orbit : slot.kimonoOrbits) orbit.release(*m_gl);
        if (slot.cloth && slot.cloth.use_count() == 1) slot.cloth->release(*m_gl);
        for (GpuMesh& mesh : slot.meshes) mesh.release(*m_gl);
        if (slot.skeleton) slot.skeleton->release(*m_gl);
        if (slot.partner) slot.partner->release(*m_gl);
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
    if (scene.takes.empty()) {
        // Nothing to draw (no take shown, or none the renderer can pose): the view is empty.
        releaseSceneBuffers();
        ++m_sceneGeneration;
        return analysis::okStatus();
    }
    // A slot made from what the same slot of the scene before was made from, in a scene of the
    // same body, no part meshes and the same layout, keeps its Slot (TakeSlot::sources).
    const bool sameStage = scene.bodySource && scene.bodySource == m_bodySource && scene.partMeshes.empty() && !m_sceneHadMeshes &&
                           layout == m_builtLayout;
    std::vector<bool> keep(scene.takes.size(), false);
    for (std::size_t s = 0; sameStage && s < scene.takes.size() && s < m_slots.size() && s < m_slotSources.size(); ++s)
        keep[s] = !scene.takes[s].sources.empty() && scene.takes[s].sources == m_slotSources[s];
    std::vector<analysis::Take> drawn; // each slot's take as the renderer poses it (drawnTake)
    if (auto status = validateScene(scene, &drawn, keep); !status.ok()) {
        // Nothing of the scene before stays drawn as if it were the new one's.
        releaseSceneBuffers();
        ++m_sceneGeneration;
        return status;
    }
    ++m_sceneGeneration;
    m_shadowKey.clear();
    std::vector<std::optional<Slot>> kept(scene.takes.size());
    for (std::size_t s = 0; s < keep.size(); ++s)
        if (keep[s]) {
            kept[s].emplace(std::move(m_slots[s]));
            m_slots[s] = Slot{}; // nothing of it is released below
        }
    std::vector<std::shared_ptr<SkeletonFigure>> reusable;
    for (Slot& slot : m_slots)
        if (slot.skeleton) reusable.push_back(std::move(slot.skeleton));
    std::vector<std::shared_ptr<PuppetFigure>> reusablePuppets;
    if (m_puppet) reusablePuppets.push_back(std::move(m_puppet));
    for (Slot& slot : m_slots)
        if (slot.puppet) reusablePuppets.push_back(std::move(slot.puppet));
    std::vector<std::shared_ptr<PartnerFigure>> reusablePartners;
    for (Slot& slot : m_slots)
        if (slot.partner) reusablePartners.push_back(std::move(slot.partner));
    // The cloth's buffers, by the cloth they hold (a scene is replaced on every step of a drag).
    std::vector<std::pair<std::shared_ptr<const analysis::KimonoCloth>, std::shared_ptr<ClothGpu>>> reusableCloths;
    for (Slot& slot : m_slots)
        if (slot.cloth && slot.kimono) reusableCloths.emplace_back(slot.kimono->cloth, std::move(slot.cloth));
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

    m_slotsBuilt = 0;
    for (std::size_t s = 0; s < scene.takes.size(); ++s) {
        if (kept[s]) {
            m_slots.push_back(std::move(*kept[s]));
            continue;
        }
        ++m_slotsBuilt;
        const TakeSlot& source = scene.takes[s];
        Slot slot;
        slot.body = source.body ? *source.body : m_body;
        slot.take = std::move(drawn[s]);
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
            if (const PuppetFigure* puppet = slotPuppet(slot)) {
                slot.partnerSkinJoint = analysis::puppetJointPoses(*puppet->mesh, slot.body, analysis::worldPartPoses(slot.body, slot.binding, slot.take, 0));
                slot.partner = partnerFigure(*puppet, slot.partnerSkinJoint, reusablePartners);
            }
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
            // The file's mesh at frame 0 (its soles may be below the ankles' spheres).
            if (takeHasFileMesh(slot.take)) {
                const analysis::SkeletonMesh& mesh = *slot.take.skeleton->skeleton->mesh;
                const auto skinned = analysis::skinSkeletonMesh(mesh, slot.take.skeleton->worldPoses(0));
                slot.fileMeshLowest = std::numeric_limits<float>::max();
                slot.fileMeshHighest = std::numeric_limits<float>::lowest();
                for (const Eigen::Vector3d& p : skinned) {
                    slot.fileMeshLowest = std::min(slot.fileMeshLowest, float(p.z()));
                    slot.fileMeshHighest = std::max(slot.fileMeshHighest, float(p.z()));
                }
                if (skinned.empty()) slot.fileMeshLowest = slot.fileMeshHighest = 0.0f;
            }
        }
        if (modelled && source.kimono) attachKimono(slot, source.kimono, int(s), reusableCloths);
        m_slots.push_back(std::move(slot));
    }
    for (auto& [cloth, gpu] : reusableCloths)
        if (gpu && gpu.use_count() == 1) gpu->release(*m_gl);
    for (auto& unused : reusable)
        if (unused && unused.use_count() == 1) unused->release(*m_gl);
    for (auto& unused : reusablePuppets)
        if (unused && unused.use_count() == 1) unused->release(*m_gl);
    for (auto& unused : reusablePartners)
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
    m_slotSources.clear();
    for (const TakeSlot& source : scene.takes) m_slotSources.push_back(source.sources);
    m_bodySource = scene.bodySource;
    m_sceneHadMeshes = !scene.partMeshes.empty();
    m_builtLayout = layout;
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
    figure->gpu.upload(*m_gl, *figure->mesh, true);
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

std::shared_ptr<Renderer::PartnerFigure> Renderer::partnerFigure(const PuppetFigure& puppet,
                                                                 const std::array<analysis::RigidTransform, analysis::kPuppetJointCount>& pose,
                                                                 std::vector<std::shared_ptr<PartnerFigure>>& reusable)
{
    for (const auto& figure : reusable)
        if (figure && figure->matches(puppet.mesh.get(), pose)) return figure;
    auto figure = std::make_shared<PartnerFigure>();
    figure->mesh = puppet.mesh;
    figure->joints = pose;
    const analysis::SkinnedSurface surface = analysis::skinPuppet(*puppet.mesh, pose);
    Mesh mesh;
    mesh.vertices.reserve(surface.positions.size());
    for (std::size_t v = 0; v < surface.positions.size(); ++v) {
        const Eigen::Vector3f& p = surface.positions[v];
        const Eigen::Vector3f& n = surface.normals[v];
        mesh.vertices.push_back(Vertex{glm::vec3(p.x(), p.y(), p.z()), glm::vec3(n.x(), n.y(), n.z()), kPartnerColour});
    }
    mesh.indices = puppet.mesh->indices;
    figure->gpu.upload(*m_gl, mesh);
    reusable.push_back(figure);
    return figure;
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
    // The file's mesh's reach from its joints, in the bind pose (rigid skinning keeps it).
    if (const auto& mesh = motion.skeleton->mesh; mesh && analysis::meshFitsSkeleton(*mesh, *motion.skeleton)) {
        for (std::size_t v = 0; v < mesh->vertexCount(); ++v)
            for (int k = 0; k < 4; ++k) {
                const std::size_t j = mesh->joints[v][std::size_t(k)];
                if (mesh->weights[v][k] > 0.0f && j < mesh->bindPoses.size())
                    figure->fileMeshReach = std::max(figure->fileMeshReach,
                                                     float((mesh->positions[v].cast<double>() - mesh->bindPoses[j].translation).norm()));
            }
    }
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

void Renderer::attachKimono(Slot& slot, const std::shared_ptr<const analysis::KimonoSimulation>& kimono, int slotIndex,
                            std::vector<std::pair<std::shared_ptr<const analysis::KimonoCloth>, std::shared_ptr<ClothGpu>>>& reusable)
{
    const PuppetFigure* puppet = slotPuppet(slot);
    if (!puppet || !kimono->cloth || kimono->frameCount() != slot.take.frameCount() || kimono->body.parts.size() != slot.body.parts.size())
        return;
    // Simulated on the body this take is drawn with, or not shown (the skinned kimono is).
    for (std::size_t p = 0; p < slot.body.parts.size(); ++p)
        if (kimono->body.parts[p].name != slot.body.parts[p].name || !kimono->body.parts[p].fit.matrix().isApprox(slot.body.parts[p].fit.matrix(), 0.0))
            return;
    slot.kimono = kimono;
    slot.kimonoPlayer = std::make_unique<analysis::KimonoPlayer>(kimono, std::make_shared<const analysis::Take>(slot.take));
    for (auto& [cloth, gpu] : reusable)
        if (gpu && cloth == kimono->cloth) slot.cloth = gpu;
    if (!slot.cloth) {
        slot.cloth = std::make_shared<ClothGpu>();
        slot.cloth->upload(*m_gl, *kimono->cloth, *puppet->mesh);
    }
    // The measured points' orbits: the sleeve tips and the hem over the whole take.
    for (int point = 0; point < analysis::kKimonoPointCount; ++point) {
        std::vector<glm::vec3> path;
        path.reserve(std::size_t(kimono->frameCount()));
        for (Eigen::Index f = 0; f < kimono->frameCount(); ++f)
            path.emplace_back(float(kimono->points(f, 3 * point)), float(kimono->points(f, 3 * point + 1)), float(kimono->points(f, 3 * point + 2)));
        GpuMesh orbit;
        orbit.upload(*m_gl, orbitTubeMesh(path, slot.orbitRadius, kimonoOrbitColour(slotIndex, point)));
        slot.kimonoOrbits.push_back(std::move(orbit));
    }
    updateCloth(slot);
}

void Renderer::updateCloth(Slot& slot) const
{
    slot.clothReady = false;
    slot.clothUploaded = false;
    if (!slot.kimonoPlayer) return;
    // The frame's particles as simulated (stored), or stepped on by the player from the last
    // frame shown or the checkpoint before it (a take too long to store every frame).
    // Either way rounded to floats first, so both draw the same pixels.
    std::vector<Eigen::Vector3d> x(slot.kimono->cloth->size());
    if (const float* frame = slot.kimono->storedFrame(slot.frame)) {
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = Eigen::Vector3d(frame[3 * i], frame[3 * i + 1], frame[3 * i + 2]);
    } else {
        auto played = slot.kimonoPlayer->frame(slot.frame);
        if (!played || played.value()->size() != x.size()) return; // the skinned kimono is drawn
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = (*played.value())[i].cast<float>().cast<double>();
    }
    const std::vector<Eigen::Vector3f> normals = analysis::kimonoNormals(*slot.kimono->cloth, x);
    slot.clothVertices.resize(x.size() * 6);
    for (std::size_t i = 0; i < x.size(); ++i) {
        float* out = &slot.clothVertices[6 * i];
        for (int k = 0; k < 3; ++k) {
            out[k] = float(x[i][k]);
            out[3 + k] = normals[i][k];
        }
    }
    slot.clothReady = true;
}

void Renderer::updatePoses(Slot& slot) const
{
    updateCloth(slot);
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

} // namespace bunraku::render
