#include "render/renderer_internal.h"

#include "analysis/body/dual_quaternion.h"

#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

// The renderer's passes: the key light's depth map, the colour frame, the part-ID frame for
// picking.
namespace bunraku::render {

bool Renderer::drawBody(const Slot& slot, int takeSlot, const glm::mat4& root, const glm::mat4& viewProjection, const glm::vec3& eye,
                        bool partIds, bool fileMesh)
{
    SkeletonFigure& figure = *slot.skeleton;
    if (!fileMesh && !figure.bodyTried) {
        figure.bodyTried = true;
        auto made = analysis::performerBody(*slot.take.skeleton);
        if (made.ok()) {
            figure.body = std::make_shared<const analysis::PerformerBody>(std::move(made).value());
            figure.bodyGpu.upload(*m_gl, figure.body->mesh);
        }
    }
    if (fileMesh && !figure.fileMeshTried) {
        figure.fileMeshTried = true;
        const analysis::Skeleton& skeleton = *slot.take.skeleton->skeleton;
        if (skeleton.mesh) {
            auto made = analysis::skeletonMeshBody(*skeleton.mesh, skeleton);
            if (made.ok()) {
                figure.fileMesh = std::make_shared<const analysis::PerformerBody>(std::move(made).value());
                figure.fileMeshGpu.upload(*m_gl, figure.fileMesh->mesh);
            }
        }
    }
    const analysis::PerformerBody* body = fileMesh ? figure.fileMesh.get() : figure.body.get();
    if (!body) return false;
    QOpenGLExtraFunctions& gl = *m_gl;
    m_bodyProgram->bind();
    const auto at = [this](BodyUniform uniform) { return m_bodyUniforms[std::size_t(uniform)]; };
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(root)));
    gl.glUniformMatrix4fv(at(BodyModel), 1, GL_FALSE, glm::value_ptr(root));
    gl.glUniformMatrix3fv(at(BodyNormalMatrix), 1, GL_FALSE, glm::value_ptr(normalMatrix));
    gl.glUniformMatrix4fv(at(BodyViewProjection), 1, GL_FALSE, glm::value_ptr(viewProjection));
    gl.glUniform3f(at(BodyLightPosition), eye.x, eye.y, eye.z);
    const glm::vec3 key = keyLightDirection();
    gl.glUniform3f(at(BodyKeyDirection), key.x, key.y, key.z);
    gl.glUniform4f(at(BodyColour), 1.0f, 1.0f, 1.0f, 1.0f);
    gl.glUniform1i(at(BodyUseVertexColour), 1);
    gl.glUniform1i(at(BodyLit), 1);
    gl.glUniform1i(at(BodyPartIdBase), partIds ? kSkeletonId + 1 + kIdsPerSlot * takeSlot : -1);
    gl.glUniform1i(at(BodyBoneIds), 1);
    gl.glUniform1i(at(BodyLinearBlend), fileMesh ? 1 : 0);
    const auto skinning = analysis::bodySkinningTransforms(*body, slot.take.skeleton->worldPoses(slot.frame));
    std::vector<glm::vec4> real(skinning.size()), dual(skinning.size());
    for (std::size_t j = 0; j < skinning.size(); ++j) {
        const analysis::DualQuaternion q = analysis::DualQuaternion::fromRigid(skinning[j]);
        real[j] = glm::vec4(float(q.real.x()), float(q.real.y()), float(q.real.z()), float(q.real.w()));
        dual[j] = glm::vec4(float(q.dual.x()), float(q.dual.y()), float(q.dual.z()), float(q.dual.w()));
    }
    gl.glUniform4fv(at(BodyJointReal), GLsizei(real.size()), glm::value_ptr(real[0]));
    gl.glUniform4fv(at(BodyJointDual), GLsizei(dual.size()), glm::value_ptr(dual[0]));
    (fileMesh ? figure.fileMeshGpu : figure.bodyGpu).draw(gl);
    m_program->bind();
    return true;
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
    key.push_back(m_draft ? 1.0f : 0.0f);
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        const glm::mat4 root = takeRoot(int(s), camera);
        key.insert(key.end(), glm::value_ptr(root), glm::value_ptr(root) + 16);
        key.push_back(float(m_slots[s].frame));
        key.push_back(float(int(puppetDrawn(int(s))) + 2 * int(skeletonDrawn(int(s))) + 4 * int(partnerShown(int(s), camera))));
        key.push_back(float(int(m_visibility.figures[s]))); // the skeleton's capsules, body or mesh
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
        const FigureStyle style = m_visibility.figures[s];
        if (skeletonDrawn(int(s)) && (style == FigureStyle::Body || style == FigureStyle::FileMesh) &&
            drawBody(slot, int(s), root, viewProjection, eye, ids, style == FigureStyle::FileMesh)) {
            // the performer's body, or the file's own mesh, skinned to the skeleton
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
        if (pass != Pass::PartIds && !(pass == Pass::Shadow && m_draft) && partnerShown(int(s), camera)) {
            const glm::mat4 world_T_partner = partnerTransform(slot, root);
            setModel(world_T_partner);
            setColour(glm::vec3(1.0f), true, pass == Pass::Colour);
            if (slot.partner) slot.partner->gpu.draw(gl);
            else m_partner.draw(gl);
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
            gl.glUniform1i(m_uniforms.shadowDraft, m_draft ? 1 : 0);
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
            // The kimono's measured points, while the puppet wears its simulated cloth.
            const bool kimonoOrbits = clothDrawn(int(s)) || (!m_visibility.puppet && slot.kimono);
            if (kimonoOrbits)
                for (const GpuMesh& orbit : slot.kimonoOrbits) orbit.draw(gl);
            const float pointRadius = std::max(m_layout.orbitPointRadius, 2.5f * slot.orbitRadius);
            for (std::size_t k = 0; k < slot.sensorFirstChannel.size(); ++k) {
                const glm::vec3 position = sensorPosition(slot.take, slot.frame, slot.sensorFirstChannel[k]);
                setModel(root * glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(pointRadius)));
                setColour(orbitColour(int(s), int(k)), false, true);
                m_sphere.draw(gl);
            }
            if (kimonoOrbits && slot.frame < slot.kimono->frameCount())
                for (int point = 0; point < analysis::kKimonoPointCount; ++point) {
                    const glm::vec3 position(float(slot.kimono->points(slot.frame, 3 * point)), float(slot.kimono->points(slot.frame, 3 * point + 1)),
                                             float(slot.kimono->points(slot.frame, 3 * point + 2)));
                    setModel(root * glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(pointRadius)));
                    setColour(kimonoOrbitColour(int(s), point), false, true);
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
    if (!clothDrawn(takeSlot)) {
        figure.gpu.draw(gl);
        m_program->bind();
        return;
    }
    // Dressed in the simulated kimono: the puppet without its skinned skirt and sleeves, then
    // the cloth, whose positions are in take coordinates already (every joint at the identity;
    // each particle keeps its hanging joint for the ID pass).
    figure.gpu.drawUnderCloth(gl);
    if (!slot.clothUploaded) {
        slot.cloth->update(gl, slot.clothVertices);
        slot.clothUploaded = true;
    }
    std::array<glm::vec4, analysis::kPuppetJointCount> identityReal, identityDual;
    identityReal.fill(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    identityDual.fill(glm::vec4(0.0f));
    gl.glUniform4fv(m_skinUniforms.jointReal, analysis::kPuppetJointCount, glm::value_ptr(identityReal[0]));
    gl.glUniform4fv(m_skinUniforms.jointDual, analysis::kPuppetJointCount, glm::value_ptr(identityDual[0]));
    slot.cloth->draw(gl);
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
