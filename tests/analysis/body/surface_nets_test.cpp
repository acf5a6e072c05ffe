// The polygoniser and the simplifier of the modelled puppet, on a sphere whose truth is known.
#include "analysis/body/mesh_decimation.h"
#include "analysis/body/surface_nets.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <map>

using namespace bunraku::analysis;

namespace {

SurfaceNetsMesh sphere(float radius, float cell, int threads = 1)
{
    SurfaceNetsGrid grid;
    grid.lower = Eigen::Vector3f::Constant(-radius - 2.0f);
    grid.upper = Eigen::Vector3f::Constant(radius + 2.0f);
    grid.cellSize = cell;
    grid.threads = threads;
    return surfaceNets([radius](const Eigen::Vector3f& p) { return p.norm() - radius; }, grid);
}

/// Borders: edges without a twin of the opposite direction.
std::size_t borderEdges(const std::vector<std::uint32_t>& indices)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) ++edges[{indices[t + std::size_t(e)], indices[t + std::size_t((e + 1) % 3)]}];
    std::size_t border = 0;
    for (const auto& [edge, count] : edges) {
        const auto twin = edges.find({edge.second, edge.first});
        if (twin == edges.end() || twin->second != count) ++border;
    }
    return border;
}

double signedVolume(const std::vector<Eigen::Vector3f>& p, const std::vector<std::uint32_t>& indices)
{
    double volume = 0.0;
    for (std::size_t t = 0; t < indices.size(); t += 3)
        volume += double(p[indices[t]].dot(p[indices[t + 1]].cross(p[indices[t + 2]]))) / 6.0;
    return volume;
}

} // namespace

TEST_CASE("surface nets polygonise a sphere: on the surface and closed and outward", "[puppet_model][surface_nets]")
{
    const float radius = 5.0f;
    const SurfaceNetsMesh mesh = sphere(radius, 0.5f);
    REQUIRE(mesh.positions.size() > 500);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        REQUIRE(std::abs(mesh.positions[v].norm() - radius) < 1e-3f);
        REQUIRE(mesh.normals[v].dot(mesh.positions[v].normalized()) > 0.999f);
    }
    CHECK(borderEdges(mesh.indices) == 0);
    int components = 0;
    meshComponents(mesh.positions.size(), mesh.indices, &components);
    CHECK(components == 1);
    // Counter-clockwise from outside: the enclosed volume is positive and close to the ball's.
    const double volume = signedVolume(mesh.positions, mesh.indices);
    CHECK(volume == Approx(4.0 / 3.0 * M_PI * std::pow(radius, 3)).epsilon(0.02));
    // The same mesh whatever the number of threads.
    const SurfaceNetsMesh threaded = sphere(radius, 0.5f, 3);
    CHECK(threaded.indices == mesh.indices);
    CHECK(threaded.positions == mesh.positions);
}

TEST_CASE("simplifying a sphere keeps it closed and within the error asked", "[puppet_model][surface_nets]")
{
    const float radius = 5.0f;
    const SurfaceNetsMesh mesh = sphere(radius, 0.5f);
    std::vector<std::uint32_t> indices = mesh.indices;
    const std::size_t before = indices.size() / 3;
    DecimationOptions options;
    options.targetTriangles = before / 4;
    options.maxError = 0.05;
    options.maxEdge = 3.0;
    std::vector<char> locked(mesh.positions.size(), 0);
    locked[0] = 1;
    const std::vector<std::uint32_t> into = decimateMesh(mesh.positions, indices, locked, options);
    CHECK(indices.size() / 3 < before);
    CHECK(borderEdges(indices) == 0);
    CHECK(into[0] == 0); // a locked vertex stays
    // Kept vertices are input vertices (on the sphere), every edge at most 3 cm, and the volume
    // close to the ball's.
    for (const std::uint32_t v : indices) REQUIRE(into[v] == v);
    for (std::size_t t = 0; t < indices.size(); t += 3)
        for (int e = 0; e < 3; ++e)
            REQUIRE((mesh.positions[indices[t + std::size_t(e)]] - mesh.positions[indices[t + std::size_t((e + 1) % 3)]]).norm() <= 3.0f + 1e-4f);
    CHECK(signedVolume(mesh.positions, indices) == Approx(4.0 / 3.0 * M_PI * std::pow(radius, 3)).epsilon(0.05));
}
