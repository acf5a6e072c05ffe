#pragma once
/// A mesh on the GPU: a vertex array with its vertex and index buffers. Buffers are allocated by
/// upload() (scene changes only); per-frame changes go through updateVertices (glBufferSubData).
/// Every call needs the owning OpenGL context current.

#include "render/mesh.h"

#include <QOpenGLExtraFunctions>

namespace bunraku::render {

class GpuMesh {
public:
    GpuMesh() = default;
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;
    ~GpuMesh() = default; ///< GL names are freed by release(), which needs the context

    /// Allocates the buffers and copies `mesh` (attribute locations 0 position, 1 normal, 2 colour).
    void upload(QOpenGLExtraFunctions& gl, const Mesh& mesh);
    /// Overwrites the first vertices in place; `vertices` must not outgrow the upload.
    void updateVertices(QOpenGLExtraFunctions& gl, const std::vector<Vertex>& vertices);
    void draw(QOpenGLExtraFunctions& gl) const;
    void release(QOpenGLExtraFunctions& gl);

    bool empty() const { return m_indexCount == 0; }
    int vertexCount() const { return m_vertexCount; }

private:
    GLuint m_vertexArray = 0;
    GLuint m_vertexBuffer = 0;
    GLuint m_indexBuffer = 0;
    GLsizei m_indexCount = 0;
    int m_vertexCount = 0;
    GLenum m_mode = GL_TRIANGLES;
};

} // namespace bunraku::render
