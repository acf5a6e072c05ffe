#include "render/puppet_geometry.h"

#include "render/scene.h"

namespace bunraku::render {

namespace {
glm::vec3 toGlm(const Eigen::Vector3d& v) { return {float(v.x()), float(v.y()), float(v.z())}; }
} // namespace

Mesh primitiveMesh(const analysis::Primitive& primitive)
{
    using analysis::PrimitiveShape;
    Mesh mesh;
    switch (primitive.shape) {
    case PrimitiveShape::Box: mesh = boxMesh(toGlm(primitive.size)); break;
    case PrimitiveShape::Cylinder: mesh = cylinderMesh(float(primitive.radius), float(primitive.length)); break;
    case PrimitiveShape::Ellipsoid: mesh = ellipsoidMesh(toGlm(primitive.size)); break;
    case PrimitiveShape::Frustum:
        mesh = frustumMesh(float(primitive.radius), float(primitive.topRadius), float(primitive.length));
        break;
    }
    paint(mesh, toGlm(primitive.colour));
    return mesh;
}

std::vector<Mesh> buildPuppetMeshes(const analysis::BodyDescription& body, const std::map<std::string, Mesh>& partMeshes)
{
    std::vector<Mesh> meshes;
    meshes.reserve(body.parts.size());
    for (const analysis::BodyPart& part : body.parts) {
        if (const auto loaded = partMeshes.find(part.name); loaded != partMeshes.end()) {
            meshes.push_back(loaded->second);
            continue;
        }
        Mesh mesh;
        for (const analysis::Primitive& primitive : part.primitives)
            mesh.append(transformed(primitiveMesh(primitive), toMatrix(primitive.part_T_primitive)));
        meshes.push_back(std::move(mesh));
    }
    return meshes;
}

} // namespace bunraku::render
