// The performer's skeleton in the 3D view: capsules and spheres placed by the joints' world
// poses, shaded like the puppet, picked by bone, drawn per take as puppet, skeleton or both, and
// framed by its own height.
#include "render_test_support.h"

#include "analysis/core/skeleton.h"
#include "render/skeleton_geometry.h"

using namespace bunraku;

namespace {

/// A standing figure `height` cm tall whose hips sway along y over the frames: hips (moving),
/// spine, head (+End Site), a right arm out sideways (shoulder, hand carrying the puppet's
/// "hand"), a leg down to the floor. Joints in the workbench's axes, cm.
std::shared_ptr<const analysis::SkeletalMotion> figure(Eigen::Index frames, double height)
{
    const double s = height / 170.0;
    auto skeleton = std::make_shared<analysis::Skeleton>();
    skeleton->name = "figure";
    using analysis::SkeletonJoint;
    skeleton->joints = {SkeletonJoint{"hips", -1, Eigen::Vector3d(0, 0, 95 * s), {}, false},
                        SkeletonJoint{"spine", 0, Eigen::Vector3d(0, 0, 45 * s), {}, false},
                        SkeletonJoint{"head", 1, Eigen::Vector3d(0, 0, 15 * s), {}, false},
                        SkeletonJoint{"head_End", 2, Eigen::Vector3d(0, 0, 15 * s), {}, true},
                        SkeletonJoint{"shoulder_R", 1, Eigen::Vector3d(0, -20 * s, 0), {}, false},
                        SkeletonJoint{"hand_R", 4, Eigen::Vector3d(0, -55 * s, 0), {}, false},
                        SkeletonJoint{"hand_R_End", 5, Eigen::Vector3d(0, -15 * s, 0), {}, true},
                        SkeletonJoint{"leg_R", 0, Eigen::Vector3d(0, -10 * s, 0), {}, false},
                        SkeletonJoint{"leg_R_End", 7, Eigen::Vector3d(0, 0, -95 * s), {}, true}};
    skeleton->parts = {analysis::PartBinding{"hand", 5, {}}};
    auto motion = std::make_shared<analysis::SkeletalMotion>(analysis::makeRestMotion(skeleton, frames));
    motion->movingJoints = {0};
    motion->movingTranslations.resize(frames, 3);
    for (Eigen::Index f = 0; f < frames; ++f) motion->movingTranslations.row(f) << 0.0, 2.0 * double(f), 95.0 * s;
    return motion;
}

/// The figure with the puppet's channels 90 cm to its left (+y), so neither hides the other.
analysis::Take takeWithFigure(Eigen::Index frames, double height)
{
    analysis::Take take = test::spreadArmsTake(frames, {0, 90, 100});
    take.skeleton = figure(frames, height);
    return take;
}

/// Takes kept where they are (the figure at the origin), the second half the separation right.
render::LayoutOptions uncentred()
{
    render::LayoutOptions layout;
    layout.centreTakes = false;
    layout.separation = 200.0f;
    return layout;
}

render::Camera frontCamera(float distance, float height)
{
    render::Camera camera;
    camera.angleDeg = 270.0f; // from the front (+x looking back)
    camera.elevationDeg = 0.0f;
    camera.distance = distance;
    camera.target = {0.0f, 0.0f, height};
    return camera;
}

glm::vec3 displayedJoint(render::Renderer& renderer, int slot, int joint, const render::Camera& camera)
{
    return glm::vec3(renderer.displayedJointTransforms(slot, camera).at(std::size_t(joint))[3]);
}

void setFigures(render::Renderer& renderer, render::FigureStyle first, render::FigureStyle second = render::FigureStyle::Puppet)
{
    auto visibility = renderer.visibility();
    visibility.figures = {first, second};
    visibility.axis = visibility.partner = visibility.grid = false;
    renderer.setVisibility(visibility);
}

} // namespace

