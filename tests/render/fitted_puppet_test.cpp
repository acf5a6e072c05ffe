// A BVH take is drawn with the puppet fitted to its performer: in the ID pass the arm and hand
// parts cover their bones (forearm, hand) on every fixture family and every Bandai file.
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_anatomy.h"
#include "analysis/io/bvh_import.h"
#include "render/take_scene.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"
#include "tests/support/shared_data.h"
#include "render_test_support.h"

using namespace bunraku;

namespace {

struct NamedTake {
    std::string name;
    analysis::Take take;
    analysis::BodySide side = analysis::BodySide::Right;
};

NamedTake imported(const analysis::io::BvhFile& file, const std::string& name, analysis::BodySide side)
{
    analysis::io::BvhImportOptions options;
    options.guessUnits = true;
    options.side = side;
    auto take = analysis::io::bvhToPuppetTake(file, options);
    INFO(name << ": " << (take.ok() ? std::string() : take.error().message));
    REQUIRE(take.ok());
    return {name, std::move(take).value(), side};
}

/// The fraction of points spread over the middle 60 % of the segment a-b whose pixel (or a
/// neighbour within 2 px) shows body part `part` of take slot 0.
double coverage(const render::Renderer& renderer, const QImage& ids, const render::Camera& camera, const Eigen::Vector3d& a,
                const Eigen::Vector3d& b, int part)
{
    int covered = 0;
    constexpr int samples = 13;
    for (int k = 0; k < samples; ++k) {
        const Eigen::Vector3d p = a + (0.2 + 0.6 * double(k) / (samples - 1)) * (b - a);
        const auto screen = camera.project(glm::vec3(float(p.x()), float(p.y()), float(p.z())), ids.size());
        if (test::anyPixelNear(ids, screen.pixel, 2, [&](QRgb pixel) {
                const auto hit = renderer.decodePartId(pixel);
                return hit && hit->takeSlot == 0 && hit->partIndex == part;
            }))
            ++covered;
    }
    return double(covered) / samples;
}

void checkArmAndHandOnTheirBones(const NamedTake& named)
{
    INFO(named.name << ", " << analysis::bodySideName(named.side) << " side");
    auto offscreen = test::makeOffscreenRenderer();
    render::TakeSceneOptions sceneOptions;
    sceneOptions.computeAxes = false;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {named.take}, sceneOptions);
    INFO((scene.ok() ? std::string() : scene.error().message));
    REQUIRE(scene.ok());
    REQUIRE(scene->takes.front().body); // drawn with its own, fitted body
    render::LayoutOptions layout;
    layout.centreTakes = false;
    REQUIRE(offscreen->setScene(*scene, layout).ok());

    const auto& skeleton = *named.take.skeleton->skeleton;
    analysis::PartJoints joints{};
    for (std::size_t p = 0; p < 4; ++p) joints[p] = skeleton.binding(analysis::kPuppetParts[p])->joint;
    const auto landmarks = analysis::findLandmarks(*named.take.skeleton, joints, 0);
    REQUIRE(landmarks.ok());
    // From the front, 45 degrees towards the side of the bound arm, level with the elbow.
    render::Camera camera;
    camera.angleDeg = named.side == analysis::BodySide::Right ? 225.0f : 315.0f;
    camera.elevationDeg = 10.0f;
    camera.distance = 300.0f;
    camera.target = {float(landmarks->chest.x()), float(landmarks->chest.y()), float(landmarks->elbow.z())};
    const QImage ids = offscreen->partIdImage(camera, QSize(640, 480));
    const auto& body = scene->takes.front().body;
    const int arm = body->partIndex("right_arm");
    const int hand = body->partIndex("right_hand");
    CHECK(coverage(offscreen->renderer(), ids, camera, landmarks->elbow, landmarks->wrist, arm) >= 0.75);
    CHECK(coverage(offscreen->renderer(), ids, camera, landmarks->wrist, landmarks->fingerTip, hand) >= 0.75);
    // The head is drawn around the head joint, the torso between the neck and the hips.
    CHECK(coverage(offscreen->renderer(), ids, camera, landmarks->neck, landmarks->headTop, body->partIndex("head")) >= 0.75);
    CHECK(coverage(offscreen->renderer(), ids, camera, landmarks->neckBase, landmarks->hips, body->partIndex("shoulder")) >= 0.75);
}

} // namespace

TEST_CASE("arm and hand of the fitted puppet sit on their bones for every fixture family", "[render][skeleton]")
{
    for (const auto& family : test::bvhFamilies()) {
        for (const auto side : {analysis::BodySide::Right, analysis::BodySide::Left}) {
            auto file = analysis::io::parseBvh(test::fixtureBvh(family, 12, side == analysis::BodySide::Left), family.id + ".bvh");
            REQUIRE(file.ok());
            checkArmAndHandOnTheirBones(imported(*file, family.id, side));
        }
    }
}

TEST_CASE("arm and hand of the fitted puppet sit on their bones for every bandai file", "[render][skeleton]")
{
    for (const auto& path : test::bandaiFilesOrSkip()) {
        auto file = analysis::io::readBvh(path);
        REQUIRE(file.ok());
        checkArmAndHandOnTheirBones(imported(*file, path.filename().string(), analysis::BodySide::Right));
    }
}

TEST_CASE("two fitted Bandai puppets side by side stand apart on the screen", "[render][skeleton]")
{
    const auto normal = test::bandaiDir() / "bye_normal_001.bvh";
    const auto angry = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(normal) && std::filesystem::exists(angry))) return;
    std::vector<analysis::Take> takes;
    for (const auto& path : {normal, angry}) {
        auto file = analysis::io::readBvh(path);
        REQUIRE(file.ok());
        takes.push_back(imported(*file, path.filename().string(), analysis::BodySide::Right).take);
    }
    auto offscreen = test::makeOffscreenRenderer();
    render::TakeSceneOptions sceneOptions;
    sceneOptions.computeAxes = false;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), takes, sceneOptions);
    REQUIRE(scene.ok());
    REQUIRE(offscreen->setScene(*scene, render::LayoutOptions{}).ok());
    render::Renderer& renderer = offscreen->renderer();
    const render::Camera camera = renderer.framingCamera();
    // Puppets fitted to the performers are taller than the shipped one: they stand further apart
    // than its 70 cm (65 cm here before: the angry wave's arm reached into the normal take).
    const glm::vec3 apart = glm::vec3(renderer.takeRoot(1, camera)[3] - renderer.takeRoot(0, camera)[3]);
    CHECK(glm::dot(apart, camera.right()) > 80.0f);
    for (const double seconds : {0.0, 0.8, 1.5, 2.2, 3.0}) {
        INFO("at " << seconds << " s");
        renderer.setTime(seconds);
        const QImage ids = offscreen->partIdImage(camera, QSize(960, 540));
        int rightmostA = -1;
        int leftmostB = ids.width();
        for (int y = 0; y < ids.height(); ++y)
            for (int x = 0; x < ids.width(); ++x) {
                const auto hit = renderer.decodePartId(ids.pixel(x, y));
                if (!hit || hit->partIndex < 0) continue;
                if (hit->takeSlot == 0) rightmostA = std::max(rightmostA, x);
                if (hit->takeSlot == 1) leftmostB = std::min(leftmostB, x);
            }
        REQUIRE(rightmostA >= 0);
        REQUIRE(leftmostB < ids.width());
        CHECK(rightmostA < leftmostB);
    }
}
