#include "render/skinned_puppet.h"

#include "analysis/body/dual_quaternion.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace bunraku::render {

namespace {
struct SkinnedVertex {
    float position[3];
    float normal[3];
    float colour[3];
    float sheenRegion[2];
    float paint[3];
    std::uint8_t joints[4];
    float weights[4];
};
} // namespace

JointDualQuaternions jointDualQuaternions(const analysis::PuppetMesh& mesh,
                                          const std::array<analysis::RigidTransform, analysis::kPuppetJointCount>& world_T_joint)
{
    JointDualQuaternions out;
    for (int j = 0; j < analysis::kPuppetJointCount; ++j) {
        const auto q = analysis::DualQuaternion::fromRigid(world_T_joint[std::size_t(j)] * mesh.bindPoses[std::size_t(j)].inverse());
        out.real[std::size_t(j)] = glm::vec4(float(q.real.x()), float(q.real.y()), float(q.real.z()), float(q.real.w()));
        out.dual[std::size_t(j)] = glm::vec4(float(q.dual.x()), float(q.dual.y()), float(q.dual.z()), float(q.dual.w()));
    }
    return out;
}

SkinnedPuppetGpu::SkinnedPuppetGpu(SkinnedPuppetGpu&& other) noexcept { *this = std::move(other); }

SkinnedPuppetGpu& SkinnedPuppetGpu::operator=(SkinnedPuppetGpu&& other) noexcept
{
    std::swap(m_vertexArray, other.m_vertexArray);
    std::swap(m_vertexBuffer, other.m_vertexBuffer);
    std::swap(m_indexBuffer, other.m_indexBuffer);
    std::swap(m_indexCount, other.m_indexCount);
    return *this;
}

void SkinnedPuppetGpu::upload(QOpenGLExtraFunctions& gl, const analysis::PuppetMesh& mesh)
{
    release(gl);
    m_indexCount = GLsizei(mesh.indices.size());
    if (m_indexCount == 0) return;
    std::vector<SkinnedVertex> vertices(mesh.vertexCount());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        SkinnedVertex& out = vertices[v];
        for (int k = 0; k < 3; ++k) {
            out.position[k] = mesh.positions[v][k];
            out.normal[k] = mesh.normals[v][k];
            out.colour[k] = mesh.colours[v][k];
            out.paint[k] = mesh.paintPositions[v][k];
        }
        out.sheenRegion[0] = mesh.sheen[v];
        out.sheenRegion[1] = float(mesh.regions[v]);
        for (int k = 0; k < 4; ++k) {
            out.joints[k] = mesh.joints[v][std::size_t(k)];
            out.weights[k] = mesh.weights[v][k];
        }
    }
    gl.glGenVertexArrays(1, &m_vertexArray);
    gl.glGenBuffers(1, &m_vertexBuffer);
    gl.glGenBuffers(1, &m_indexBuffer);
    gl.glBindVertexArray(m_vertexArray);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vertexBuffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(SkinnedVertex)), vertices.data(), GL_STATIC_DRAW);
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer);
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
                    GL_STATIC_DRAW);
    const auto stride = GLsizei(sizeof(SkinnedVertex));
    const auto attribute = [&](GLuint location, GLint size, std::size_t offset) {
        gl.glEnableVertexAttribArray(location);
        gl.glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    };
    attribute(0, 3, offsetof(SkinnedVertex, position));
    attribute(1, 3, offsetof(SkinnedVertex, normal));
    attribute(2, 3, offsetof(SkinnedVertex, colour));
    attribute(3, 2, offsetof(SkinnedVertex, sheenRegion));
    attribute(4, 3, offsetof(SkinnedVertex, paint));
    gl.glEnableVertexAttribArray(5);
    gl.glVertexAttribIPointer(5, 4, GL_UNSIGNED_BYTE, stride, reinterpret_cast<const void*>(offsetof(SkinnedVertex, joints)));
    attribute(6, 4, offsetof(SkinnedVertex, weights));
    gl.glBindVertexArray(0);
}

void SkinnedPuppetGpu::draw(QOpenGLExtraFunctions& gl) const
{
    if (m_indexCount == 0) return;
    gl.glBindVertexArray(m_vertexArray);
    gl.glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    gl.glBindVertexArray(0);
}

void SkinnedPuppetGpu::release(QOpenGLExtraFunctions& gl)
{
    if (m_vertexArray != 0) gl.glDeleteVertexArrays(1, &m_vertexArray);
    if (m_vertexBuffer != 0) gl.glDeleteBuffers(1, &m_vertexBuffer);
    if (m_indexBuffer != 0) gl.glDeleteBuffers(1, &m_indexBuffer);
    m_vertexArray = m_vertexBuffer = m_indexBuffer = 0;
    m_indexCount = 0;
}

} // namespace bunraku::render
