// The lit stage: the key light's box holds what casts and receives, the floor under a figure is
// darker than the floor away from it (a shadow, where the light's direction puts it, whatever the
// camera), and the partner is a figure as tall as the take's, facing it.
#include "render_test_support.h"

#include "render/shadow_map.h"

#include <glm/gtc/matrix_transform.hpp>

using namespace bunraku;

namespace {

bool insideClip(const glm::mat4& clip_T_world, const glm::vec3& world)
{
    const glm::vec4 clip = clip_T_world * glm::vec4(world, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f && std::abs(ndc.z) <= 1.0f;
}

int luminance(QRgb pixel) { return (qRed(pixel) * 30 + qGreen(pixel) * 59 + qBlue(pixel) * 11) / 100; }

struct Stage {
    std::unique_ptr<render::OffscreenRenderer> offscreen = test::makeOffscreenRenderer();
    render::Camera camera;
    QSize size{640, 480};

    Stage()
    {
        render::SceneContent scene;
        scene.body = analysis::defaultBodyDescription();
        scene.takes.push_back(render::TakeSlot{test::spreadArmsTake(4), {}});
        REQUIRE(offscreen->setScene(scene).ok());
        camera.elevationDeg = 70.0f;
        camera.distance = 330.0f;
        camera.target = {0.0f, 0.0f, 40.0f};
    }
    void show(bool shadows, bool partner = false)
    {
        render::SceneVisibility visibility;
        visibility.axis = visibility.orbits = false;
        visibility.partner = partner;
        visibility.shadows = shadows;
        offscreen->renderer().setVisibility(visibility);
    }
    QImage image() { return offscreen->render(camera, size); }
    QImage ids() { return offscreen->renderer().partIdImage(camera, size); }
    /// Where the key light's ray through the shoulder board's sensor meets the floor.
    glm::vec3 shadowOfShoulder() const
    {
        const auto& body = offscreen->renderer();
        const glm::vec3 shoulder = body.displayedSensorPositions(0, body.frame(0), camera)[1];
        const glm::vec3 light = render::keyLightDirection();
        const float floor = body.floorHeight();
        return shoulder - light * ((shoulder.z - floor) / light.z);
    }
};

} // namespace

TEST_CASE("the key light's box holds the figures and the floor under them", "[render][shadow]")
{
    render::Bounds figures;
    figures.add(glm::vec3(-30.0f, -45.0f, 20.0f));
    figures.add(glm::vec3(25.0f, 45.0f, 130.0f));
    const glm::vec3 light = render::keyLightDirection();
    CHECK(glm::length(light) == Approx(1.0f));
    CHECK(light.z > 0.5f); // above the figures
    const glm::mat4 box = render::shadowViewProjection(figures, 18.0f, light, 2048);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 point((corner & 1) ? figures.upper.x : figures.lower.x, (corner & 2) ? figures.upper.y : figures.lower.y,
                              (corner & 4) ? figures.upper.z : figures.lower.z);
        INFO("corner " << corner);
        CHECK(insideClip(box, point));
        CHECK(insideClip(box, glm::vec3(point.x, point.y, 18.0f))); // the floor under it
    }
    // The shadow of the highest corner falls inside the box too (far down the light's ray).
    const glm::vec3 top = figures.upper;
    CHECK(insideClip(box, top - light * ((top.z - 18.0f) / light.z)));
    // The light looks down its direction: a point nearer the light is nearer in depth.
    const glm::vec4 low = box * glm::vec4(0.0f, 0.0f, 60.0f, 1.0f);
    const glm::vec4 high = box * glm::vec4(glm::vec3(0.0f, 0.0f, 60.0f) + 20.0f * light, 1.0f);
    CHECK(high.z / high.w < low.z / low.w);

    // A box moved by a fraction of a texel keeps its texels where they were: the shadow's edge
    // does not shimmer under a walking take.
    render::Bounds nudged = figures;
    nudged.lower += glm::vec3(0.01f, 0.0f, 0.0f);
    nudged.upper += glm::vec3(0.01f, 0.0f, 0.0f);
    const glm::mat4 moved = render::shadowViewProjection(nudged, 18.0f, light, 2048);
    for (const glm::vec3 point : {glm::vec3(0.0f), glm::vec3(10.0f, -20.0f, 50.0f)}) {
        const glm::vec4 a = box * glm::vec4(point, 1.0f), b = moved * glm::vec4(point, 1.0f);
        const float texel = 2.0f / 2048.0f;
        const float dx = (a.x - b.x) / texel, dy = (a.y - b.y) / texel;
        CHECK(std::abs(dx - std::round(dx)) < 1e-2f);
        CHECK(std::abs(dy - std::round(dy)) < 1e-2f);
    }
    CHECK(render::shadowViewProjection(render::Bounds{}, 0.0f, light, 2048) == glm::mat4(1.0f));
}

