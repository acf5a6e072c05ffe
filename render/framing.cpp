#include "render/framing.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bunraku::render {

void Bounds::add(const glm::vec3& point)
{
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) return;
    if (!valid) {
        lower = upper = point;
        valid = true;
        return;
    }
    lower = glm::min(lower, point);
    upper = glm::max(upper, point);
}

void Bounds::add(const Bounds& other)
{
    if (!other.valid) return;
    add(other.lower);
    add(other.upper);
}

float Bounds::extent() const
{
    const glm::vec3 s = size();
    return std::max({s.x, s.y, s.z});
}

Camera framedCamera(const Camera& view, const Bounds& bounds, QSize size, float margin)
{
    if (bounds.empty() || size.isEmpty()) return view;
    Camera camera = view;
    camera.target = bounds.centre();
    const float aspect = float(size.width()) / float(size.height());
    const float fill = 1.0f - std::clamp(margin, 0.0f, 0.9f);
    const float tanVertical = std::tan(glm::radians(camera.fieldOfViewDeg) * 0.5f) * fill;
    const float tanHorizontal = tanVertical * aspect;
    const glm::vec3 right = camera.right();
    const glm::vec3 up = camera.up();
    const glm::vec3 forward = camera.forward();
    // A corner v (from the target) lies at depth d + v.forward in front of the eye, and inside
    // the view when |v.right| <= depth tan(h/2) and |v.up| <= depth tan(v/2): the smallest d
    // meeting that for every corner. The box is symmetric about the target, so a depth margin of
    // a tenth of its size keeps the nearest corner off the near plane.
    const float clearance = 0.1f * std::max(bounds.extent(), 1.0f);
    float distance = kMinCameraDistance;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point((corner & 1) ? bounds.upper.x : bounds.lower.x, (corner & 2) ? bounds.upper.y : bounds.lower.y,
                              (corner & 4) ? bounds.upper.z : bounds.lower.z);
        const glm::vec3 v = point - camera.target;
        const float depthOffset = glm::dot(v, forward);
        distance = std::max(distance, std::abs(glm::dot(v, right)) / tanHorizontal - depthOffset);
        distance = std::max(distance, std::abs(glm::dot(v, up)) / tanVertical - depthOffset);
        distance = std::max(distance, clearance - depthOffset);
    }
    camera.distance = std::clamp(distance, kMinCameraDistance, kMaxCameraDistance);
    return camera;
}

Camera resetCamera(const Bounds& bounds, QSize size)
{
    Camera camera;
    camera.angleDeg = 340.0f;
    camera.elevationDeg = 15.0f;
    camera.fieldOfViewDeg = 35.0f;
    return framedCamera(camera, bounds, size, 0.05f);
}

Camera followingCamera(const Camera& camera, const Bounds& figures)
{
    if (figures.empty()) return camera;
    Camera moved = camera;
    moved.target.x = figures.centre().x;
    moved.target.y = figures.centre().y;
    return moved;
}

bool boundsDiffer(const Bounds& a, const Bounds& b, float ratio)
{
    if (a.empty() || b.empty()) return a.empty() != b.empty();
    const float extentA = std::max(a.extent(), 1.0f);
    const float extentB = std::max(b.extent(), 1.0f);
    if (extentA > extentB * ratio || extentB > extentA * ratio) return true;
    return glm::length(a.centre() - b.centre()) > (ratio - 1.0f) * std::max(extentA, extentB);
}

} // namespace bunraku::render
