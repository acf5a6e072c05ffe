// Picking returns the body part (and take) under a screen point.
#include "render_test_support.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

using namespace bunraku;

namespace {

glm::vec3 toGlm(const Eigen::Vector3d& v) { return {float(v.x()), float(v.y()), float(v.z())}; }

} // namespace

TEST_CASE("picking at a part's projected centre returns that part and the background returns nothing",
          "[render][picking]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2), {}});
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2), {}});
    render::LayoutOptions layout;
    layout.separation = 140.0f;
    REQUIRE(offscreen->setScene(scene, layout).ok());

    const QSize size(800, 450);
    render::Camera camera;
    camera.angleDeg = 270.0f; // from the front
    camera.elevationDeg = 5.0f;
    camera.distance = 330.0f;
    camera.target = {0.0f, 0.0f, 75.0f};

    for (int slot = 0; slot < 2; ++slot) {
        const auto world_T_part = offscreen->renderer().displayedPartTransforms(slot, camera);
        for (std::size_t p = 0; p < scene.body.parts.size(); ++p) {
            // The first primitive's centre, which lies on the part's front face from this camera.
            const auto& primitive = scene.body.parts[p].primitives.front();
            const glm::vec3 centre =
                glm::vec3(world_T_part[p] * glm::vec4(toGlm(primitive.part_T_primitive.translation), 1.0f));
            const QPoint pixel = camera.project(centre, size).pixel.toPoint();
            const auto picked = offscreen->pick(camera, size, pixel);
            INFO("take " << slot << " part " << scene.body.parts[p].name);
            REQUIRE(picked.has_value());
            CHECK(picked->takeSlot == slot);
            CHECK(picked->partName == scene.body.parts[p].name);
            CHECK(picked->partIndex == int(p));
        }
    }
    CHECK_FALSE(offscreen->pick(camera, size, QPoint(5, 5)).has_value());
    CHECK_FALSE(offscreen->pick(camera, size, QPoint(-1, 10)).has_value());

    // A hidden puppet cannot be picked.
    auto visibility = offscreen->renderer().visibility();
    visibility.puppet = false;
    offscreen->renderer().setVisibility(visibility);
    const auto world_T_head = offscreen->renderer().displayedPartTransforms(0, camera)[0];
    const QPoint head = camera.project(glm::vec3(world_T_head[3]), size).pixel.toPoint();
    CHECK_FALSE(offscreen->pick(camera, size, head).has_value());
}

TEST_CASE("picking leaves the caller's framebuffer bound and its image intact", "[render][picking]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2), {}});
    REQUIRE(offscreen->setScene(scene).ok());
    render::Camera camera;
    camera.target = {0.0f, 0.0f, 75.0f};
    const QSize size(320, 240);
    const QImage before = offscreen->render(camera, size);
    (void)offscreen->pick(camera, size, QPoint(160, 120));
    const QImage after = offscreen->render(camera, size);
    CHECK(before == after);
    // And none of it raised an OpenGL error.
    REQUIRE(offscreen->makeCurrent());
    CHECK(QOpenGLContext::currentContext()->functions()->glGetError() == GLenum(GL_NO_ERROR));
}
