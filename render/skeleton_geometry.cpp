#include "render/skeleton_geometry.h"

#include "analysis/core/puppet_layout.h"
#include "render/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace bunraku::render {

namespace {

constexpr float kMinimumBoneLength = 1e-3f; // cm

/// The rotation taking +z to the unit vector `direction`.
glm::mat4 zTo(const glm::vec3& direction)
{
    const glm::vec3 z(0.0f, 0.0f, 1.0f);
    const float cosine = glm::dot(z, direction);
    if (cosine > 1.0f - 1e-6f) return glm::mat4(1.0f);
    if (cosine < -1.0f + 1e-6f) return glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float>, glm::vec3(1.0f, 0.0f, 0.0f));
    return glm::rotate(glm::mat4(1.0f), std::acos(cosine), glm::normalize(glm::cross(z, direction)));
}

glm::vec3 toGlm(const Eigen::Vector3d& v) { return {float(v.x()), float(v.y()), float(v.z())}; }

} // namespace

float skeletonHeight(const analysis::SkeletalMotion& motion)
{
    if (motion.frameCount() < 1) return 1.0f;
    double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
    for (const auto& pose : motion.worldPoses(0)) {
        low = std::min(low, pose.translation.z());
        high = std::max(high, pose.translation.z());
    }
    return std::max(1.0f, float(high - low));
}

float skeletonJointRadius(const analysis::SkeletalMotion& motion, const SkeletonStyle& style)
{
    return style.jointRadiusScale * style.boneRadiusPerHeight * skeletonHeight(motion);
}

Mesh capsuleMesh(float radius, float length, int segments, int capStacks)
{
    Mesh mesh;
    // Rings from the bottom pole to the top pole: the lower cap about z = 0, the upper about z = length.
    struct Ring {
        float centre, latitude;
    };
    std::vector<Ring> rings;
    const float quarter = std::numbers::pi_v<float> / 2.0f;
    for (int k = 0; k <= capStacks; ++k) rings.push_back({0.0f, -quarter + quarter * float(k) / float(capStacks)});
    for (int k = 0; k <= capStacks; ++k) rings.push_back({length, quarter * float(k) / float(capStacks)});
    for (const Ring& ring : rings)
        for (int s = 0; s <= segments; ++s) {
            const float angle = 2.0f * std::numbers::pi_v<float> * float(s) / float(segments);
            const glm::vec3 normal(std::cos(ring.latitude) * std::cos(angle), std::cos(ring.latitude) * std::sin(angle), std::sin(ring.latitude));
            Vertex vertex;
            vertex.position = radius * normal + glm::vec3(0.0f, 0.0f, ring.centre);
            vertex.normal = normal;
            mesh.vertices.push_back(vertex);
        }
    const auto row = std::uint32_t(segments + 1);
    for (std::uint32_t r = 0; r + 1 < rings.size(); ++r)
        for (std::uint32_t s = 0; s < std::uint32_t(segments); ++s) {
            const std::uint32_t a = r * row + s, b = a + 1, c = a + row, d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
        }
    return mesh;
}

std::string jointPart(const analysis::Skeleton& skeleton, int joint)
{
    for (const auto& binding : skeleton.parts)
        if (binding.joint == joint) return binding.part;
    return {};
}

bool isRigidBone(const analysis::SkeletalMotion& motion, int child)
{
    if (std::find(motion.movingJoints.begin(), motion.movingJoints.end(), child) != motion.movingJoints.end()) return false;
    return motion.staticTranslations[std::size_t(child)].norm() > kMinimumBoneLength;
}

std::vector<Mesh> buildSkeletonMeshes(const analysis::SkeletalMotion& motion, const SkeletonStyle& style)
{
    const analysis::Skeleton& skeleton = *motion.skeleton;
    const float boneRadius = style.boneRadiusPerHeight * skeletonHeight(motion);
    const float jointRadius = skeletonJointRadius(motion, style);
    std::vector<Mesh> meshes(skeleton.joints.size());
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        if (skeleton.joints[j].endSite) continue;
        glm::vec3 colour = style.boneColour;
        const std::string part = jointPart(skeleton, int(j));
        for (std::size_t p = 0; p < analysis::kPuppetParts.size(); ++p)
            if (!part.empty() && analysis::kPuppetParts[p] == part) colour = orbitColour(0, int(p));
        Mesh mesh = ellipsoidMesh(glm::vec3(jointRadius), style.segments, std::max(4, style.segments / 2));
        for (int child : skeleton.children(int(j))) {
            if (!isRigidBone(motion, child)) continue;
            const glm::vec3 bone = toGlm(motion.staticTranslations[std::size_t(child)]);
            const float length = glm::length(bone);
            mesh.append(transformed(capsuleMesh(boneRadius, length, style.segments, 3), zTo(bone / length)));
        }
        paint(mesh, colour);
        meshes[j] = std::move(mesh);
    }
    return meshes;
}

} // namespace bunraku::render