TEST_CASE("the floor under a figure is darker than the floor away from it", "[render][shadow]")
{
    Stage stage;
    stage.offscreen->makeCurrent();
    const float angle = GENERATE(170.0f, 200.0f, 230.0f);
    stage.camera.angleDeg = angle;
    INFO("camera angle " << angle);
    const glm::vec3 shadow = stage.shadowOfShoulder();
    const glm::vec3 shoulder = stage.offscreen->renderer().displayedSensorPositions(0, 0, stage.camera)[1];
    // The floor as far from the figure on the light's side: lit.
    const glm::vec3 lit(2.0f * shoulder.x - shadow.x, 2.0f * shoulder.y - shadow.y, shadow.z);
    const QPoint shadowPixel = stage.camera.project(shadow, stage.size).pixel.toPoint();
    const QPoint litPixel = stage.camera.project(lit, stage.size).pixel.toPoint();
    stage.show(true);
    const QImage ids = stage.ids();
    REQUIRE(QRect(QPoint(0, 0), stage.size).contains(shadowPixel));
    REQUIRE(QRect(QPoint(0, 0), stage.size).contains(litPixel));
    // Both points are floor, not figure, in this view.
    REQUIRE(qRed(ids.pixel(shadowPixel)) == 0);
    REQUIRE(qRed(ids.pixel(litPixel)) == 0);
    const QImage with = stage.image();
    // A draft frame (a moving view) has the shadow too, with the cheaper filter.
    stage.offscreen->renderer().setDraft(true);
    const QImage draft = stage.image();
    stage.offscreen->renderer().setDraft(false);
    stage.show(false);
    const QImage without = stage.image();
    CHECK(luminance(draft.pixel(shadowPixel)) < luminance(without.pixel(shadowPixel)) - 40);
    CHECK(std::abs(luminance(draft.pixel(litPixel)) - luminance(without.pixel(litPixel))) <= 2);
    INFO("shadow pixel " << shadowPixel.x() << "," << shadowPixel.y() << ": " << luminance(with.pixel(shadowPixel)) << " with shadows, "
                         << luminance(without.pixel(shadowPixel)) << " without; lit pixel " << luminance(with.pixel(litPixel)) << " / "
                         << luminance(without.pixel(litPixel)));
    CHECK(luminance(with.pixel(shadowPixel)) < luminance(without.pixel(shadowPixel)) - 40);
    CHECK(luminance(with.pixel(shadowPixel)) < luminance(with.pixel(litPixel)) - 40);
    CHECK(std::abs(luminance(with.pixel(litPixel)) - luminance(without.pixel(litPixel))) <= 2);
    // Shadows only darken, and only the floor: every pixel is the same or darker, the figure's
    // pixels unchanged.
    int darker = 0, lighter = 0, figureChanged = 0;
    for (int y = 0; y < stage.size.height(); ++y)
        for (int x = 0; x < stage.size.width(); ++x) {
            const int a = luminance(with.pixel(x, y)), b = luminance(without.pixel(x, y));
            lighter += a > b + 1 ? 1 : 0;
            figureChanged += qRed(ids.pixel(x, y)) != 0 && with.pixel(x, y) != without.pixel(x, y) ? 1 : 0;
            darker += a < b - 10 ? 1 : 0;
        }
    CHECK(lighter == 0);
    CHECK(figureChanged == 0);
    CHECK(darker > 400);
}

TEST_CASE("the shadow follows the figure from frame to frame and stays while the camera turns", "[render][shadow]")
{
    // The puppet of spreadArmsTake steps 60 cm to its right (-y) at frame 1.
    const analysis::Take still = test::spreadArmsTake(2);
    analysis::Take take = still;
    for (int p = 0; p < 4; ++p) take.values(1, p * 6 + 1) -= 60.0;
    Stage stage;
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{take, {}});
    render::LayoutOptions layout;
    layout.centreTakes = false;
    stage.offscreen->makeCurrent();
    REQUIRE(stage.offscreen->setScene(scene, layout).ok());
    stage.camera.angleDeg = 200.0f;
    stage.camera.target = {0.0f, -30.0f, 40.0f};
    stage.show(true);
    const auto luminanceAt = [&](const glm::vec3& world) {
        return luminance(stage.image().pixel(stage.camera.project(world, stage.size).pixel.toPoint()));
    };
    const glm::vec3 first = stage.shadowOfShoulder();
    const int litFloor = luminanceAt(first + glm::vec3(0.0f, 100.0f, 0.0f));
    CHECK(luminanceAt(first) < litFloor - 40);
    stage.offscreen->renderer().setFrame(1);
    const glm::vec3 second = stage.shadowOfShoulder();
    REQUIRE(glm::length(second - first) > 50.0f);
    CHECK(luminanceAt(second) < litFloor - 40);
    CHECK(luminanceAt(first) >= litFloor - 2); // the floor the figure left is lit again
    // Turning the camera around a still frame keeps the shadow where the light puts it.
    for (const float angle : {150.0f, 240.0f}) {
        stage.camera.angleDeg = angle;
        INFO("camera angle " << angle);
        CHECK(luminanceAt(second) < litFloor - 40);
    }
}

