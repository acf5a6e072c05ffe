#pragma once
/// The 3D view's key light and its shadow on the floor (shadow mapping): where the light is, the
/// orthographic box it sees (GL-free, testable without a display), and the depth texture the
/// figures are drawn into from the light before the colour pass samples it.
///
/// The key light is fixed in the world (above the figures, in front and to their left, as a
/// stage's key light), so a shadow does not turn with the camera; the floor samples the depth
/// texture with percentage-closer filtering over a width that grows with the distance from the
/// caster (resources/shaders/scene.frag): contact shadows are sharp, far ones soft.

#include "render/framing.h"

#include <QOpenGLExtraFunctions>

#include <glm/glm.hpp>

namespace bunraku::render {

/// Unit vector from the figures towards the key light (world, z up; the puppet faces +x).
glm::vec3 keyLightDirection();

/// The light's clip_T_world: an orthographic box looking along -`towardsLight` that holds
/// `casters` (the figures, world cm) and, in depth, the floor at `floorZ` where their shadows
/// fall. Its centre is
/// moved to whole texels of a `mapSize`-texel map, so a box that moves (a walking take) does not
/// make the shadow's edge shimmer. An empty `casters` gives the identity.
glm::mat4 shadowViewProjection(const Bounds& casters, float floorZ, const glm::vec3& towardsLight, int mapSize);

/// A depth texture with its framebuffer (GL_DEPTH_COMPONENT24, compare mode on for a
/// sampler2DShadow; the shader treats the floor outside the light's box as lit). Needs the
/// context it was made in to be current.
class ShadowMap {
public:
    ShadowMap() = default;
    ShadowMap(const ShadowMap&) = delete;
    ShadowMap& operator=(const ShadowMap&) = delete;

    /// Makes the texture (once, or again for another size); false when the framebuffer is not
    /// complete on this driver (the view then draws without shadows).
    bool ensure(QOpenGLExtraFunctions& gl, int size);
    /// Binds the framebuffer, sets the viewport to the map and clears its depth.
    void beginWriting(QOpenGLExtraFunctions& gl) const;
    /// Binds the map to texture unit `compared` (compare mode: a sampler2DShadow) and to unit
    /// `depths` with a sampler object that reads plain depths (a sampler2D); unit 0 is left active.
    void bindForReading(QOpenGLExtraFunctions& gl, int compared, int depths) const;
    /// Unbinds those units (before the map is written again).
    void unbindFromReading(QOpenGLExtraFunctions& gl, int compared, int depths) const;
    GLuint texture() const { return m_texture; }
    int size() const { return m_size; }
    void release(QOpenGLExtraFunctions& gl);

private:
    GLuint m_framebuffer = 0;
    GLuint m_texture = 0;
    GLuint m_depthSampler = 0; ///< compare mode off, nearest: the blocker search reads depths
    int m_size = 0;
};

} // namespace bunraku::render
