#include "render/scene.h"

#include "analysis/body/body_pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/skeleton_mesh.h"
#include "analysis/core/skeleton_take.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace bunraku::render {

std::optional<FigureStyle> figureStyleFromName(std::string_view name)
{
    if (name == "puppet") return FigureStyle::Puppet;
    if (name == "skeleton") return FigureStyle::Skeleton;
    if (name == "both") return FigureStyle::PuppetAndSkeleton;
    if (name == "body") return FigureStyle::Body;
    if (name == "mesh") return FigureStyle::FileMesh;
    return std::nullopt;
}

bool takeHasFileMesh(const analysis::Take& take)
{
    return take.skeleton && take.skeleton->skeleton && take.skeleton->skeleton->mesh &&
           analysis::meshFitsSkeleton(*take.skeleton->skeleton->mesh, *take.skeleton->skeleton);
}

analysis::Status validateScene(const SceneContent& scene, std::vector<analysis::Take>* drawn, const std::vector<bool>& kept)
{
    using analysis::ErrorCode;
    using analysis::makeError;
    if (scene.takes.empty() || scene.takes.size() > kMaxTakeSlots)
        return makeError(ErrorCode::InvalidArgument,
                         "a scene shows 1 or 2 takes, got " + std::to_string(scene.takes.size()));
    if (scene.body.parts.empty() || scene.body.parts.size() > kMaxBodyParts)
        return makeError(ErrorCode::Unsupported, "the renderer draws bodies of 1.." + std::to_string(kMaxBodyParts) +
                                                     " parts, the body has " + std::to_string(scene.body.parts.size()));
    for (std::size_t s = 0; s < scene.takes.size(); ++s) {
        const TakeSlot& slot = scene.takes[s];
        if (s < kept.size() && kept[s]) {
            if (drawn) drawn->emplace_back();
            continue;
        }
        const std::string name = slot.take.displayName();
        if (auto status = analysis::validateTake(slot.take); !status.ok()) return status.error();
        const analysis::BodyDescription& body = slot.body ? *slot.body : scene.body;
        if (slot.body) {
            bool same = slot.body->parts.size() == scene.body.parts.size();
            for (std::size_t p = 0; same && p < scene.body.parts.size(); ++p) same = slot.body->parts[p].name == scene.body.parts[p].name;
            if (!same)
                return makeError(ErrorCode::InvalidArgument, "take " + name + ": its own body does not have the scene body's parts");
        }
        if (analysis::bindBody(body, slot.take).ok()) {
            if (drawn) drawn->push_back(slot.take); // copied only for a caller that keeps it
        } else {
            auto posed = drawnTake(body, slot.take); // a skeleton's joints: the puppet its skeleton poses
            if (!posed.ok()) return posed.error();
            if (drawn) drawn->push_back(std::move(posed).value());
        }
        if (!slot.world_T_axis.empty() && Eigen::Index(slot.world_T_axis.size()) != slot.take.frameCount())
            return makeError(ErrorCode::InvalidArgument,
                             "take " + name + ": " + std::to_string(slot.world_T_axis.size()) + " axis poses for " +
                                 std::to_string(slot.take.frameCount()) + " frames");
    }
    for (const auto& [part, mesh] : scene.partMeshes) {
        if (scene.body.partIndex(part) < 0)
            return makeError(ErrorCode::NotFound, "mesh for unknown body part '" + part + "'");
        if (mesh.topology != MeshTopology::Triangles || mesh.empty())
            return makeError(ErrorCode::InvalidArgument, "mesh for body part '" + part + "' has no triangles");
    }
    return analysis::okStatus();
}

