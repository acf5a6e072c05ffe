#include "render/mesh.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace bunraku::render {

void Mesh::append(const Mesh& other)
{
    const auto offset = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    indices.reserve(indices.size() + other.indices.size());
    for (const std::uint32_t index : other.indices) indices.push_back(index + offset);
}

Mesh transformed(const Mesh& mesh, const glm::mat4& a_T_b)
{
    Mesh result = mesh;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(a_T_b)));
    for (Vertex& vertex : result.vertices) {
        vertex.position = glm::vec3(a_T_b * glm::vec4(vertex.position, 1.0f));
        const glm::vec3 normal = normalMatrix * vertex.normal;
        const float length = glm::length(normal);
        vertex.normal = length > 0.0f ? normal / length : normal;
    }
    return result;
}

void paint(Mesh& mesh, const glm::vec3& colour)
{
    for (Vertex& vertex : mesh.vertices) vertex.colour = colour;
}

Mesh boxMesh(const glm::vec3& size)
{
    Mesh mesh;
    const glm::vec3 h = size * 0.5f;
    // Each face: its normal and two in-plane axes u, v with u x v = normal (counter-clockwise).
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = std::abs(n.z) > 0.5f ? glm::vec3(1, 0, 0) * n.z : glm::vec3(-n.y, n.x, 0);
        const glm::vec3 v = glm::cross(n, u);
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            const glm::vec3 p = n + u * c[0] + v * c[1]; // in the unit cube [-1, 1]^3
            mesh.vertices.push_back(Vertex{p * h, n, glm::vec3(0.8f)});
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return mesh;
}

Mesh frustumMesh(float bottomRadius, float topRadius, float length, int segments)
{
    Mesh mesh;
    const float half = length * 0.5f;
    const float twoPi = glm::two_pi<float>();
    // Side normals tilt outwards/upwards by the cone's slope.
    const float slope = length > 0.0f ? (bottomRadius - topRadius) / length : 0.0f;
    for (int i = 0; i <= segments; ++i) {
        const float a = twoPi * float(i) / float(segments);
        const glm::vec3 radial(std::cos(a), std::sin(a), 0.0f);
        const glm::vec3 normal = glm::normalize(radial + glm::vec3(0, 0, slope));
        mesh.vertices.push_back(Vertex{radial * bottomRadius + glm::vec3(0, 0, -half), normal, glm::vec3(0.8f)});
        mesh.vertices.push_back(Vertex{radial * topRadius + glm::vec3(0, 0, half), normal, glm::vec3(0.8f)});
    }
    for (int i = 0; i < segments; ++i) {
        const auto b = static_cast<std::uint32_t>(2 * i);
        mesh.indices.insert(mesh.indices.end(), {b, b + 2, b + 3, b, b + 3, b + 1});
    }
    // Caps: a centre vertex and a ring with the cap's normal.
    for (const float side : {-1.0f, 1.0f}) {
        const float radius = side < 0 ? bottomRadius : topRadius;
        if (radius <= 0.0f) continue;
        const glm::vec3 normal(0, 0, side);
        const auto centre = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(Vertex{glm::vec3(0, 0, side * half), normal, glm::vec3(0.8f)});
        for (int i = 0; i <= segments; ++i) {
            const float a = twoPi * float(i) / float(segments);
            mesh.vertices.push_back(
                Vertex{glm::vec3(std::cos(a) * radius, std::sin(a) * radius, side * half), normal, glm::vec3(0.8f)});
        }
        for (int i = 0; i < segments; ++i) {
            const auto r = static_cast<std::uint32_t>(centre + 1 + i);
            if (side > 0)
                mesh.indices.insert(mesh.indices.end(), {centre, r, r + 1});
            else
                mesh.indices.insert(mesh.indices.end(), {centre, r + 1, r});
        }
    }
    return mesh;
}

Mesh cylinderMesh(float radius, float length, int segments)
{
    return frustumMesh(radius, radius, length, segments);
}

Mesh ellipsoidMesh(const glm::vec3& radii, int slices, int stacks)
{
    Mesh mesh;
    const float pi = glm::pi<float>();
    for (int j = 0; j <= stacks; ++j) {
        const float polar = pi * float(j) / float(stacks); // 0 at +z
        for (int i = 0; i <= slices; ++i) {
            const float azimuth = 2.0f * pi * float(i) / float(slices);
            const glm::vec3 unit(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
            // The normal of x^2/a^2 + ... = 1 at p is p / radii^2.
            const glm::vec3 position = unit * radii;
            const glm::vec3 gradient = position / (radii * radii);
            mesh.vertices.push_back(Vertex{position, glm::normalize(gradient), glm::vec3(0.8f)});
        }
    }
    const auto row = static_cast<std::uint32_t>(slices + 1);
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            const auto a = static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
            mesh.indices.insert(mesh.indices.end(), {a, a + row, a + row + 1, a, a + row + 1, a + 1});
        }
    }
    return mesh;
}

Mesh gridMesh(float halfExtent, float spacing)
{
    Mesh mesh;
    mesh.topology = MeshTopology::Lines;
    const int steps = static_cast<int>(std::floor(halfExtent / spacing));
    const glm::vec3 up(0, 0, 1);
    for (int i = -steps; i <= steps; ++i) {
        const float c = float(i) * spacing;
        const glm::vec3 colour = i == 0 ? glm::vec3(0.55f) : glm::vec3(0.72f);
        const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(Vertex{{c, -halfExtent, 0}, up, colour});
        mesh.vertices.push_back(Vertex{{c, halfExtent, 0}, up, colour});
        mesh.vertices.push_back(Vertex{{-halfExtent, c, 0}, up, colour});
        mesh.vertices.push_back(Vertex{{halfExtent, c, 0}, up, colour});
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base + 3});
    }
    return mesh;
}

Mesh polylineMesh(const std::vector<glm::vec3>& points, const glm::vec3& colour)
{
    Mesh mesh;
    mesh.topology = MeshTopology::LineStrip;
    for (std::size_t i = 0; i < points.size(); ++i) {
        mesh.vertices.push_back(Vertex{points[i], glm::vec3(0, 0, 1), colour});
        mesh.indices.push_back(static_cast<std::uint32_t>(i));
    }
    return mesh;
}

} // namespace bunraku::render
