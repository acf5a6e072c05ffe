#include "render/gpu_mesh.h"

#include <cstddef>
#include <utility>

namespace bunraku::render {

GpuMesh::GpuMesh(GpuMesh&& other) noexcept { *this = std::move(other); }

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept
{
    std::swap(m_vertexArray, other.m_vertexArray);
    std::swap(m_vertexBuffer, other.m_vertexBuffer);
    std::swap(m_indexBuffer, other.m_indexBuffer);
    std::swap(m_indexCount, other.m_indexCount);
    std::swap(m_vertexCount, other.m_vertexCount);
    std::swap(m_mode, other.m_mode);
    return *this;
}

void GpuMesh::upload(QOpenGLExtraFunctions& gl, const Mesh& mesh)
{
    release(gl);
    m_mode = mesh.topology == MeshTopology::Triangles ? GL_TRIANGLES
             : mesh.topology == MeshTopology::Lines   ? GL_LINES
                                                      : GL_LINE_STRIP;
    m_indexCount = GLsizei(mesh.indices.size());
    m_vertexCount = int(mesh.vertices.size());
    if (m_indexCount == 0) return;
    gl.glGenVertexArrays(1, &m_vertexArray);
    gl.glGenBuffers(1, &m_vertexBuffer);
    gl.glGenBuffers(1, &m_indexBuffer);
    gl.glBindVertexArray(m_vertexArray);
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vertexBuffer);
    gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(Vertex)), mesh.vertices.data(),
                    GL_STATIC_DRAW);
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer);
    gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                    mesh.indices.data(), GL_STATIC_DRAW);
    const auto stride = GLsizei(sizeof(Vertex));
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, position)));
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, normal)));
    gl.glEnableVertexAttribArray(2);
    gl.glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, colour)));
    gl.glBindVertexArray(0);
}

void GpuMesh::updateVertices(QOpenGLExtraFunctions& gl, const std::vector<Vertex>& vertices)
{
    if (m_vertexBuffer == 0 || vertices.empty() || int(vertices.size()) > m_vertexCount) return;
    gl.glBindBuffer(GL_ARRAY_BUFFER, m_vertexBuffer);
    gl.glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data());
}

void GpuMesh::draw(QOpenGLExtraFunctions& gl) const
{
    if (m_indexCount == 0) return;
    gl.glBindVertexArray(m_vertexArray);
    gl.glDrawElements(m_mode, m_indexCount, GL_UNSIGNED_INT, nullptr);
    gl.glBindVertexArray(0);
}

void GpuMesh::release(QOpenGLExtraFunctions& gl)
{
    if (m_vertexArray != 0) gl.glDeleteVertexArrays(1, &m_vertexArray);
    if (m_vertexBuffer != 0) gl.glDeleteBuffers(1, &m_vertexBuffer);
    if (m_indexBuffer != 0) gl.glDeleteBuffers(1, &m_indexBuffer);
    m_vertexArray = m_vertexBuffer = m_indexBuffer = 0;
    m_indexCount = 0;
    m_vertexCount = 0;
}

} // namespace bunraku::render
