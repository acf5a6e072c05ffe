// The scene's objects appear where they should and disappear when hidden: motion axis bars in
// their colours at the centre of mass, orbits through the sensors' positions, the grid and the
// partner marker.
#include "render_test_support.h"

#include <glm/gtc/constants.hpp>

using namespace bunraku;

namespace {

constexpr Eigen::Index kFrames = 40;

/// Every sensor circles its own centre (radius 12 cm, one turn over the take) in a horizontal plane.
analysis::Take circlingTake()
{
    return test::puppetTake(kFrames, [](Eigen::Index f) {
        const double a = 2.0 * glm::pi<double>() * double(f) / double(kFrames);
        const double c = 12.0 * std::cos(a), s = 12.0 * std::sin(a);
        return std::array<test::PartPose, 4>{test::PartPose{c, s, 110.0, 0, 0, 0},
                                             test::PartPose{c * 0.5, s * 0.5, 100.0, 0, 0, 0},
                                             test::PartPose{c, -15.0 + s, 90.0, 0, 0, -90.0},
                                             test::PartPose{30.0 + c, -40.0 + s, 80.0, 0, 0, -90.0}};
    });
}

/// The motion axis per frame: centre of mass at (5, -3, 75) + frame * 0.5 cm along x, turned
/// 30 deg about z.
std::vector<analysis::RigidTransform> axisPoses()
{
    std::vector<analysis::RigidTransform> poses;
    for (Eigen::Index f = 0; f < kFrames; ++f) {
        analysis::RigidTransform pose;
        pose.rotation = analysis::rotationFromYawPitchRoll({30.0, 0.0, 0.0});
        pose.translation = Eigen::Vector3d(5.0 + 0.5 * double(f), -3.0, 75.0);
        poses.push_back(pose);
    }
    return poses;
}

struct Fixture {
    std::unique_ptr<render::OffscreenRenderer> offscreen = test::makeOffscreenRenderer();
    render::SceneContent scene;
    render::LayoutOptions layout;
    render::Camera camera;
    QSize size{640, 480};

    Fixture()
    {
        scene.body = analysis::defaultBodyDescription();
        scene.takes.push_back(render::TakeSlot{circlingTake(), axisPoses()});
        layout.centreTakes = false;
        REQUIRE(offscreen->setScene(scene, layout).ok());
        camera.angleDeg = 300.0f;
        camera.elevationDeg = 35.0f;
        camera.distance = 240.0f;
        camera.target = {0.0f, 0.0f, 70.0f};
    }
    void show(bool puppet, bool axis, bool orbits, bool grid, bool partner)
    {
        render::SceneVisibility visibility;
        visibility.puppet = puppet;
        visibility.axis = axis;
        visibility.orbits = orbits;
        visibility.grid = grid;
        visibility.partner = partner;
        offscreen->renderer().setVisibility(visibility);
    }
    QImage image() { return offscreen->render(camera, size); }
};

bool dominant(QRgb pixel, int channel)
{
    const int v[3] = {qRed(pixel), qGreen(pixel), qBlue(pixel)};
    const int other1 = v[(channel + 1) % 3], other2 = v[(channel + 2) % 3];
    return v[channel] > 60 && v[channel] > 2 * other1 && v[channel] > 2 * other2;
}

} // namespace

TEST_CASE("the axis bars show red, green and blue along the axis from the projected centre of mass",
          "[render][axis]")
{
    Fixture fixture;
    fixture.show(true, true, false, true, false);
    const Eigen::Index frame = GENERATE(Eigen::Index(0), Eigen::Index(25));
    fixture.offscreen->makeCurrent();
    fixture.offscreen->renderer().setFrame(frame);
    const QImage image = fixture.image();
    const auto pose = axisPoses()[std::size_t(frame)];
    const glm::mat4 world_T_axis = render::toMatrix(pose);
    for (int axis = 0; axis < 3; ++axis) {
        INFO("axis " << axis << " frame " << frame);
        glm::vec4 along(0, 0, 0, 1);
        along[axis] = fixture.layout.axisBarLength * 0.6f;
        const auto point = fixture.camera.project(glm::vec3(world_T_axis * along), fixture.size);
        CHECK(test::anyPixelNear(image, point.pixel, 1, [axis](QRgb p) { return dominant(p, axis); }));
        // The bars start at the centre of mass: each colour is within a few pixels of it.
        const auto com = fixture.camera.project(glm::vec3(world_T_axis * glm::vec4(0, 0, 0, 1)), fixture.size);
        CHECK(test::anyPixelNear(image, com.pixel, 4, [axis](QRgb p) { return dominant(p, axis); }));
    }

    // Hidden, the axis leaves no green or blue anywhere (the puppet has neither), and the red
    // bar's pixels change back to what lies behind it.
    fixture.show(true, false, false, true, false);
    const QImage without = fixture.image();
    for (int axis = 1; axis < 3; ++axis) CHECK(test::countPixels(without, [axis](QRgb p) { return dominant(p, axis); }) == 0);
    glm::vec4 alongX(fixture.layout.axisBarLength * 0.6f, 0, 0, 1);
    const QPoint red = fixture.camera.project(glm::vec3(world_T_axis * alongX), fixture.size).pixel.toPoint();
    CHECK(without.pixel(red) != image.pixel(red));
}

