#include "render/renderer.h"

#include "analysis/core/puppet_layout.h"
#include "render/orbit_geometry.h"
#include "render/puppet_geometry.h"

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
const glm::vec3 kBackground(0.94f, 0.95f, 0.97f);
const glm::vec3 kPartnerColour(0.42f, 0.48f, 0.58f);

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

} // namespace

struct Renderer::Slot {
    analysis::Take take;
    analysis::BodyBinding binding;
    std::vector<analysis::RigidTransform> world_T_axis;
    glm::vec3 centre{0.0f};
    std::vector<Eigen::Index> sensorFirstChannel; ///< one per 6-DOF part of the take
    std::vector<GpuMesh> orbits;                  ///< one tube per sensor, take coordinates
    float orbitRadius = 0.4f;                     ///< cm, the tubes' (orbitTubeRadius)
    Eigen::Index frame = 0;
    std::vector<glm::mat4> take_T_part; ///< at `frame`, one per body part
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
    m_program = std::move(program);
    m_context = context;
    m_gl = context->extraFunctions();

    m_box.upload(*m_gl, boxMesh(glm::vec3(1.0f)));
    m_sphere.upload(*m_gl, ellipsoidMesh(glm::vec3(1.0f), 16, 10));
    m_partner.upload(*m_gl, partnerMesh());
    return analysis::okStatus();
}

void Renderer::releaseSceneBuffers()
{
    for (GpuMesh& mesh : m_partMeshes) mesh.release(*m_gl);
    m_partMeshes.clear();
    for (Slot& slot : m_slots)
        for (GpuMesh& orbit : slot.orbits) orbit.release(*m_gl);
    m_slots.clear();
    m_grid.release(*m_gl);
}

void Renderer::release()
{
    if (m_gl == nullptr) return;
    releaseSceneBuffers();
    m_box.release(*m_gl);
    m_sphere.release(*m_gl);
    m_partner.release(*m_gl);
    m_pickFramebuffer.reset();
    m_program.reset();
    m_gl = nullptr;
    m_context = nullptr;
}

analysis::Status Renderer::setScene(const SceneContent& scene, const LayoutOptions& layout)
{
    if (m_gl == nullptr)
        return analysis::makeError(analysis::ErrorCode::InvalidArgument, "the renderer is not initialised");
    if (auto status = validateScene(scene); !status.ok()) return status;
    releaseSceneBuffers();
    m_layout = layout;
    m_body = scene.body;
    m_partNames.clear();
    for (const auto& part : m_body.parts) m_partNames.push_back(part.name);

    const std::vector<Mesh> meshes = buildPuppetMeshes(m_body, scene.partMeshes);
    m_partMeshes.resize(meshes.size());
    for (std::size_t i = 0; i < meshes.size(); ++i) m_partMeshes[i].upload(*m_gl, meshes[i]);
    m_partBounds.assign(meshes.size(), Bounds{});
    for (std::size_t i = 0; i < meshes.size(); ++i)
        for (const Vertex& vertex : meshes[i].vertices) m_partBounds[i].add(vertex.position);

    float lowest = std::numeric_limits<float>::max();
    for (std::size_t s = 0; s < scene.takes.size(); ++s) {
        const TakeSlot& source = scene.takes[s];
        Slot slot;
        slot.take = source.take;
        slot.binding = analysis::bindBody(m_body, slot.take).value();
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
        for (std::size_t p = 0; p < firstPoses.size() && p < m_partBounds.size(); ++p)
            for (const glm::vec3& corner : {m_partBounds[p].lower, m_partBounds[p].upper})
                if (!m_partBounds[p].empty()) pathBounds.add(glm::vec3(toMatrix(firstPoses[p]) * glm::vec4(corner, 1.0f)));
        slot.orbitRadius = orbitTubeRadius(pathBounds.extent());
        for (std::size_t k = 0; k < sensors.size(); ++k) {
            GpuMesh orbit;
            orbit.upload(*m_gl, orbitTubeMesh(paths[k], slot.orbitRadius, orbitColour(int(s), int(k))));
            slot.orbits.push_back(std::move(orbit));
        }
        // The floor: under the lowest vertex of the puppet at the first frame.
        const auto poses = analysis::worldPartPoses(m_body, slot.binding, slot.take, 0);
        for (std::size_t p = 0; p < meshes.size(); ++p) {
            const glm::mat4 world_T_part = toMatrix(poses[p]);
            for (const Vertex& vertex : meshes[p].vertices)
                lowest = std::min(lowest, (world_T_part * glm::vec4(vertex.position, 1.0f)).z);
        }
        m_slots.push_back(std::move(slot));
    }
    m_floorHeight = lowest == std::numeric_limits<float>::max() ? 0.0f : lowest - 1.0f;
    m_grid.upload(*m_gl, gridMesh(m_layout.gridHalfExtent, m_layout.gridSpacing));
    setFrame(0);
    return analysis::okStatus();
}