TEST_CASE("a capsule runs from its joint to the bone's end with round caps", "[render][skeleton]")
{
    const render::Mesh capsule = render::capsuleMesh(2.0f, 10.0f, 12, 4);
    float low = 1e9f, high = -1e9f, widest = 0.0f;
    for (const auto& v : capsule.vertices) {
        low = std::min(low, v.position.z);
        high = std::max(high, v.position.z);
        widest = std::max(widest, std::hypot(v.position.x, v.position.y));
        CHECK(std::abs(glm::length(v.normal) - 1.0f) < 1e-5f);
    }
    CHECK(low == Approx(-2.0f).margin(1e-5));
    CHECK(high == Approx(12.0f).margin(1e-5));
    CHECK(widest == Approx(2.0f).margin(1e-5));
}

TEST_CASE("the skeleton is drawn at its joints, picked by bone, and only when its take shows it", "[render][skeleton]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::Renderer& renderer = offscreen->renderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{takeWithFigure(5, 170.0), {}});
    REQUIRE(offscreen->setScene(scene, uncentred()).ok());
    renderer.setFrame(3);
    const QSize size(640, 640);
    const render::Camera camera = frontCamera(420.0f, 90.0f);

    setFigures(renderer, render::FigureStyle::Skeleton);
    CHECK(renderer.skeletonDrawn(0));
    CHECK_FALSE(renderer.puppetDrawn(0));
    // Joint poses: the hips moved 6 cm along y at frame 3 (before centring, which moves the take
    // by its shoulder centre).
    const glm::vec3 hips = displayedJoint(renderer, 0, 0, camera), spine = displayedJoint(renderer, 0, 1, camera);
    CHECK(spine.z - hips.z == Approx(45.0f).margin(1e-4));
    const QImage image = offscreen->render(camera, size);
    const QPointF middle = camera.project(0.5f * (hips + spine), size).pixel; // the hips' bone to the spine
    CHECK_FALSE(test::isBackground(image.pixel(middle.toPoint())));
    // Shaded: the lit capsule is brighter where it faces the camera than at its silhouette.
    const QRgb centre = image.pixel(middle.toPoint());
    int edgeX = int(middle.x());
    while (edgeX < size.width() - 1 && !test::isBackground(image.pixel(edgeX + 1, int(middle.y())))) ++edgeX;
    CHECK(qGray(centre) > qGray(image.pixel(edgeX, int(middle.y()))) + 10);

    const auto picked = offscreen->pick(camera, size, middle.toPoint());
    REQUIRE(picked.has_value());
    CHECK(picked->takeSlot == 0);
    CHECK(picked->joint == 0);
    CHECK(picked->jointName == "hips");
    CHECK(picked->partName.empty()); // the hips carry no puppet part
    // The bone of the joint that carries the puppet's hand picks as that part.
    const glm::vec3 hand = displayedJoint(renderer, 0, 5, camera);
    const glm::vec3 handEnd = glm::vec3(renderer.displayedJointTransforms(0, camera)[6][3]);
    const auto pickedHand = offscreen->pick(camera, size, camera.project(0.5f * (hand + handEnd), size).pixel.toPoint());
    REQUIRE(pickedHand.has_value());
    CHECK(pickedHand->jointName == "hand_R");
    CHECK(pickedHand->partName == "hand");

    // The puppet alone: no bone there, no bone picked.
    setFigures(renderer, render::FigureStyle::Puppet);
    CHECK(test::isBackground(offscreen->render(camera, size).pixel(middle.toPoint())));
    CHECK_FALSE(offscreen->pick(camera, size, middle.toPoint()).has_value());
    // Both: the bone and the puppet's shoulder board.
    setFigures(renderer, render::FigureStyle::PuppetAndSkeleton);
    const QImage both = offscreen->render(camera, size);
    CHECK_FALSE(test::isBackground(both.pixel(middle.toPoint())));
    const glm::vec3 shoulderBoard = glm::vec3(renderer.displayedPartTransforms(0, camera)[1][3]);
    CHECK_FALSE(test::isBackground(both.pixel(camera.project(shoulderBoard, size).pixel.toPoint())));
    // The figure hidden: nothing of it is drawn.
    auto hidden = renderer.visibility();
    hidden.puppet = false;
    renderer.setVisibility(hidden);
    CHECK_FALSE(renderer.skeletonDrawn(0));
    CHECK(test::isBackground(offscreen->render(camera, size).pixel(middle.toPoint())));
}