TEST_CASE("orbits pass through the projected sensor positions of every frame", "[render][orbits]")
{
    Fixture fixture;
    fixture.show(false, false, true, false, false); // orbits are drawn when the puppet is hidden
    const QImage image = fixture.image();
    const auto& take = fixture.scene.takes[0].take;
    for (Eigen::Index f = 0; f < kFrames; f += 3) {
        for (int part = 0; part < 4; ++part) {
            const glm::vec3 sensor(float(take.values(f, part * 6)), float(take.values(f, part * 6 + 1)),
                                   float(take.values(f, part * 6 + 2)));
            const auto point = fixture.camera.project(sensor, fixture.size);
            INFO("frame " << f << " sensor " << part);
            CHECK(test::anyPixelNear(image, point.pixel, 1, [](QRgb p) { return !test::isBackground(p); }));
        }
    }
    // Between the circles there is nothing: the centre of the hand's circle is background.
    const auto centre = fixture.camera.project({30.0f, -40.0f, 80.0f}, fixture.size);
    CHECK(test::isBackground(image.pixel(centre.pixel.toPoint())));

    // With the puppet shown, orbits follow the thesis and disappear, unless asked for always.
    fixture.show(true, false, false, false, false);
    const QImage puppetOnly = fixture.image();
    fixture.show(true, false, true, false, false);
    CHECK(fixture.image() == puppetOnly);
    auto visibility = fixture.offscreen->renderer().visibility();
    visibility.orbitVisibility = render::OrbitVisibility::Always;
    fixture.offscreen->renderer().setVisibility(visibility);
    const QImage always = fixture.image();
    int changed = 0;
    for (int y = 0; y < always.height(); ++y)
        for (int x = 0; x < always.width(); ++x) changed += always.pixel(x, y) != puppetOnly.pixel(x, y) ? 1 : 0;
    CHECK(changed > 100);
}

TEST_CASE("the moving point on each orbit sits at the current frame's sensor position", "[render][orbits]")
{
    Fixture fixture;
    fixture.show(false, false, true, false, false);
    const Eigen::Index frame = 7;
    fixture.offscreen->makeCurrent();
    fixture.offscreen->renderer().setTime(double(frame) / fixture.scene.takes[0].take.rateHz);
    REQUIRE(fixture.offscreen->renderer().frame(0) == frame);
    const QImage image = fixture.image();
    const auto& take = fixture.scene.takes[0].take;
    for (int part = 0; part < 4; ++part) {
        const glm::vec3 sensor(float(take.values(frame, part * 6)), float(take.values(frame, part * 6 + 1)),
                               float(take.values(frame, part * 6 + 2)));
        const auto point = fixture.camera.project(sensor, fixture.size);
        // The point is a sphere several pixels wide: the whole neighbourhood is covered.
        int covered = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                covered += test::isBackground(image.pixel(point.pixel.toPoint() + QPoint(dx, dy))) ? 0 : 1;
        INFO("sensor " << part);
        CHECK(covered == 9);
    }
}

TEST_CASE("each object alone draws pixels and hiding it removes them", "[render][visibility]")
{
    Fixture fixture;
    const auto nonBackground = [](const QImage& image) {
        return test::countPixels(image, [](QRgb p) { return !test::isBackground(p); });
    };
    fixture.show(false, false, false, false, false);
    CHECK(nonBackground(fixture.image()) == 0);
    for (int object = 0; object < 5; ++object) {
        INFO("object " << object << " (puppet, axis, orbits, grid, partner)");
        fixture.show(object == 0, object == 1, object == 2, object == 3, object == 4);
        CHECK(nonBackground(fixture.image()) > 50);
    }
    // The grid lies on the floor under the puppet: the projected floor point under the origin
    // is on the grid's centre line.
    fixture.show(false, false, false, true, false);
    const auto floor = fixture.camera.project({0.0f, 0.0f, fixture.offscreen->renderer().floorHeight()}, fixture.size);
    CHECK(test::anyPixelNear(fixture.image(), floor.pixel, 1, [](QRgb p) { return !test::isBackground(p); }));
}
