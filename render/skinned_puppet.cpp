#include "render/skinned_puppet.h"

#include "analysis/body/dual_quaternion.h"
#include "analysis/cloth/kimono_mesh.h"

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
    std::swap(m_underClothCount, other.m_underClothCount);
    return *this;
}

void SkinnedPuppetGpu::upload(QOpenGLExtraFunctions& gl, const analysis::PuppetMesh& mesh, bool clothSplit)
{
    release(gl);
    m_indexCount = GLsizei(mesh.indices.size());
    m_underClothCount = m_indexCount;
    if (m_indexCount == 0) return;
    // The triangles the cloth keeps first, then the skinned skirt and sleeves.
    std::vector<std::uint32_t> indices;
    if (clothSplit) {
        indices = analysis::puppetIndicesUnderCloth(mesh);
        m_underClothCount = GLsizei(indices.size());
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            if (analysis::replacedByCloth(mesh, a) && analysis::replacedByCloth(mesh, b) && analysis::replacedByCloth(mesh, c))
                indices.insert(indices.end(), {a, b, c});
        }
    }
    const std::vector<std::uint32_t>& uploaded = clothSplit ? indices : mesh.indices;
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
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(uploaded.size() * sizeof(std::uint32_t)), uploaded.data(), GL_STATIC_DRAW);
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

void SkinnedPuppetGpu::drawUnderCloth(QOpenGLExtraFunctions& gl) const
{
    if (m_underClothCount == 0) return;
    gl.glBindVertexArray(m_vertexArray);
    gl.glDrawElements(GL_TRIANGLES, m_underClothCount, GL_UNSIGNED_INT, nullptr);
    gl.glBindVertexArray(0);
}

void SkinnedPuppetGpu::release(QOpenGLExtraFunctions& gl)
{
    if (m_vertexArray != 0) gl.glDeleteVertexArrays(1, &m_vertexArray);
    if (m_vertexBuffer != 0) gl.glDeleteBuffers(1, &m_vertexBuffer);
    if (m_indexBuffer != 0) gl.glDeleteBuffers(1, &m_indexBuffer);
    m_vertexArray = m_vertexBuffer = m_indexBuffer = 0;
    m_indexCount = m_underClothCount = 0;
}

namespace {
struct ClothStaticVertex {
    float colour[3];
    float sheenRegion[2];
    float paint[3];
    std::uint8_t joints[4];
    float weights[4];
};
} // namespace

ClothGpu::ClothGpu(ClothGpu&& other) noexcept { *this = std::move(other); }

ClothGpu& ClothGpu::operator=(ClothGpu&& other) noexcept
{
    std::swap(m_vertexArray, other.m_vertexArray);
    std::swap(m_staticBuffer, other.m_staticBuffer);
    std::swap(m_movingBuffer, other.m_movingBuffer);
    std::swap(m_indexBuffer, other.m_indexBuffer);
    std::swap(m_indexCount, other.m_indexCount);
    std::swap(m_vertexCount, other.m_vertexCount);
    return *this;
}

void ClothGpu::upload(QOpenGLExtraFunctions& gl, const analysis::KimonoCloth& cloth, const analysis::PuppetMesh& puppet)
{
    release(gl);
    if (cloth.triangles.empty()) return;
    const analysis::KimonoLook look = analysis::kimonoLook(cloth, puppet);
    std::vector<ClothStaticVertex> vertices(cloth.size());
    for (std::size_t i = 0; i < cloth.size(); ++i) {
        ClothStaticVertex& out = vertices[i];
        for (int k = 0; k < 3; ++k) {
            out.colour[k] = look.colours[i][k];
            out.paint[k] = look.paintPositions[i][k];
        }
        out.sheenRegion[0] = look.sheen[i];
        out.sheenRegion[1] = float(look.regions[i]);
        const analysis::PuppetJoint joint = cloth.holder[i] == analysis::KimonoCloth::Shoulder   ? analysis::PuppetJoint::Kimono
                                            : cloth.holder[i] == analysis::KimonoCloth::RightArm ? analysis::PuppetJoint::RightSleeve
                                                                                                 : analysis::PuppetJoint::LeftSleeve;
        out.joints[0] = std::uint8_t(joint);
        out.joints[1] = out.joints[2] = out.joints[3] = 0;
        out.weights[0] = 1.0f;
        out.weights[1] = out.weights[2] = out.weights[3] = 0.0f;
    }
    m_vertexCount = GLsizei(cloth.size());
    m_indexCount = GLsizei(cloth.triangles.size());
    gl.glGenVertexArrays(1, &m_vertexArray);
    gl.glGenBuffers(1, &m_staticBuffer);
    gl.glGenBuffers(1, &m_movingBuffer);
    gl.glGenBuffers(1, &m_indexBuffer);
    gl.glBindVertexArray(m_vertexArray);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_movingBuffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cloth.size() * 6 * sizeof(float)), nullptr, GL_DYNAMIC_DRAW);
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, GLsizei(6 * sizeof(float)), nullptr);
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, GLsizei(6 * sizeof(float)), reinterpret_cast<const void*>(3 * sizeof(float)));
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_staticBuffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(ClothStaticVertex)), vertices.data(), GL_STATIC_DRAW);
    const auto stride = GLsizei(sizeof(ClothStaticVertex));
    const auto attribute = [&](GLuint location, GLint size, std::size_t offset) {
        gl.glEnableVertexAttribArray(location);
        gl.glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    };
    attribute(2, 3, offsetof(ClothStaticVertex, colour));
    attribute(3, 2, offsetof(ClothStaticVertex, sheenRegion));
    attribute(4, 3, offsetof(ClothStaticVertex, paint));
    gl.glEnableVertexAttribArray(5);
    gl.glVertexAttribIPointer(5, 4, GL_UNSIGNED_BYTE, stride, reinterpret_cast<const void*>(offsetof(ClothStaticVertex, joints)));
    attribute(6, 4, offsetof(ClothStaticVertex, weights));
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer);
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(cloth.triangles.size() * sizeof(std::uint32_t)), cloth.triangles.data(),
                    GL_STATIC_DRAW);
    gl.glBindVertexArray(0);
}

void ClothGpu::update(QOpenGLExtraFunctions& gl, const std::vector<float>& positionsAndNormals)
{
    if (m_vertexCount == 0 || positionsAndNormals.size() != std::size_t(m_vertexCount) * 6) return;
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_movingBuffer);
    gl.glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(positionsAndNormals.size() * sizeof(float)), positionsAndNormals.data());
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ClothGpu::draw(QOpenGLExtraFunctions& gl) const
{
    if (m_indexCount == 0) return;
    gl.glBindVertexArray(m_vertexArray);
    gl.glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    gl.glBindVertexArray(0);
}

void ClothGpu::release(QOpenGLExtraFunctions& gl)
{
    if (m_vertexArray != 0) gl.glDeleteVertexArrays(1, &m_vertexArray);
    for (GLuint* buffer : {&m_staticBuffer, &m_movingBuffer, &m_indexBuffer})
        if (*buffer != 0) gl.glDeleteBuffers(1, buffer);
    m_vertexArray = m_staticBuffer = m_movingBuffer = m_indexBuffer = 0;
    m_indexCount = m_vertexCount = 0;
}

} // namespace bunraku::render
