// A known pose projects each body part where the pose math says: the part's silhouette in the
// ID pass has the bounding box of its projected vertices, and each primitive's centre shows it.
#include "analysis/body/body_pose.h"
#include "render/mesh_file.h"
#include "render/puppet_geometry.h"
#include "tests/support/test_paths.h"
#include "render_test_support.h"

#include <QRect>

#include <fstream>

using namespace bunraku;

namespace {

render::SceneContent spreadArmsScene()
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(3), {}});
    return scene;
}

/// world_T_part from the take's channels alone: the driving part's pose, mirrored for the left
/// limbs across the shoulder's sagittal plane (thesis 5.2.1, body_pose.h).
analysis::RigidTransform expectedPose(const analysis::BodyDescription& body, const analysis::Take& take, std::size_t part)
{
    const auto& description = body.parts[part];
    const auto column = [&](const std::string& name) {
        for (int p = 0; p < analysis::kPuppetPartCount; ++p)
            if (analysis::kPuppetParts[std::size_t(p)] == name) return Eigen::Index(p * analysis::kDofCount);
        FAIL("no take part " << name);
        return Eigen::Index(0);
    };
    const auto source = analysis::partPose(take, 0, column(description.drivenBy));
    if (!description.mirrored) return source;
    return analysis::mirroredPose(source, analysis::partPose(take, 0, column(body.mirrorFramePart)));
}

} // namespace

TEST_CASE("each part of a known pose covers the bounding box its vertices project to", "[render][puppet]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::LayoutOptions layout;
    layout.centreTakes = false;
    const auto scene = spreadArmsScene();
    REQUIRE(offscreen->setScene(scene, layout).ok());

    const QSize size(640, 480);
    render::Camera camera;
    camera.angleDeg = 270.0f; // from the front
    camera.elevationDeg = GENERATE(8.0f, 30.0f);
    camera.distance = 230.0f;
    camera.target = {0.0f, 0.0f, 75.0f};
    const QImage ids = offscreen->partIdImage(camera, size);
    REQUIRE(ids.size() == size);

    const auto meshes = render::buildPuppetMeshes(scene.body);
    for (std::size_t p = 0; p < scene.body.parts.size(); ++p) {
        INFO("part " << scene.body.parts[p].name << ", camera elevation " << camera.elevationDeg);
        const glm::mat4 world_T_part = render::toMatrix(expectedPose(scene.body, scene.takes[0].take, p));
        // Expected: the projected vertices' bounding box.
        double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
        for (const auto& vertex : meshes[p].vertices) {
            const auto point = camera.project(glm::vec3(world_T_part * glm::vec4(vertex.position, 1.0f)), size);
            left = std::min(left, point.pixel.x());
            right = std::max(right, point.pixel.x());
            top = std::min(top, point.pixel.y());
            bottom = std::max(bottom, point.pixel.y());
        }
        // Drawn: the bounding box of the part's pixels in the ID pass.
        int drawnLeft = size.width(), drawnRight = -1, drawnTop = size.height(), drawnBottom = -1;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                const auto hit = offscreen->renderer().decodePartId(ids.pixel(x, y));
                if (!hit || hit->partIndex != int(p)) continue;
                drawnLeft = std::min(drawnLeft, x);
                drawnRight = std::max(drawnRight, x);
                drawnTop = std::min(drawnTop, y);
                drawnBottom = std::max(drawnBottom, y);
            }
        REQUIRE(drawnRight >= 0);
        // Pixel x covers [x, x + 1): the box's edges agree within 2 pixels.
        CHECK(std::abs(drawnLeft - left) <= 2.0);
        CHECK(std::abs(drawnRight + 1 - right) <= 2.0);
        CHECK(std::abs(drawnTop - top) <= 2.0);
        CHECK(std::abs(drawnBottom + 1 - bottom) <= 2.0);

        // And each primitive's centre shows its part.
        for (const auto& primitive : scene.body.parts[p].primitives) {
            const Eigen::Vector3d centre =
                expectedPose(scene.body, scene.takes[0].take, p).apply(primitive.part_T_primitive.translation);
            const auto point = camera.project(glm::vec3(float(centre.x()), float(centre.y()), float(centre.z())), size);
            INFO("primitive " << primitive.name);
            CHECK(test::anyPixelNear(ids, point.pixel, 1, [&](QRgb pixel) {
                const auto hit = offscreen->renderer().decodePartId(pixel);
                return hit && hit->partIndex == int(p);
            }));
        }
    }
}