TEST_CASE("a 170 cm performer and a 1 m figure both fit the framing camera, bones in proportion", "[render][skeleton]")
{
    for (const double height : {170.0, 100.0}) {
        INFO("height " << height);
        auto offscreen = test::makeOffscreenRenderer();
        render::Renderer& renderer = offscreen->renderer();
        render::SceneContent scene;
        scene.body = analysis::defaultBodyDescription();
        scene.takes.push_back(render::TakeSlot{takeWithFigure(2, height), {}});
        REQUIRE(offscreen->setScene(scene, uncentred()).ok());
        setFigures(renderer, render::FigureStyle::Skeleton);
        const QSize size(640, 360);
        const render::Camera camera = renderer.framingCamera();
        // The floor lies under the feet.
        CHECK(renderer.floorHeight() < -0.02f * float(height));
        CHECK(renderer.floorHeight() > -0.05f * float(height) - 2.0f);
        float top = 1e9f, bottom = -1e9f;
        for (const glm::mat4& world_T_joint : renderer.displayedJointTransforms(0, camera)) {
            const auto projected = camera.project(glm::vec3(world_T_joint[3]), size);
            CHECK(QRectF(0, 0, size.width(), size.height()).contains(projected.pixel));
            top = std::min(top, float(projected.pixel.y()));
            bottom = std::max(bottom, float(projected.pixel.y()));
        }
        // Framed by its own height: the figure covers about the same share of the image at either size.
        CHECK((bottom - top) / float(size.height()) > 0.45f);
        CHECK((bottom - top) / float(size.height()) < 0.9f);
        const auto meshes = render::buildSkeletonMeshes(*scene.takes[0].take.skeleton);
        float radius = 0.0f;
        for (const auto& v : meshes[2].vertices) radius = std::max(radius, glm::length(v.position) * float(v.position.z < 0.0f)); // the head: its bone points up
        CHECK(radius == Approx(1.3f * 0.02f * float(height)).epsilon(0.01)); // the joint sphere, sized from the take
    }
}

TEST_CASE("two takes side by side each show their own figure", "[render][skeleton]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::Renderer& renderer = offscreen->renderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{takeWithFigure(2, 170.0), {}});
    scene.takes.push_back(render::TakeSlot{takeWithFigure(2, 170.0), {}});
    REQUIRE(offscreen->setScene(scene, uncentred()).ok());
    setFigures(renderer, render::FigureStyle::Skeleton, render::FigureStyle::Puppet);
    const QSize size(900, 500);
    const render::Camera camera = renderer.framingCamera();
    CHECK(renderer.skeletonDrawn(0));
    CHECK_FALSE(renderer.skeletonDrawn(1));
    for (int slot = 0; slot < 2; ++slot) {
        const glm::vec3 hips = displayedJoint(renderer, slot, 0, camera), spine = displayedJoint(renderer, slot, 1, camera);
        const auto picked = offscreen->pick(camera, size, camera.project(0.5f * (hips + spine), size).pixel.toPoint());
        INFO("slot " << slot);
        if (slot == 0) {
            REQUIRE(picked.has_value());
            CHECK(picked->takeSlot == 0);
            CHECK(picked->jointName == "hips");
        } else {
            CHECK_FALSE((picked.has_value() && picked->joint >= 0));
        }
    }
    // The first take stands to the screen's left of the second.
    CHECK(camera.project(displayedJoint(renderer, 0, 0, camera), size).pixel.x() <
          camera.project(displayedJoint(renderer, 1, 0, camera), size).pixel.x());
}
