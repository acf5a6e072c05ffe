#include "render/orbit_geometry.h"

#include <algorithm>
#include <cmath>

namespace bunraku::render {

namespace {

/// A unit vector perpendicular to `direction` (unit).
glm::vec3 anyPerpendicular(const glm::vec3& direction)
{
    const glm::vec3 axis = std::abs(direction.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    return glm::normalize(glm::cross(direction, axis));
}

} // namespace

float orbitTubeRadius(float extent) { return std::clamp(0.01f * extent, 0.4f, 5.0f); }

Mesh orbitTubeMesh(const std::vector<glm::vec3>& points, float radius, const glm::vec3& colour, std::size_t maxPoints, int sides)
{
    Mesh mesh;
    sides = std::max(3, sides);
    std::vector<glm::vec3> path;
    const std::size_t step = std::max<std::size_t>(1, (points.size() + std::max<std::size_t>(2, maxPoints) - 1) /
                                                           std::max<std::size_t>(2, maxPoints));
    for (std::size_t i = 0; i < points.size(); i += step)
        if (path.empty() || glm::length(points[i] - path.back()) > 1e-4f) path.push_back(points[i]);
    if (!points.empty() && (path.empty() || glm::length(points.back() - path.back()) > 1e-4f)) path.push_back(points.back());
    if (path.size() < 2) return mesh;

    // Rings carried along the path by parallel transport (no twist where the path turns).
    glm::vec3 normal(0.0f);
    for (std::size_t i = 0; i < path.size(); ++i) {
        const glm::vec3 ahead = path[std::min(i + 1, path.size() - 1)] - path[i > 0 ? i - 1 : 0];
        const glm::vec3 tangent = glm::length(ahead) > 0.0f ? glm::normalize(ahead) : glm::vec3(1.0f, 0.0f, 0.0f);
        if (i == 0) normal = anyPerpendicular(tangent);
        normal = normal - tangent * glm::dot(normal, tangent);
        normal = glm::length(normal) > 1e-6f ? glm::normalize(normal) : anyPerpendicular(tangent);
        const glm::vec3 binormal = glm::cross(tangent, normal);
        for (int k = 0; k < sides; ++k) {
            const float angle = 2.0f * 3.14159265f * float(k) / float(sides);
            const glm::vec3 out = std::cos(angle) * normal + std::sin(angle) * binormal;
            mesh.vertices.push_back(Vertex{path[i] + radius * out, out, colour});
        }
    }
    const auto ring = [sides](std::size_t i, int k) { return std::uint32_t(i * std::size_t(sides) + std::size_t(k % sides)); };
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        for (int k = 0; k < sides; ++k) {
            mesh.indices.insert(mesh.indices.end(), {ring(i, k), ring(i + 1, k), ring(i + 1, k + 1)});
            mesh.indices.insert(mesh.indices.end(), {ring(i, k), ring(i + 1, k + 1), ring(i, k + 1)});
        }
    return mesh;
}

} // namespace bunraku::render
