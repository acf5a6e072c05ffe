#pragma once
/// Camera framing for the 3D view (Frame All, Frame Selected, Reset Camera, and the automatic
/// framing of a take of another size): boxes around what the scene draws, and cameras that fit
/// a box into a view of a given size. The renderer measures the box (Renderer::displayedBounds)
/// from whatever it draws - puppets, skeletons, orbits, the partner marker - so framing never
/// depends on what a figure is made of.

#include "render/camera.h"

#include <glm/glm.hpp>

#include <QSize>

#include <string>

namespace bunraku::render {

/// An axis-aligned box in world coordinates (cm); empty until a point is added.
struct Bounds {
    glm::vec3 lower{0.0f};
    glm::vec3 upper{0.0f};
    bool valid = false;

    void add(const glm::vec3& point);
    void add(const Bounds& other);
    bool empty() const { return !valid; }
    glm::vec3 centre() const { return 0.5f * (lower + upper); }
    glm::vec3 size() const { return valid ? upper - lower : glm::vec3(0.0f); }
    /// The longest side (cm), 0 when empty.
    float extent() const;
};

/// Over which frames a box is measured.
enum class FramingSpan {
    WholeTake,    ///< every frame of every take (a walking take frames its whole path)
    CurrentFrame, ///< the frame shown now
};

/// What to measure: every take shown or one, and everything drawn or one part.
struct BoundsQuery {
    FramingSpan span = FramingSpan::WholeTake;
    int takeSlot = -1; ///< -1: every take in the scene
    /// A take part ("hand": the body parts it drives) or a body part name; empty: everything.
    std::string part;
    /// The figures only (puppets, skeletons, orbits): not the partner marker beside them.
    bool figuresOnly = false;
    /// WholeTake: at most this many frames of each take are posed (evenly spaced, the last one
    /// included).
    int sampledFrames = 120;
};

/// The camera looking the way `view` looks (angle, elevation, field of view kept) at the centre
/// of `bounds`, as close as possible with all of the box's corners inside a view of `size`
/// pixels, leaving `margin` (a fraction of the half-width and half-height, e.g. 0.1) free on
/// every side. Distances stay within the camera's zoom limits [kMinDistance, kMaxDistance].
/// An empty box returns `view` unchanged.
Camera framedCamera(const Camera& view, const Bounds& bounds, QSize size, float margin = 0.1f);

/// The view Reset Camera returns to: angle 340 deg (the figure's left front), elevation 15 deg,
/// field of view 35 deg, framing `bounds` in a view of `size`.
Camera resetCamera(const Bounds& bounds, QSize size);

/// Follow (the 3D view's Follow, `bunraku render --follow`): the camera carried along the floor
/// so that it looks at the middle of `figures` (the figures' box at the frame shown) - target x
/// and y from the box; its height, angle, elevation, distance and field of view kept, so a walk
/// stays in frame at the size it was framed. An empty box returns `camera` unchanged.
Camera followingCamera(const Camera& camera, const Bounds& figures);

/// True when two boxes differ enough that a camera framed for one does not suit the other: the
/// longest side changed by more than `ratio` (either way), or the centre moved by more than
/// (ratio - 1) times the larger longest side. A take of another performer's size or one that
/// walks elsewhere differs; the same take recomputed (a drag step) does not.
bool boundsDiffer(const Bounds& a, const Bounds& b, float ratio = 1.3f);

} // namespace bunraku::render
