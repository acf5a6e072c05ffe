// Two takes side by side (thesis Fig. 6.18): the first take's puppet is on the left and the
// second's on the right as seen from the camera, whatever its angle.
#include "render_test_support.h"

using namespace bunraku;

namespace {

struct Silhouette {
    int pixels = 0;
    double meanX = 0.0;
};

/// Pixel count and mean column of each take's puppet in the ID pass.
std::array<Silhouette, 2> silhouettes(render::OffscreenRenderer& offscreen, const render::Camera& camera, QSize size)
{
    std::array<Silhouette, 2> result{};
    const QImage ids = offscreen.partIdImage(camera, size);
    for (int y = 0; y < ids.height(); ++y)
        for (int x = 0; x < ids.width(); ++x)
            if (const auto hit = offscreen.renderer().decodePartId(ids.pixel(x, y))) {
                auto& s = result[std::size_t(hit->takeSlot)];
                s.meanX += x;
                ++s.pixels;
            }
    for (auto& s : result)
        if (s.pixels > 0) s.meanX /= s.pixels;
    return result;
}

} // namespace

TEST_CASE("with two takes the first puppet lands left and the second right at every camera angle",
          "[render][two takes]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    // The second take stands far away from the first in the recording's coordinates: its place
    // on screen must come from the layout, not from its data.
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2, {0, 0, 100}), {}});
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2, {150, 80, 100}), {}});
    REQUIRE(offscreen->setScene(scene).ok());

    const QSize size(640, 360);
    render::Camera camera;
    camera.angleDeg = GENERATE(0.0f, 90.0f, 180.0f, 270.0f);
    camera.elevationDeg = GENERATE(10.0f, 90.0f);
    camera.distance = 320.0f;
    camera.target = {0.0f, 0.0f, 70.0f};
    INFO("angle " << camera.angleDeg << " elevation " << camera.elevationDeg);

    const auto [first, second] = silhouettes(*offscreen, camera, size);
    REQUIRE(first.pixels > 100);
    REQUIRE(second.pixels > 100);
    CHECK(first.meanX < size.width() / 2.0);
    CHECK(second.meanX > size.width() / 2.0);
    // Symmetric about the image centre (both are centred, then shifted by half the separation).
    CHECK(first.meanX + second.meanX == Approx(double(size.width())).margin(12.0));
}

TEST_CASE("each take of two keeps its own motion axis", "[render][two takes]")
{
    auto offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    std::vector<analysis::RigidTransform> axis(2);
    axis[0].translation = Eigen::Vector3d(0, 0, 80);
    axis[1].translation = Eigen::Vector3d(0, 0, 80);
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2), axis});
    scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(2), {}});
    REQUIRE(offscreen->setScene(scene).ok());
    render::Camera camera;
    camera.angleDeg = 200.0f;
    const auto first = offscreen->renderer().displayedAxisTransform(0, camera);
    REQUIRE(first.has_value());
    CHECK_FALSE(offscreen->renderer().displayedAxisTransform(1, camera).has_value());
    // The axis moves with its take's root: half the separation to the screen's left.
    const glm::vec3 origin((*first)[3]);
    const glm::vec3 expected = glm::vec3(0, 0, 80) - camera.right() * (offscreen->renderer().layout().separation / 2.0f);
    CHECK(glm::distance(origin, expected) < 1e-3f);
}

TEST_CASE("a scene replaced for take A keeps what was built for take B and draws what a scene built whole draws",
          "[render][two takes][keep]")
{
    auto offscreen = test::makeOffscreenRenderer();
    const auto body = std::make_shared<const int>(0); // the body's identity, as the caller holds it
    const auto takeB = std::make_shared<const analysis::Take>(test::travellingTake(6, 60.0));
    const auto sceneWith = [&](const std::shared_ptr<const analysis::Take>& takeA, bool sources) {
        render::SceneContent scene;
        scene.body = analysis::defaultBodyDescription();
        scene.bodySource = body;
        for (const auto& take : {takeA, takeB}) {
            render::TakeSlot slot{*take, {}};
            if (sources) slot.sources = {take};
            scene.takes.push_back(std::move(slot));
        }
        return scene;
    };
    const auto firstA = std::make_shared<const analysis::Take>(test::spreadArmsTake(6, {0, 0, 100}));
    REQUIRE(offscreen->setScene(sceneWith(firstA, true)).ok());
    CHECK(offscreen->renderer().slotsBuilt() == 2);
    // Take A replaced (a step of a drag): B is kept.
    const auto nextA = std::make_shared<const analysis::Take>(test::spreadArmsTake(6, {0, 10, 95}));
    REQUIRE(offscreen->setScene(sceneWith(nextA, true)).ok());
    CHECK(offscreen->renderer().slotsBuilt() == 1);
    render::Camera camera;
    camera.angleDeg = 20.0f;
    camera.elevationDeg = 15.0f;
    camera.distance = 400.0f;
    camera.target = {0.0f, 0.0f, 70.0f};
    const QSize size(480, 270);
    auto framesOf = [&] {
        std::vector<QImage> images;
        for (Eigen::Index frame : {0, 5}) {
            offscreen->renderer().setFrame(frame);
            images.push_back(offscreen->render(camera, size));
            images.push_back(offscreen->partIdImage(camera, size));
        }
        return images;
    };
    const std::vector<QImage> kept = framesOf();
    // The same scene built whole (no sources): the same pixels, colours and part IDs.
    REQUIRE(offscreen->setScene(sceneWith(nextA, false)).ok());
    CHECK(offscreen->renderer().slotsBuilt() == 2);
    const std::vector<QImage> whole = framesOf();
    REQUIRE(kept.size() == whole.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        INFO("image " << i);
        CHECK(kept[i] == whole[i]);
    }
    // A scene of another layout, or of another body, builds every slot; the same scene again, none.
    render::LayoutOptions wider;
    wider.separation = 90.0f;
    REQUIRE(offscreen->setScene(sceneWith(nextA, true), wider).ok());
    CHECK(offscreen->renderer().slotsBuilt() == 2);
    REQUIRE(offscreen->setScene(sceneWith(nextA, true), wider).ok());
    CHECK(offscreen->renderer().slotsBuilt() == 0);
    render::SceneContent otherBody = sceneWith(nextA, true);
    otherBody.bodySource = std::make_shared<const int>(1);
    REQUIRE(offscreen->setScene(otherBody, wider).ok());
    CHECK(offscreen->renderer().slotsBuilt() == 2);
}