void Renderer::setFrame(Eigen::Index frame)
{
    for (Slot& slot : m_slots) {
        slot.frame = std::clamp<Eigen::Index>(frame, 0, slot.take.frameCount() - 1);
        const auto poses = analysis::worldPartPoses(m_body, slot.binding, slot.take, slot.frame);
        slot.take_T_part.resize(poses.size());
        for (std::size_t p = 0; p < poses.size(); ++p) slot.take_T_part[p] = toMatrix(poses[p]);
    }
}

void Renderer::setTime(double seconds)
{
    for (Slot& slot : m_slots) {
        slot.frame = frameAtTime(slot.take, seconds);
        const auto poses = analysis::worldPartPoses(m_body, slot.binding, slot.take, slot.frame);
        slot.take_T_part.resize(poses.size());
        for (std::size_t p = 0; p < poses.size(); ++p) slot.take_T_part[p] = toMatrix(poses[p]);
    }
}

bool Renderer::hasScene() const { return !m_slots.empty(); }

int Renderer::takeCount() const { return int(m_slots.size()); }

Eigen::Index Renderer::frame(int takeSlot) const { return m_slots.at(std::size_t(takeSlot)).frame; }

glm::mat4 Renderer::takeRoot(int takeSlot, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    return slotRoot(slot.centre, takeSlot, int(m_slots.size()), camera, m_layout);
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

Camera Renderer::framingCamera() const
{
    Camera camera;
    camera.angleDeg = 340.0f;
    camera.elevationDeg = 15.0f;
    camera.target = {0.0f, 0.0f, m_floorHeight + 45.0f};
    camera.distance = m_slots.size() > 1 ? 300.0f : 230.0f;
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
        if (m_visibility.puppet) {
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
        // The orbits, or the sensors standing for a hidden puppet.
        if (m_visibility.orbitsDrawn() || !m_visibility.puppet) {
            for (const Eigen::Index first : slot.sensorFirstChannel) {
                if (!wanted(slot.take.channels[std::size_t(first)].part, {})) continue;
                for (const Eigen::Index f : frames) bounds.add(glm::vec3(root * glm::vec4(sensorPosition(slot.take, f, first), 1.0f)));
            }
        }
        if (!query.part.empty()) continue;
        if (m_visibility.partner && !query.figuresOnly) {
            // partnerMesh: a disc of radius 14 cm on the floor under a cone 46 cm high.
            const glm::vec3 partner = slot.centre + glm::vec3(m_layout.partnerDistance, 0.0f, 0.0f);
            for (const glm::vec3 corner : {glm::vec3(-14.0f, -14.0f, 0.0f), glm::vec3(14.0f, 14.0f, 46.0f)})
                bounds.add(glm::vec3(root * glm::vec4(partner.x + corner.x, partner.y + corner.y, m_floorHeight + corner.z, 1.0f)));
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

void Renderer::drawScene(const Camera& camera, QSize size, bool partIds)
{
    QOpenGLExtraFunctions& gl = *m_gl;
    gl.glViewport(0, 0, size.width(), size.height());
    const glm::vec3 background = partIds ? glm::vec3(0.0f) : kBackground;
    gl.glClearColor(background.r, background.g, background.b, partIds ? 0.0f : 1.0f);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(GL_LESS);
    gl.glDisable(GL_CULL_FACE);
    gl.glDisable(GL_BLEND);
    if (partIds) gl.glDisable(GL_DITHER);

    m_program->bind();
    const glm::mat4 viewProjection = camera.viewProjection(size);
    gl.glUniformMatrix4fv(m_uniforms.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    const glm::vec3 eye = camera.eye();
    gl.glUniform3f(m_uniforms.lightPosition, eye.x, eye.y, eye.z);

    if (m_visibility.grid && !partIds && !m_slots.empty()) {
        setModel(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, m_floorHeight)));
        setColour(glm::vec3(1.0f), true, false);
        m_grid.draw(gl);
    }

    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        const Slot& slot = m_slots[s];
        const glm::mat4 root = takeRoot(int(s), camera);
        if (m_visibility.puppet) {
            for (std::size_t p = 0; p < m_partMeshes.size() && p < slot.take_T_part.size(); ++p) {
                setModel(root * slot.take_T_part[p]);
                if (partIds)
                    setColour(glm::vec3(float(1 + int(p) + kIdsPerSlot * int(s)) / 255.0f, 0.0f, 0.0f), false, false);
                else
                    setColour(glm::vec3(1.0f), true, true);
                m_partMeshes[p].draw(gl);
            }
        }
        if (partIds) continue;
        if (m_visibility.partner) {
            const glm::vec3 partner = slot.centre + glm::vec3(m_layout.partnerDistance, 0.0f, 0.0f);
            setModel(root * glm::translate(glm::mat4(1.0f), glm::vec3(partner.x, partner.y, m_floorHeight)));
            setColour(glm::vec3(1.0f), true, true);
            m_partner.draw(gl);
        }
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
    if (result.takeSlot >= int(m_slots.size()) || result.partIndex >= int(m_partNames.size())) return std::nullopt;
    result.partName = m_partNames[std::size_t(result.partIndex)];
    return result;
}

} // namespace bunraku::render
