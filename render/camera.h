#pragma once
/// The viewer's camera (thesis 6: a camera on a circle around the origin at an angle, 0 deg on
/// +y, or straight above / below, with a light at the camera). World frame: z up, cm.
///
/// The eye sits at target + distance * (cos(elevation) * h(angle) + sin(elevation) * z) with the
/// horizontal direction h(angle) = (-sin(angle), cos(angle), 0): angle 0 puts the camera on +y
/// looking towards -y, angles grow counter-clockwise seen from above. The screen's right is
/// r(angle) = (-cos(angle), -sin(angle), 0) at every elevation, so top and bottom views keep the
/// orientation of the orbit they came from.

#include <glm/glm.hpp>

#include <QPoint>
#include <QPointF>
#include <QSize>

namespace bunraku::render {

/// The distances (cm) a camera may zoom between.
inline constexpr float kMinCameraDistance = 10.0f;
inline constexpr float kMaxCameraDistance = 5000.0f;

enum class CameraPreset {
    Top,    ///< straight above, looking down
    Bottom, ///< straight below, looking up
};

/// A ray in world coordinates (cm).
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< unit
};

/// A point projected to the screen: pixels from the top-left corner, and whether it lies in
/// front of the camera.
struct ScreenPoint {
    QPointF pixel;
    float depth = 0.0f; ///< normalised device depth in [-1, 1]
    bool inFront = false;
};

struct Camera {
    float angleDeg = 0.0f;       ///< around z, 0 = on +y, counter-clockwise from above
    float elevationDeg = 15.0f;  ///< above the horizontal, clamped to [-90, 90]
    float distance = 260.0f;     ///< cm from the target
    glm::vec3 target{0.0f, 0.0f, 0.0f}; ///< the point looked at (the origin until panned)
    float fieldOfViewDeg = 35.0f; ///< vertical
    /// 0: a perspective camera (fieldOfViewDeg); > 0: orthographic, the view's height (cm) at
    /// every depth (tests comparing with another renderer's orthographic camera, e.g. Blender's).
    float orthographicHeight = 0.0f;

    /// The same camera moved to a preset (angle, distance and target kept).
    Camera withPreset(CameraPreset preset) const;

    glm::vec3 eye() const;
    /// Screen right, horizontal, unit (see the file comment).
    glm::vec3 right() const;
    /// Screen up, unit, orthogonal to right and to the viewing direction.
    glm::vec3 up() const;
    /// Unit vector from the eye towards the target.
    glm::vec3 forward() const;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    /// projection(aspect of size) * view().
    glm::mat4 viewProjection(QSize size) const;

    /// Where a world point (cm) lands in an image of `size` pixels.
    ScreenPoint project(const glm::vec3& world, QSize size) const;
    /// The ray from the eye through a pixel (from the top-left corner) of an image of `size`.
    Ray rayThrough(QPointF pixel, QSize size) const;

    /// Mouse interaction: turn by degrees (elevation clamped), pan by pixels of an image of
    /// `size` (the target moves in the screen plane so the scene follows the mouse), zoom by a
    /// factor (> 1 moves closer).
    void orbitBy(float angleDeltaDeg, float elevationDeltaDeg);
    void panBy(QPointF pixelDelta, QSize size);
    void zoomBy(float factor);
};

} // namespace bunraku::render
