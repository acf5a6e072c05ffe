// Tessellated primitives span their analytic extents, and mesh files load through assimp.
#include "analysis/body/body_description.h"
#include "render/mesh.h"
#include "render/mesh_file.h"
#include "render/puppet_geometry.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace bunraku;

namespace {
std::pair<glm::vec3, glm::vec3> bounds(const render::Mesh& mesh)
{
    glm::vec3 low(1e9f), high(-1e9f);
    for (const auto& v : mesh.vertices) {
        low = glm::min(low, v.position);
        high = glm::max(high, v.position);
    }
    return {low, high};
}
} // namespace

TEST_CASE("each primitive's mesh spans its analytic half extents", "[mesh]")
{
    const auto& body = analysis::defaultBodyDescription();
    int checked = 0;
    for (const auto& part : body.parts) {
        for (const auto& primitive : part.primitives) {
            const auto [low, high] = bounds(render::primitiveMesh(primitive));
            const Eigen::Vector3d half = primitive.halfExtents();
            for (int axis = 0; axis < 3; ++axis) {
                // Polygons inscribe curved surfaces: at most 1 - cos(pi/24) short of the radius.
                CHECK(high[axis] == Approx(half[axis]).epsilon(0.01));
                CHECK(low[axis] == Approx(-half[axis]).epsilon(0.01));
            }
            ++checked;
        }
    }
    CHECK(checked > 5);
}

TEST_CASE("puppet meshes put every vertex inside its part's primitives", "[mesh]")
{
    const auto& body = analysis::defaultBodyDescription();
    const auto meshes = render::buildPuppetMeshes(body);
    REQUIRE(meshes.size() == body.parts.size());
    for (std::size_t p = 0; p < meshes.size(); ++p) {
        REQUIRE_FALSE(meshes[p].empty());
        int outside = 0;
        for (const auto& vertex : meshes[p].vertices) {
            const Eigen::Vector3d q(vertex.position.x, vertex.position.y, vertex.position.z);
            bool inside = false;
            for (const auto& primitive : body.parts[p].primitives) {
                const Eigen::Vector3d local = primitive.part_T_primitive.inverse().apply(q);
                // Grow by a hair: surface vertices sit exactly on the boundary.
                const Eigen::Vector3d shrunk = local * (1.0 - 1e-4);
                inside = inside || primitive.containsLocal(shrunk);
            }
            if (!inside) ++outside;
        }
        INFO(body.parts[p].name);
        CHECK(outside == 0);
    }
}

TEST_CASE("an OBJ file loads with its triangles scaled into the part frame", "[mesh]")
{
    const auto dir = test::scratchDir("render_mesh_file");
    const auto file = dir / "wedge.obj";
    std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    render::MeshFileOptions options;
    options.scale = 10.0f;
    const auto mesh = render::loadMeshFile(file, options);
    REQUIRE(mesh.ok());
    CHECK(mesh->indices.size() == 12);
    const auto [low, high] = bounds(*mesh);
    CHECK(high.x == Approx(10.0f));
    CHECK(high.z == Approx(10.0f));
    CHECK(low.y == Approx(0.0f));

    const auto missing = render::loadMeshFile(dir / "absent.obj");
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error().message.find("absent.obj") != std::string::npos);
}
