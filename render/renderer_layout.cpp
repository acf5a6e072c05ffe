#include "render/renderer_internal.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <functional>
#include <limits>

// The renderer's placement, bounds and framing: CPU only, no OpenGL call.
namespace bunraku::render {

const Renderer::PuppetFigure* Renderer::slotPuppet(const Slot& slot) const
{
    return slot.puppet ? slot.puppet.get() : m_puppet.get();
}

void Renderer::addPuppetBounds(Bounds& bounds, const Slot& slot, Eigen::Index frame, const glm::mat4& root,
                               const std::function<bool(const std::string&, const std::string&)>& wanted) const
{
    const PuppetFigure* figure = slotPuppet(slot);
    if (!figure) return;
    const auto joints = analysis::puppetJointPoses(*figure->mesh, slot.body, analysis::worldPartPoses(slot.body, slot.binding, slot.take, frame));
    const auto partOf = analysis::puppetJointPartIndices(slot.body);
    for (int j = 0; j < analysis::kPuppetJointCount; ++j) {
        const Bounds& box = figure->jointBounds[std::size_t(j)];
        const int p = partOf[std::size_t(j)];
        if (box.empty() || p < 0) continue;
        if (wanted && !wanted(slot.body.parts[std::size_t(p)].name, slot.body.parts[std::size_t(p)].drivenBy)) continue;
        const glm::mat4 world_T_joint = root * toMatrix(joints[std::size_t(j)]);
        for (int corner = 0; corner < 8; ++corner)
            bounds.add(glm::vec3(world_T_joint * glm::vec4((corner & 1) ? box.upper.x : box.lower.x, (corner & 2) ? box.upper.y : box.lower.y,
                                                           (corner & 4) ? box.upper.z : box.lower.z, 1.0f)));
    }
}

glm::mat4 Renderer::takeRoot(int takeSlot, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    LayoutOptions layout = m_layout;
    layout.separation *= framedHeight() / kPuppetFramedHeight;
    return slotRoot(slot.centre, takeSlot, int(m_slots.size()), camera, layout);
}

std::vector<glm::mat4> Renderer::displayedPartTransforms(int takeSlot, const Camera& camera) const
{
    const glm::mat4 root = takeRoot(takeSlot, camera);
    std::vector<glm::mat4> result;
    for (const glm::mat4& take_T_part : m_slots.at(std::size_t(takeSlot)).take_T_part) result.push_back(root * take_T_part);
    return result;
}

std::optional<glm::mat4> Renderer::displayedAxisTransform(int takeSlot, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    if (slot.world_T_axis.empty()) return std::nullopt;
    return takeRoot(takeSlot, camera) * toMatrix(slot.world_T_axis[std::size_t(slot.frame)]);
}

std::vector<glm::vec3> Renderer::displayedSensorPositions(int takeSlot, Eigen::Index frame, const Camera& camera) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    const glm::mat4 root = takeRoot(takeSlot, camera);
    const Eigen::Index f = std::clamp<Eigen::Index>(frame, 0, slot.take.frameCount() - 1);
    std::vector<glm::vec3> result;
    for (const Eigen::Index first : slot.sensorFirstChannel)
        result.push_back(glm::vec3(root * glm::vec4(sensorPosition(slot.take, f, first), 1.0f)));
    return result;
}

std::vector<glm::mat4> Renderer::displayedJointTransforms(int takeSlot, const Camera& camera) const
{
    const glm::mat4 root = takeRoot(takeSlot, camera);
    std::vector<glm::mat4> result;
    for (const glm::mat4& take_T_joint : m_slots.at(std::size_t(takeSlot)).take_T_joint) result.push_back(root * take_T_joint);
    return result;
}

bool Renderer::skeletonDrawn(int takeSlot) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    return m_visibility.puppet && slot.take.skeleton && m_visibility.figures[std::size_t(takeSlot)] != FigureStyle::Puppet;
}

bool Renderer::clothDrawn(int takeSlot) const
{
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    return puppetDrawn(takeSlot) && slot.cloth && slot.clothReady && slotPuppet(slot) != nullptr;
}

bool Renderer::puppetDrawn(int takeSlot) const
{
    return m_visibility.puppet && (!skeletonDrawn(takeSlot) || m_visibility.figures[std::size_t(takeSlot)] == FigureStyle::PuppetAndSkeleton);
}