TEST_CASE("the partner is a figure as tall as the take's standing in front of it", "[render][partner]")
{
    Stage stage;
    stage.offscreen->makeCurrent();
    stage.camera.angleDeg = 340.0f;
    stage.camera.elevationDeg = 15.0f;
    stage.show(true, true);
    render::Renderer& renderer = stage.offscreen->renderer();
    render::BoundsQuery current;
    current.span = render::FramingSpan::CurrentFrame;
    render::BoundsQuery figuresOnly = current;
    figuresOnly.figuresOnly = true;
    const render::Bounds figure = renderer.displayedBounds(stage.camera, figuresOnly);
    const render::Bounds all = renderer.displayedBounds(stage.camera, current);
    // The partner stands 110 cm ahead (+x) of the take's centre, on the same floor, as tall.
    const float partnerDistance = render::LayoutOptions{}.partnerDistance;
    CHECK(all.upper.x > figure.upper.x + 0.5f * partnerDistance);
    CHECK(all.upper.z == Approx(figure.upper.z).margin(1.0));
    CHECK(all.lower.z == Approx(figure.lower.z).margin(1.0));
    // Drawn: pixels beyond the figure towards +x that the cone never covered, lit as a body.
    const QImage image = stage.image();
    const glm::vec3 partnerChest(figure.centre().x + partnerDistance, figure.centre().y, figure.lower.z + 0.75f * figure.size().z);
    const QPoint chest = stage.camera.project(partnerChest, stage.size).pixel.toPoint();
    CHECK_FALSE(test::isBackground(image.pixel(chest)));
    stage.show(true, false);
    CHECK(test::isBackground(stage.image().pixel(chest)));
}

TEST_CASE("a take that travels 4 m stays on the floor and its partner out of its way", "[render][partner][travel]")
{
    Stage stage;
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    scene.takes.push_back(render::TakeSlot{test::travellingTake(60, 400.0), {}});
    stage.offscreen->makeCurrent();
    REQUIRE(stage.offscreen->setScene(scene).ok());
    stage.show(true, true);
    render::Renderer& renderer = stage.offscreen->renderer();
    // The floor holds the walk before it fades (at 55 % of its half extent).
    render::BoundsQuery whole;
    whole.figuresOnly = true;
    const render::Bounds walk = renderer.displayedBounds(renderer.framingCamera(), whole);
    CHECK(walk.size().x > 400.0f);
    CHECK(0.55f * renderer.floorHalfExtent() >= std::max(std::abs(walk.lower.x), std::abs(walk.upper.x)));
    CHECK(renderer.floorHalfExtent() <= 5000.0f);
    // The partner stands beyond the walk's end (+x), not in the walker's path.
    render::BoundsQuery withPartner;
    const render::Bounds all = renderer.displayedBounds(renderer.framingCamera(), withPartner);
    CHECK(all.upper.x >= walk.upper.x + 60.0f);
    // At the last frame the floor under the figure is floor (lit, not faded into the background).
    renderer.setFrame(59);
    stage.camera = renderer.framingCamera();
    stage.camera.elevationDeg = 40.0f;
    stage.camera.distance = 700.0f;
    stage.camera.target = {0.0f, 0.0f, 60.0f};
    const QImage image = stage.image();
    const glm::vec3 shoulder = renderer.displayedSensorPositions(0, 59, stage.camera)[1];
    const glm::vec3 behind(shoulder.x - 40.0f, shoulder.y + 30.0f, renderer.floorHeight());
    const QPoint pixel = stage.camera.project(behind, stage.size).pixel.toPoint();
    REQUIRE(QRect(QPoint(0, 0), stage.size).contains(pixel));
    CHECK_FALSE(test::isBackground(image.pixel(pixel)));
}
