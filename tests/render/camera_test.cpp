// The camera's geometry: where the eye sits for an angle and elevation, which way the screen's
// right points, and that projection and rays agree.
#include "render/camera.h"

#include <catch2/catch.hpp>

#include <glm/gtc/epsilon.hpp>

using bunraku::render::Camera;
using bunraku::render::CameraPreset;

namespace {
bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-4f)
{
    return glm::all(glm::epsilonEqual(a, b, tolerance));
}
} // namespace

TEST_CASE("angle 0 puts the camera on +y and angles turn counter-clockwise from above", "[camera]")
{
    Camera camera;
    camera.elevationDeg = 0.0f;
    camera.distance = 200.0f;
    CHECK(near(camera.eye(), {0, 200, 0}, 1e-3f));
    camera.angleDeg = 90.0f;
    CHECK(near(camera.eye(), {-200, 0, 0}, 1e-3f));
    camera.angleDeg = 180.0f;
    CHECK(near(camera.eye(), {0, -200, 0}, 1e-3f));
    camera.angleDeg = 270.0f;
    CHECK(near(camera.eye(), {200, 0, 0}, 1e-3f));
}

TEST_CASE("the target projects to the image centre and the screen's right is r(angle)", "[camera]")
{
    const QSize size(640, 480);
    const float angle = GENERATE(0.0f, 37.0f, 90.0f, 200.0f, 270.0f);
    const float elevation = GENERATE(-90.0f, -30.0f, 0.0f, 25.0f, 90.0f);
    Camera camera;
    camera.angleDeg = angle;
    camera.elevationDeg = elevation;
    camera.target = {10.0f, -20.0f, 50.0f};
    const auto centre = camera.project(camera.target, size);
    REQUIRE(centre.inFront);
    CHECK(centre.pixel.x() == Approx(320.0).margin(1e-3));
    CHECK(centre.pixel.y() == Approx(240.0).margin(1e-3));
    // A point to the camera's right lands right of the centre, one above it above the centre.
    const auto right = camera.project(camera.target + camera.right() * 20.0f, size);
    CHECK(right.pixel.x() > 330.0);
    CHECK(right.pixel.y() == Approx(240.0).margin(1e-2));
    const auto up = camera.project(camera.target + camera.up() * 20.0f, size);
    CHECK(up.pixel.y() < 230.0);
    // The screen's right is horizontal at every elevation and orthogonal to the view.
    CHECK(camera.right().z == 0.0f);
    CHECK(std::abs(glm::dot(camera.right(), camera.forward())) < 1e-5f);
}

TEST_CASE("top and bottom presets look straight down and up", "[camera]")
{
    Camera camera;
    camera.angleDeg = 30.0f;
    camera.distance = 300.0f;
    const Camera top = camera.withPreset(CameraPreset::Top);
    CHECK(near(top.eye(), {0, 0, 300}, 1e-3f));
    CHECK(near(top.forward(), {0, 0, -1}));
    const Camera bottom = camera.withPreset(CameraPreset::Bottom);
    CHECK(near(bottom.eye(), {0, 0, -300}, 1e-3f));
    CHECK(near(bottom.right(), camera.right()));
}

TEST_CASE("the ray through a projected point passes through the point", "[camera]")
{
    const QSize size(800, 600);
    Camera camera;
    camera.angleDeg = 123.0f;
    camera.elevationDeg = 17.0f;
    const glm::vec3 point(31.0f, -12.0f, 64.0f);
    const auto projected = camera.project(point, size);
    const auto ray = camera.rayThrough(projected.pixel, size);
    const glm::vec3 toPoint = point - ray.origin;
    const glm::vec3 closest = ray.origin + ray.direction * glm::dot(toPoint, ray.direction);
    CHECK(glm::distance(closest, point) < 0.05f);
}

TEST_CASE("panning keeps the target under the mouse and zooming changes the distance", "[camera]")
{
    const QSize size(640, 480);
    Camera camera;
    camera.angleDeg = 45.0f;
    camera.elevationDeg = 20.0f;
    const glm::vec3 anchor = camera.target;
    camera.panBy(QPointF(40.0, -25.0), size);
    const auto moved = camera.project(anchor, size);
    CHECK(moved.pixel.x() == Approx(360.0).margin(0.5));
    CHECK(moved.pixel.y() == Approx(215.0).margin(0.5));
    const float distance = camera.distance;
    camera.zoomBy(2.0f);
    CHECK(camera.distance == Approx(distance / 2.0f));
    camera.orbitBy(0.0f, 500.0f);
    CHECK(camera.elevationDeg == 90.0f);
}

TEST_CASE("an orthographic camera maps its height to the image at every depth", "[camera]")
{
    Camera camera;
    camera.angleDeg = 270.0f; // on +x, looking along -x
    camera.elevationDeg = 0.0f;
    camera.distance = 500.0f;
    camera.target = {0.0f, 0.0f, 100.0f};
    camera.orthographicHeight = 200.0f;
    const QSize size(400, 400);
    // 1 cm = 2 px, whatever the depth; the target at the centre.
    for (const float depth : {-80.0f, 0.0f, 150.0f}) {
        const auto centre = camera.project({depth, 0.0f, 100.0f}, size);
        CHECK(centre.pixel.x() == Approx(200.0).margin(1e-3));
        CHECK(centre.pixel.y() == Approx(200.0).margin(1e-3));
        const auto high = camera.project({depth, 0.0f, 150.0f}, size);
        CHECK(high.pixel.y() == Approx(100.0).margin(1e-3));
        const auto right = camera.project({depth, 50.0f, 100.0f}, size); // the screen's right is +y here
        CHECK(right.pixel.x() == Approx(300.0).margin(1e-3));
    }
    // Rays are parallel, along the view.
    const auto ray = camera.rayThrough(QPointF(20.0, 380.0), size);
    CHECK(near(ray.direction, camera.forward()));
    // Dragging 100 px to the right moves the target 50 cm to the screen's left.
    camera.panBy(QPointF(100.0, 0.0), size);
    CHECK(near(camera.target, {0.0f, -50.0f, 100.0f}, 1e-3f));
}
