// A known pose projects each body part where the pose math says: the part's silhouette in the
// ID pass has the bounding box of its skinned vertices projected, and its frame's origin shows it.
#include "analysis/body/body_pose.h"
#include "analysis/body/puppet_model.h"
#include "render/mesh_file.h"
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

TEST_CASE("each part of a known pose covers the bounding box its skinned vertices project to", "[render][puppet]")
{
    // The modelled puppet is skinned on the GPU (resources/shaders/skinned.vert); the same dual
    // quaternion skinning on the CPU (analysis::skinPuppet) says where each vertex goes. A
    // part's pixels in the ID pass are those of the triangles whose vertices it moves most.
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

    const analysis::PuppetMesh& mesh = analysis::shippedPuppetMesh();
    std::vector<analysis::RigidTransform> parts;
    for (std::size_t p = 0; p < scene.body.parts.size(); ++p) parts.push_back(expectedPose(scene.body, scene.takes[0].take, p));
    const analysis::SkinnedSurface skinned = analysis::skinPuppet(mesh, analysis::puppetJointPoses(mesh, scene.body, parts));
    const auto partOfJoint = analysis::puppetJointPartIndices(scene.body);
    struct Box {
        double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
        void add(double x0, double x1, double y0, double y1)
        {
            left = std::min(left, x0);
            right = std::max(right, x1);
            top = std::min(top, y0);
            bottom = std::max(bottom, y1);
        }
    };
    // Expected: the projected vertices' boxes, per part and whole. A triangle is drawn in the ID
    // pass with the part of its last vertex (OpenGL's provoking vertex): the part's box is that
    // of its triangles.
    std::vector<Box> expected(scene.body.parts.size()), drawn(scene.body.parts.size());
    Box wholeExpected, wholeDrawn;
    std::vector<QPointF> pixels(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const Eigen::Vector3f& q = skinned.positions[v];
        pixels[v] = camera.project(glm::vec3(q.x(), q.y(), q.z()), size).pixel;
        wholeExpected.add(pixels[v].x(), pixels[v].x(), pixels[v].y(), pixels[v].y());
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const int part = partOfJoint[std::size_t(mesh.dominantJoint(mesh.indices[t + 2]))];
        for (int k = 0; k < 3; ++k) {
            const QPointF& pixel = pixels[mesh.indices[t + std::size_t(k)]];
            expected[std::size_t(part)].add(pixel.x(), pixel.x(), pixel.y(), pixel.y());
        }
    }
    // Drawn: the boxes of the parts' pixels in the ID pass (pixel x covers [x, x + 1)).
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            const auto hit = offscreen->renderer().decodePartId(ids.pixel(x, y));
            if (!hit) continue;
            drawn[std::size_t(hit->partIndex)].add(x, x + 1, y, y + 1);
            wholeDrawn.add(x, x + 1, y, y + 1);
        }
    // The whole puppet's silhouette is the box of all its vertices, within 2 pixels.
    CHECK(std::abs(wholeDrawn.left - wholeExpected.left) <= 2.0);
    CHECK(std::abs(wholeDrawn.right - wholeExpected.right) <= 2.0);
    CHECK(std::abs(wholeDrawn.top - wholeExpected.top) <= 2.0);
    CHECK(std::abs(wholeDrawn.bottom - wholeExpected.bottom) <= 2.0);
    for (std::size_t p = 0; p < scene.body.parts.size(); ++p) {
        INFO("part " << scene.body.parts[p].name << ", camera elevation " << camera.elevationDeg);
        // A part's pixels lie inside its triangles' box (the sleeves hide some of the kimono, so
        // not all of it shows).
        REQUIRE(drawn[p].right >= 0.0);
        CHECK(drawn[p].left >= expected[p].left - 2.0);
        CHECK(drawn[p].right <= expected[p].right + 2.0);
        CHECK(drawn[p].top >= expected[p].top - 2.0);
        CHECK(drawn[p].bottom <= expected[p].bottom + 2.0);

        // And the part's own frame (its sensor, inside the part) shows the part.
        const Eigen::Vector3d origin = parts[p].translation;
        const auto point = camera.project(glm::vec3(float(origin.x()), float(origin.y()), float(origin.z())), size);
        CHECK(test::anyPixelNear(ids, point.pixel, 1, [&](QRgb pixel) {
            const auto hit = offscreen->renderer().decodePartId(pixel);
            return hit && hit->partIndex == int(p);
        }));
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
