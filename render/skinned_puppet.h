#pragma once
/// The modelled puppet (analysis/body/puppet_model.h) on the GPU, skinned there: the mesh is
/// uploaded once per body (the shipped puppet, or one fitted to a performer) and each frame
/// sends only the joints' dual quaternions (resources/shaders/skinned.vert blends them per
/// vertex, as analysis::skinPuppet does on the CPU). Every call needs the owning context current.

#include "analysis/body/puppet_model.h"
#include "analysis/cloth/kimono_cloth.h"

#include <QOpenGLExtraFunctions>

#include <glm/glm.hpp>

#include <array>

namespace bunraku::render {

/// The joints' skinning transforms world_T_joint * inverse(bind) as dual quaternions
/// (real, dual; each x y z w), what the shader's u_jointReal / u_jointDual take.
struct JointDualQuaternions {
    std::array<glm::vec4, analysis::kPuppetJointCount> real{};
    std::array<glm::vec4, analysis::kPuppetJointCount> dual{};
};
JointDualQuaternions jointDualQuaternions(const analysis::PuppetMesh& mesh,
                                          const std::array<analysis::RigidTransform, analysis::kPuppetJointCount>& world_T_joint);

class SkinnedPuppetGpu {
public:
    SkinnedPuppetGpu() = default;
    SkinnedPuppetGpu(const SkinnedPuppetGpu&) = delete;
    SkinnedPuppetGpu& operator=(const SkinnedPuppetGpu&) = delete;
    SkinnedPuppetGpu(SkinnedPuppetGpu&& other) noexcept;
    SkinnedPuppetGpu& operator=(SkinnedPuppetGpu&& other) noexcept;
    ~SkinnedPuppetGpu() = default; ///< GL names are freed by release(), which needs the context

    /// Attribute locations: 0 position, 1 normal, 2 colour, 3 (sheen, region), 4 paint position,
    /// 5 joints (integers), 6 weights. With `clothSplit` the triangles are ordered so that
    /// drawUnderCloth draws the puppet without the pieces the simulated kimono replaces
    /// (analysis::puppetIndicesUnderCloth).
    void upload(QOpenGLExtraFunctions& gl, const analysis::PuppetMesh& mesh, bool clothSplit = false);
    void draw(QOpenGLExtraFunctions& gl) const;
    /// The puppet without its skinned skirt and sleeves (all of it unless uploaded with clothSplit).
    void drawUnderCloth(QOpenGLExtraFunctions& gl) const;
    void release(QOpenGLExtraFunctions& gl);
    bool empty() const { return m_indexCount == 0; }

private:
    GLuint m_vertexArray = 0;
    GLuint m_vertexBuffer = 0;
    GLuint m_indexBuffer = 0;
    GLsizei m_indexCount = 0;
    GLsizei m_underClothCount = 0; ///< the first triangles' indices: the puppet under the cloth
};

/// The simulated kimono (analysis/cloth) on the GPU: drawn by the skinned puppet's program with
/// every joint at the identity, its particles' positions and normals (take coordinates, cm)
/// replaced each frame; colours, paint and the part each particle belongs to (its hanging joint:
/// the skirt the kimono's, a sleeve its own, for the ID pass) uploaded once.
class ClothGpu {
public:
    ClothGpu() = default;
    ClothGpu(const ClothGpu&) = delete;
    ClothGpu& operator=(const ClothGpu&) = delete;
    ClothGpu(ClothGpu&& other) noexcept;
    ClothGpu& operator=(ClothGpu&& other) noexcept;
    ~ClothGpu() = default; ///< GL names are freed by release(), which needs the context

    /// The cloth's triangles and looks (analysis::kimonoLook of the puppet it dresses).
    void upload(QOpenGLExtraFunctions& gl, const analysis::KimonoCloth& cloth, const analysis::PuppetMesh& puppet);
    /// Positions and normals, one per particle (interleaved x y z nx ny nz).
    void update(QOpenGLExtraFunctions& gl, const std::vector<float>& positionsAndNormals);
    void draw(QOpenGLExtraFunctions& gl) const;
    void release(QOpenGLExtraFunctions& gl);
    bool empty() const { return m_indexCount == 0; }

private:
    GLuint m_vertexArray = 0;
    GLuint m_staticBuffer = 0;
    GLuint m_movingBuffer = 0;
    GLuint m_indexBuffer = 0;
    GLsizei m_indexCount = 0;
    GLsizei m_vertexCount = 0;
};

} // namespace bunraku::render
