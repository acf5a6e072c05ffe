#pragma once
/// The modelled puppet (analysis/body/puppet_model.h) on the GPU, skinned there: the mesh is
/// uploaded once per body (the shipped puppet, or one fitted to a performer) and each frame
/// sends only the joints' dual quaternions (resources/shaders/skinned.vert blends them per
/// vertex, as analysis::skinPuppet does on the CPU). Every call needs the owning context current.

#include "analysis/body/puppet_model.h"

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
    /// 5 joints (integers), 6 weights.
    void upload(QOpenGLExtraFunctions& gl, const analysis::PuppetMesh& mesh);
    void draw(QOpenGLExtraFunctions& gl) const;
    void release(QOpenGLExtraFunctions& gl);
    bool empty() const { return m_indexCount == 0; }

private:
    GLuint m_vertexArray = 0;
    GLuint m_vertexBuffer = 0;
    GLuint m_indexBuffer = 0;
    GLsizei m_indexCount = 0;
};

} // namespace bunraku::render