TEST_CASE("the renderer places parts by worldPartPoses under the take's root", "[render][puppet]")
{
    auto offscreen = test::makeOffscreenRenderer();
    const auto scene = spreadArmsScene();
    REQUIRE(offscreen->setScene(scene).ok()); // centred: the root moves the take to the origin
    render::Camera camera;
    const auto displayed = offscreen->renderer().displayedPartTransforms(0, camera);
    REQUIRE(displayed.size() == scene.body.parts.size());
    const glm::vec3 centre = render::takeCentre(scene.takes[0].take);
    for (std::size_t p = 0; p < displayed.size(); ++p) {
        const auto pose = expectedPose(scene.body, scene.takes[0].take, p);
        const glm::vec4 origin = displayed[p] * glm::vec4(0, 0, 0, 1);
        CHECK(origin.x == Approx(pose.translation.x() - centre.x).margin(1e-3));
        CHECK(origin.y == Approx(pose.translation.y() - centre.y).margin(1e-3));
        CHECK(origin.z == Approx(pose.translation.z()).margin(1e-3));
    }
}

TEST_CASE("a mesh loaded from a file replaces its part's primitives where the part's pose puts it",
          "[render][puppet][mesh]")
{
    const auto dir = test::scratchDir("render_part_mesh");
    // A cube of edge 2 around (0, 0, 1), scaled by 8 into cm: 16 cm, from z = 0 to 16 above the head sensor.
    std::ofstream(dir / "cube.obj") << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv -1 -1 2\nv 1 -1 2\nv 1 1 2\nv -1 1 2\n"
                                       "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
                                       "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    render::MeshFileOptions options;
    options.scale = 8.0f;
    auto cube = render::loadMeshFile(dir / "cube.obj", options);
    REQUIRE(cube.ok());

    auto scene = spreadArmsScene();
    scene.partMeshes["head"] = *cube;
    auto offscreen = test::makeOffscreenRenderer();
    render::LayoutOptions layout;
    layout.centreTakes = false;
    REQUIRE(offscreen->setScene(scene, layout).ok());

    const QSize size(480, 360);
    render::Camera camera;
    camera.angleDeg = 270.0f;
    camera.elevationDeg = 0.0f;
    camera.distance = 200.0f;
    const auto head = analysis::partPose(scene.takes[0].take, 0, 0);
    // Level with the cube's centre, so that neither its top nor its bottom face shows.
    camera.target = {0.0f, 0.0f, float(head.translation.z()) + 8.0f};
    const QImage ids = offscreen->partIdImage(camera, size);
    // The cube's front face (x = +8 cm) seen head-on: its corners bound the head's pixels.
    const auto corner = [&](double y, double z) {
        const Eigen::Vector3d p = head.apply(Eigen::Vector3d(8.0, y, z));
        return camera.project(glm::vec3(float(p.x()), float(p.y()), float(p.z())), size).pixel;
    };
    const QPointF topLeft = corner(8.0, 16.0);  // +y is the screen's right from the front: left is -y
    const QPointF bottomRight = corner(-8.0, 0.0);
    const double left = std::min(topLeft.x(), bottomRight.x()), right = std::max(topLeft.x(), bottomRight.x());
    const double top = std::min(topLeft.y(), bottomRight.y()), bottom = std::max(topLeft.y(), bottomRight.y());
    int inside = 0, outside = 0;
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            const auto hit = offscreen->renderer().decodePartId(ids.pixel(x, y));
            if (!hit || hit->partName != "head") continue;
            const bool in = x + 0.5 >= left - 1 && x + 0.5 <= right + 1 && y + 0.5 >= top - 1 && y + 0.5 <= bottom + 1;
            (in ? inside : outside) += 1;
        }
    CHECK(outside == 0);
    // The face fills its square (less the rows the shoulder board may hide below it).
    CHECK(inside > 0.9 * (right - left) * (bottom - top));

    scene.partMeshes["tail"] = *cube;
    const auto status = render::validateScene(scene);
    REQUIRE_FALSE(status.ok());
    CHECK(status.error().message.find("tail") != std::string::npos);
}
