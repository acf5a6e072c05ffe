#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace bunraku::render {

namespace {
float radians(float degrees) { return glm::radians(degrees); }
float clampedElevation(float degrees) { return std::clamp(degrees, -90.0f, 90.0f); }
} // namespace

Camera Camera::withPreset(CameraPreset preset) const
{
    Camera camera = *this;
    camera.elevationDeg = preset == CameraPreset::Top ? 90.0f : -90.0f;
    return camera;
}

glm::vec3 Camera::eye() const
{
    const float a = radians(angleDeg);
    const float e = radians(clampedElevation(elevationDeg));
    const glm::vec3 horizontal(-std::sin(a), std::cos(a), 0.0f);
    return target + distance * (std::cos(e) * horizontal + glm::vec3(0.0f, 0.0f, std::sin(e)));
}

glm::vec3 Camera::right() const
{
    const float a = radians(angleDeg);
    return {-std::cos(a), -std::sin(a), 0.0f};
}

glm::vec3 Camera::forward() const
{
    const float a = radians(angleDeg);
    const float e = radians(clampedElevation(elevationDeg));
    const glm::vec3 horizontal(-std::sin(a), std::cos(a), 0.0f);
    return -(std::cos(e) * horizontal + glm::vec3(0.0f, 0.0f, std::sin(e)));
}

glm::vec3 Camera::up() const { return glm::normalize(glm::cross(right(), forward())); }

glm::mat4 Camera::view() const { return glm::lookAt(eye(), target, up()); }

glm::mat4 Camera::projection(float aspect) const
{
    const float nearPlane = std::max(1.0f, distance * 0.02f);
    const float farPlane = distance * 4.0f + 2000.0f;
    if (orthographicHeight > 0.0f) {
        const float h = 0.5f * orthographicHeight;
        return glm::ortho(-h * aspect, h * aspect, -h, h, nearPlane, farPlane);
    }
    return glm::perspective(radians(fieldOfViewDeg), aspect, nearPlane, farPlane);
}

glm::mat4 Camera::viewProjection(QSize size) const
{
    const float aspect = size.height() > 0 ? float(size.width()) / float(size.height()) : 1.0f;
    return projection(aspect) * view();
}

ScreenPoint Camera::project(const glm::vec3& world, QSize size) const
{
    const glm::vec4 clip = viewProjection(size) * glm::vec4(world, 1.0f);
    ScreenPoint point;
    point.inFront = clip.w > 0.0f;
    if (clip.w == 0.0f) return point;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    // Pixel centres sit at half-integers: NDC -1 is the left edge of pixel 0.
    point.pixel = QPointF((ndc.x + 1.0f) * 0.5f * float(size.width()), (1.0f - ndc.y) * 0.5f * float(size.height()));
    point.depth = ndc.z;
    return point;
}

Ray Camera::rayThrough(QPointF pixel, QSize size) const
{
    const glm::mat4 inverse = glm::inverse(viewProjection(size));
    const float x = float(pixel.x()) / float(size.width()) * 2.0f - 1.0f;
    const float y = 1.0f - float(pixel.y()) / float(size.height()) * 2.0f;
    const glm::vec4 nearPoint = inverse * glm::vec4(x, y, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(x, y, 1.0f, 1.0f);
    Ray ray;
    ray.origin = glm::vec3(nearPoint) / nearPoint.w;
    ray.direction = glm::normalize(glm::vec3(farPoint) / farPoint.w - ray.origin);
    return ray;
}

void Camera::orbitBy(float angleDeltaDeg, float elevationDeltaDeg)
{
    angleDeg = std::fmod(angleDeg + angleDeltaDeg, 360.0f);
    if (angleDeg < 0.0f) angleDeg += 360.0f;
    elevationDeg = clampedElevation(elevationDeg + elevationDeltaDeg);
}

void Camera::panBy(QPointF pixelDelta, QSize size)
{
    if (size.height() <= 0) return;
    // World size of one pixel at the target's depth.
    const float viewHeight = orthographicHeight > 0.0f ? orthographicHeight : 2.0f * distance * std::tan(radians(fieldOfViewDeg) * 0.5f);
    const float worldPerPixel = viewHeight / float(size.height());
    target -= right() * float(pixelDelta.x()) * worldPerPixel;
    target += up() * float(pixelDelta.y()) * worldPerPixel;
}

void Camera::zoomBy(float factor)
{
    if (factor <= 0.0f) return;
    distance = std::clamp(distance / factor, kMinCameraDistance, kMaxCameraDistance);
}

} // namespace bunraku::render
