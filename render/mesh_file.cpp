#include "render/mesh_file.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/gtc/matrix_transform.hpp>

namespace bunraku::render {

namespace {

glm::mat4 toGlm(const aiMatrix4x4& m)
{
    // assimp is row-major, glm column-major.
    glm::mat4 result(1.0f);
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) result[column][row] = m[row][column];
    return result;
}

void appendNode(const aiScene& scene, const aiNode& node, const glm::mat4& parent_T_node, const glm::vec3& colour,
                Mesh& out)
{
    const glm::mat4 file_T_node = parent_T_node * toGlm(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& source = *scene.mMeshes[node.mMeshes[i]];
        Mesh mesh;
        for (unsigned v = 0; v < source.mNumVertices; ++v) {
            Vertex vertex;
            vertex.position = {source.mVertices[v].x, source.mVertices[v].y, source.mVertices[v].z};
            if (source.HasNormals()) vertex.normal = {source.mNormals[v].x, source.mNormals[v].y, source.mNormals[v].z};
            vertex.colour = colour;
            if (source.HasVertexColors(0))
                vertex.colour = {source.mColors[0][v].r, source.mColors[0][v].g, source.mColors[0][v].b};
            mesh.vertices.push_back(vertex);
        }
        for (unsigned f = 0; f < source.mNumFaces; ++f) {
            const aiFace& face = source.mFaces[f];
            if (face.mNumIndices != 3) continue; // points and lines are not part of a solid
            mesh.indices.insert(mesh.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
        }
        out.append(transformed(mesh, file_T_node));
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(scene, *node.mChildren[c], file_T_node, colour, out);
}

} // namespace

analysis::Result<Mesh> loadMeshFile(const std::filesystem::path& file, const MeshFileOptions& options)
{
    using analysis::ErrorCode;
    if (!std::filesystem::exists(file))
        return analysis::makeError(ErrorCode::Io, file.string() + ": no such mesh file");
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                                aiProcess_JoinIdenticalVertices |
                                                                aiProcess_SortByPType);
    if (scene == nullptr || scene->mRootNode == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0)
        return analysis::makeError(ErrorCode::Parse, file.string() + ": " + importer.GetErrorString());
    Mesh mesh;
    appendNode(*scene, *scene->mRootNode, glm::mat4(1.0f), options.colour, mesh);
    if (mesh.empty()) return analysis::makeError(ErrorCode::Parse, file.string() + ": the file holds no triangles");
    const glm::mat4 part_T_file = options.part_T_file * glm::scale(glm::mat4(1.0f), glm::vec3(options.scale));
    return transformed(mesh, part_T_file);
}

} // namespace bunraku::render