analysis::Result<analysis::Take> drawnTake(const analysis::BodyDescription& body, const analysis::Take& take)
{
    auto binding = analysis::bindBody(body, take);
    if (binding.ok()) return take;
    if (!take.skeleton || !take.skeleton->skeleton) return binding.error();
    for (const auto part : analysis::kPuppetParts)
        if (!take.skeleton->skeleton->binding(part)) return binding.error();
    auto puppet = analysis::puppetTakeFromSkeleton(take.skeleton, take.rateHz, take.labels);
    if (!puppet.ok()) return analysis::makeError(puppet.error().code, "take " + take.displayName() + ": " + puppet.error().message);
    if (auto bound = analysis::bindBody(body, *puppet); !bound.ok()) return bound.error();
    return puppet;
}

bool drawableTake(const analysis::Take& take)
{
    if (analysis::hasPuppetLayout(take)) return true;
    if (!take.skeleton || !take.skeleton->skeleton) return false;
    for (const auto part : analysis::kPuppetParts)
        if (!take.skeleton->skeleton->binding(part)) return false;
    return true;
}

glm::vec3 takeCentre(const analysis::Take& take, std::string_view centrePart)
{
    auto parts = analysis::sixDofParts(take);
    const auto centre = std::find_if(parts.begin(), parts.end(), [&](const auto& part) { return part.part == centrePart; });
    if (centre != parts.end()) parts = {*centre};
    double x = 0.0;
    double y = 0.0;
    double count = 0.0;
    for (const auto& part : parts) {
        x += take.values.col(part.firstChannel).sum();
        y += take.values.col(part.firstChannel + 1).sum();
        count += double(take.frameCount());
    }
    if (count == 0.0) return glm::vec3(0.0f);
    return {float(x / count), float(y / count), 0.0f};
}

glm::mat4 slotRoot(const glm::vec3& centre, int slotIndex, int slotCount, const Camera& camera,
                   const LayoutOptions& options)
{
    glm::vec3 offset(0.0f);
    if (options.centreTakes) offset -= centre;
    if (slotCount > 1) {
        const float side = slotIndex == 0 ? -0.5f : 0.5f;
        offset += camera.right() * (side * options.separation);
    }
    return glm::translate(glm::mat4(1.0f), offset);
}

Eigen::Index frameAtTime(const analysis::Take& take, double seconds)
{
    if (take.frameCount() == 0) return 0;
    const double frame = std::round(seconds * take.rateHz);
    return Eigen::Index(std::clamp(frame, 0.0, double(take.frameCount() - 1)));
}

glm::mat4 toMatrix(const analysis::RigidTransform& a_T_b)
{
    const Eigen::Matrix3d r = a_T_b.rotation.toRotationMatrix();
    glm::mat4 m(1.0f);
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row) m[column][row] = float(r(row, column));
    m[3] = glm::vec4(float(a_T_b.translation.x()), float(a_T_b.translation.y()), float(a_T_b.translation.z()), 1.0f);
    return m;
}

glm::vec3 orbitColour(int slotIndex, int sensorIndex)
{
    static const std::array<glm::vec3, 4> first{
        glm::vec3(0.90f, 0.45f, 0.05f), glm::vec3(0.45f, 0.20f, 0.70f), glm::vec3(0.05f, 0.55f, 0.55f),
        glm::vec3(0.60f, 0.35f, 0.15f)};
    glm::vec3 colour = first[std::size_t(sensorIndex) % first.size()];
    if (slotIndex > 0) colour *= 0.7f; // the second take's orbits are darker
    return colour;
}

glm::vec3 kimonoOrbitColour(int slotIndex, int point)
{
    glm::vec3 colour = point < 2 ? glm::vec3(0.80f, 0.10f, 0.25f) : glm::vec3(0.55f, 0.25f, 0.50f);
    if (slotIndex > 0) colour *= 0.7f;
    return colour;
}

glm::vec3 axisColour(int axis)
{
    switch (axis) {
    case 0: return {0.90f, 0.10f, 0.10f};
    case 1: return {0.10f, 0.75f, 0.10f};
    default: return {0.10f, 0.20f, 0.95f};
    }
}

} // namespace bunraku::render
