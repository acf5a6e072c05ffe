#include "render/shadow_map.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace bunraku::render {

glm::vec3 keyLightDirection() { return glm::normalize(glm::vec3(0.45f, 0.55f, 1.0f)); }

glm::mat4 shadowViewProjection(const Bounds& casters, float floorZ, const glm::vec3& towardsLight, int mapSize)
{
    if (casters.empty() || mapSize <= 0) return glm::mat4(1.0f);
    Bounds box = casters;
    box.add(glm::vec3(casters.lower.x, casters.lower.y, std::min(floorZ, casters.lower.z)));
    const glm::vec3 light = glm::normalize(towardsLight);
    const glm::vec3 up = std::abs(light.z) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    // The light's rotation only: the box is placed in its frame, then snapped to whole texels.
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), -light, up);
    // The radius in steps of 10 cm, so a figure that changes its pose does not rescale the map
    // every frame.
    const float radius = std::ceil((0.5f * glm::length(box.size()) + 2.0f) / 10.0f) * 10.0f;
    glm::vec3 centre = glm::vec3(view * glm::vec4(box.centre(), 1.0f));
    const float texel = 2.0f * radius / float(mapSize);
    centre.x = std::round(centre.x / texel) * texel;
    centre.y = std::round(centre.y / texel) * texel;
    // Depth: from the nearest caster to where the light's ray past the lowest caster meets the
    // floor (a shadow shares its caster's place across the light, never its depth: the shadow
    // of a raised hand lies far down the ray).
    const float toFloor = (box.upper.z - box.lower.z) / std::max(light.z, 0.1f);
    const glm::mat4 projection = glm::ortho(centre.x - radius, centre.x + radius, centre.y - radius, centre.y + radius,
                                            -centre.z - radius - 1.0f, -centre.z + radius + toFloor + 1.0f);
    return projection * view;
}

bool ShadowMap::ensure(QOpenGLExtraFunctions& gl, int size)
{
    if (m_texture != 0 && m_size == size) return true;
    release(gl);
    GLint previous = 0;
    gl.glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    gl.glGenTextures(1, &m_texture);
    gl.glBindTexture(GL_TEXTURE_2D, m_texture);
    gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Outside the light's box: depth 1, nothing in front, lit. (OpenGL ES 3.0 has no border
    // clamp; the shader also treats coordinates outside [0, 1] as lit.)
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    gl.glGenSamplers(1, &m_depthSampler);
    gl.glSamplerParameteri(m_depthSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.glSamplerParameteri(m_depthSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.glSamplerParameteri(m_depthSampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.glSamplerParameteri(m_depthSampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.glSamplerParameteri(m_depthSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    gl.glGenFramebuffers(1, &m_framebuffer);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_texture, 0);
    const GLenum none = GL_NONE;
    gl.glDrawBuffers(1, &none);
    gl.glReadBuffer(GL_NONE);
    const bool complete = gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    gl.glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
    m_size = size;
    if (!complete) release(gl);
    return complete;
}

void ShadowMap::beginWriting(QOpenGLExtraFunctions& gl) const
{
    gl.glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    gl.glViewport(0, 0, m_size, m_size);
    gl.glClear(GL_DEPTH_BUFFER_BIT);
}

void ShadowMap::bindForReading(QOpenGLExtraFunctions& gl, int compared, int depths) const
{
    gl.glActiveTexture(GLenum(GL_TEXTURE0 + compared));
    gl.glBindTexture(GL_TEXTURE_2D, m_texture);
    gl.glActiveTexture(GLenum(GL_TEXTURE0 + depths));
    gl.glBindTexture(GL_TEXTURE_2D, m_texture);
    gl.glBindSampler(GLuint(depths), m_depthSampler);
    gl.glActiveTexture(GL_TEXTURE0);
}

void ShadowMap::unbindFromReading(QOpenGLExtraFunctions& gl, int compared, int depths) const
{
    for (const int unit : {compared, depths}) {
        gl.glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        gl.glBindTexture(GL_TEXTURE_2D, 0);
    }
    gl.glBindSampler(GLuint(depths), 0);
    gl.glActiveTexture(GL_TEXTURE0);
}

void ShadowMap::release(QOpenGLExtraFunctions& gl)
{
    if (m_depthSampler != 0) gl.glDeleteSamplers(1, &m_depthSampler);
    m_depthSampler = 0;
    if (m_framebuffer != 0) gl.glDeleteFramebuffers(1, &m_framebuffer);
    if (m_texture != 0) gl.glDeleteTextures(1, &m_texture);
    m_framebuffer = 0;
    m_texture = 0;
    m_size = 0;
}

} // namespace bunraku::render