float Renderer::floorHeight() const
{
    float lowest = std::numeric_limits<float>::max();
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        const bool skeleton = skeletonDrawn(int(s));
        if (!skeleton || puppetDrawn(int(s))) lowest = std::min(lowest, m_slots[s].puppetLowest);
        if (skeleton) lowest = std::min(lowest, m_slots[s].skeletonLowest);
        if (skeleton && m_visibility.figures[s] == FigureStyle::FileMesh && takeHasFileMesh(m_slots[s].take))
            lowest = std::min(lowest, m_slots[s].fileMeshLowest);
    }
    return lowest == std::numeric_limits<float>::max() ? 0.0f : lowest - 1.0f;
}

float Renderer::framedHeight() const
{
    // A drawn skeleton, or a puppet fitted to a taller performer, is framed by its height (the
    // shipped puppet by the height the distances were chosen for); two such takes side by side
    // then stand as far apart as they are tall, so a raised arm does not reach into the other.
    const float floor = floorHeight();
    float height = kPuppetFramedHeight;
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        if (skeletonDrawn(int(s))) height = std::max(height, m_slots[s].skeletonHighest - floor);
        if (puppetDrawn(int(s))) height = std::max(height, m_slots[s].puppetHighest - floor);
    }
    return height;
}

Camera Renderer::framingCamera() const
{
    Camera camera;
    camera.angleDeg = 340.0f;
    camera.elevationDeg = 15.0f;
    const float floor = floorHeight();
    const float height = framedHeight();
    camera.target = {0.0f, 0.0f, floor + 0.5f * height};
    camera.distance = (m_slots.size() > 1 ? 300.0f : 230.0f) * height / kPuppetFramedHeight;
    return camera;
}

Bounds Renderer::displayedBounds(const Camera& camera, const BoundsQuery& query) const
{
    const Eigen::Index sampled = std::max(1, query.sampledFrames);
    Bounds bounds;
    for (std::size_t s = 0; s < m_slots.size(); ++s) {
        if (query.takeSlot >= 0 && query.takeSlot != int(s)) continue;
        const Slot& slot = m_slots[s];
        const glm::mat4 root = takeRoot(int(s), camera);
        std::vector<Eigen::Index> frames{slot.frame};
        if (query.span == FramingSpan::WholeTake) {
            frames.clear();
            const Eigen::Index count = slot.take.frameCount();
            const Eigen::Index step = std::max<Eigen::Index>(1, count / sampled);
            for (Eigen::Index f = 0; f < count; f += step) frames.push_back(f);
            frames.push_back(count - 1);
        }
        const auto wanted = [&](const std::string& name, const std::string& drivenBy) {
            return query.part.empty() || name == query.part || drivenBy == query.part;
        };
        if (puppetDrawn(int(s)) && slotPuppet(slot)) {
            for (const Eigen::Index f : frames) addPuppetBounds(bounds, slot, f, root, wanted);
        } else if (puppetDrawn(int(s))) {
            for (const Eigen::Index f : frames) {
                const auto poses = analysis::worldPartPoses(m_body, slot.binding, slot.take, f);
                for (std::size_t p = 0; p < poses.size() && p < m_partBounds.size(); ++p) {
                    if (!wanted(m_body.parts[p].name, m_body.parts[p].drivenBy) || m_partBounds[p].empty()) continue;
                    const glm::mat4 world_T_part = root * toMatrix(poses[p]);
                    const Bounds& box = m_partBounds[p];
                    for (int corner = 0; corner < 8; ++corner)
                        bounds.add(glm::vec3(world_T_part * glm::vec4((corner & 1) ? box.upper.x : box.lower.x,
                                                                      (corner & 2) ? box.upper.y : box.lower.y,
                                                                      (corner & 4) ? box.upper.z : box.lower.z, 1.0f)));
                }
            }
        }
        // The skeleton: every joint (a sphere of the joint radius; the bones run between them;
        // the body's trunk is up to 7.5 % of the height thick).
        if (skeletonDrawn(int(s)) && slot.skeleton) {
            const FigureStyle style = m_visibility.figures[s];
            const float radius = style == FigureStyle::Body ? std::max(slot.skeleton->jointRadius, 0.08f * (slot.skeletonHighest - slot.skeletonLowest))
                                 : style == FigureStyle::FileMesh && slot.skeleton->fileMeshReach > 0.0f
                                     ? std::max(slot.skeleton->jointRadius, slot.skeleton->fileMeshReach)
                                     : slot.skeleton->jointRadius;
            for (const Eigen::Index f : frames) {
                const auto poses = slot.take.skeleton->worldPoses(f);
                for (std::size_t j = 0; j < poses.size(); ++j) {
                    const std::string& part = j < slot.skeleton->jointParts.size() ? slot.skeleton->jointParts[j] : std::string();
                    const std::string& name = j < slot.skeleton->jointNames.size() ? slot.skeleton->jointNames[j] : std::string();
                    if (!wanted(name, part)) continue;
                    const glm::vec3 joint(root * glm::vec4(float(poses[j].translation.x()), float(poses[j].translation.y()),
                                                           float(poses[j].translation.z()), 1.0f));
                    bounds.add(joint - glm::vec3(radius));
                    bounds.add(joint + glm::vec3(radius));
                }
            }
        }
        // The orbits, or the sensors standing for a hidden puppet.
        if (m_visibility.orbitsDrawn() || !m_visibility.puppet) {
            for (const Eigen::Index first : slot.sensorFirstChannel) {
                if (!wanted(slot.take.channels[std::size_t(first)].part, {})) continue;
                for (const Eigen::Index f : frames) bounds.add(glm::vec3(root * glm::vec4(sensorPosition(slot.take, f, first), 1.0f)));
            }
        }
        if (!query.part.empty()) continue;
        if (partnerShown(int(s), camera) && !query.figuresOnly) {
            // The take's puppet as it stands at frame 0, or partnerMesh: a disc of radius 14 cm
            // under a cone 46 cm high.
            const glm::mat4 world_T_partner = partnerTransform(slot, root);
            if (slotPuppet(slot)) {
                addPuppetBounds(bounds, slot, 0, world_T_partner, {});
            } else {
                for (const glm::vec3 corner : {glm::vec3(-14.0f, -14.0f, 0.0f), glm::vec3(14.0f, 14.0f, 46.0f)})
                    bounds.add(glm::vec3(world_T_partner * glm::vec4(corner, 1.0f)));
            }
        }
        if (m_visibility.axis && !slot.world_T_axis.empty()) {
            for (const Eigen::Index f : frames) {
                const glm::mat4 world_T_axis = root * toMatrix(slot.world_T_axis[std::size_t(f)]);
                for (int axis = 0; axis < 3; ++axis) {
                    glm::vec4 tip(0.0f, 0.0f, 0.0f, 1.0f);
                    tip[axis] = m_layout.axisBarLength;
                    bounds.add(glm::vec3(world_T_axis * tip));
                }
                bounds.add(glm::vec3(world_T_axis[3]));
            }
        }
    }
    return bounds;
}

glm::mat4 Renderer::partnerTransform(const Slot& slot, const glm::mat4& root) const
{
    const glm::vec3 partner = slot.partnerSpot;
    const glm::mat4 onFloor = root * glm::translate(glm::mat4(1.0f), glm::vec3(partner.x, partner.y, floorHeight()));
    if (!slotPuppet(slot)) return onFloor;
    // The take's puppet as it stands at frame 0, turned about its centre to face the take, as
    // tall as the figure drawn (a performer's skeleton is taller than the puppet fitted to it).
    const int index = int(&slot - m_slots.data());
    const float puppetHeight = slot.puppetHighest - slot.puppetLowest;
    const float height = puppetDrawn(index) ? puppetHeight : slot.skeletonHighest - slot.skeletonLowest;
    const float scale = puppetHeight > 1.0f && height > 1.0f ? height / puppetHeight : 1.0f;
    return glm::scale(glm::rotate(onFloor, glm::pi<float>(), glm::vec3(0.0f, 0.0f, 1.0f)), glm::vec3(scale)) *
           glm::translate(glm::mat4(1.0f), glm::vec3(-slot.centre.x, -slot.centre.y, -slot.puppetLowest));
}

bool Renderer::partnerShown(int takeSlot, const Camera& camera) const
{
    if (!m_visibility.partner) return false;
    // Two takes stand side by side along the screen's right: seen from the side, one take's
    // partner would stand inside the other take's figure, and is left out.
    const Slot& slot = m_slots.at(std::size_t(takeSlot));
    const glm::vec3 partner(takeRoot(takeSlot, camera) * glm::vec4(slot.partnerSpot, 1.0f));
    for (std::size_t other = 0; other < m_slots.size(); ++other) {
        if (int(other) == takeSlot) continue;
        const glm::vec3 figure(takeRoot(int(other), camera) * glm::vec4(m_slots[other].centre, 1.0f));
        if (glm::length(glm::vec2(partner - figure)) < 0.5f * framedHeight()) return false;
    }
    return true;
}

} // namespace bunraku::render
