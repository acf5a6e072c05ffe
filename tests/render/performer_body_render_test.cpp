// The performer's body in the view (FigureStyle::Body): one connected silhouette at sampled
// frames of every fixture skeleton family and every Bandai take, seen from the front, the side
// and three quarters, and a click on a limb picks that limb's bone.
#include "analysis/io/bvh_import.h"
#include "render/take_scene.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"
#include "render_test_support.h"

using namespace bunraku;

namespace {

analysis::Take importedTake(const analysis::io::BvhFile& file, const std::string& name)
{
    analysis::io::BvhImportOptions options;
    options.guessUnits = true;
    auto take = analysis::io::bvhToPuppetTake(file, options);
    INFO(name << ": " << (take.ok() ? std::string() : take.error().message));
    REQUIRE(take.ok());
    return std::move(take).value();
}

void requireOneBody(render::OffscreenRenderer& offscreen, const analysis::Take& take, const std::string& name)
{
    render::TakeSceneOptions options;
    options.computeAxes = false;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {take}, options);
    REQUIRE(scene.ok());
    REQUIRE(offscreen.setScene(*scene).ok());
    render::Renderer& renderer = offscreen.renderer();
    render::SceneVisibility visibility;
    visibility.figures = {render::FigureStyle::Body, render::FigureStyle::Body};
    visibility.partner = false;
    renderer.setVisibility(visibility);
    REQUIRE(renderer.skeletonDrawn(0));
    REQUIRE_FALSE(renderer.puppetDrawn(0));
    const int count = 4;
    for (int k = 0; k < count; ++k) {
        const Eigen::Index frame = Eigen::Index(double(k) / (count - 1) * double(take.frameCount() - 1));
        renderer.setFrame(frame);
        for (const float angle : {270.0f, 0.0f, 315.0f}) {
            render::Camera camera = renderer.framingCamera();
            camera.angleDeg = angle;
            const QImage ids = offscreen.partIdImage(camera, QSize(400, 400));
            int pixels = 0;
            const int components = test::silhouetteComponents(ids, [&renderer](QRgb pixel) {
                const auto hit = renderer.decodePartId(pixel);
                return hit && hit->takeSlot == 0 && hit->joint >= 0;
            }, &pixels);
            INFO(name << ", frame " << frame << ", camera angle " << angle << ": " << pixels << " pixels");
            REQUIRE(pixels > 1500);
            REQUIRE(components == 1);
        }
    }
}

} // namespace

TEST_CASE("the performer's body is one connected silhouette for every fixture family", "[render][body]")
{
    auto offscreen = test::makeOffscreenRenderer();
    for (const auto& family : test::bvhFamilies()) {
        auto file = analysis::io::parseBvh(test::fixtureBvh(family, 12), family.id + ".bvh");
        REQUIRE(file.ok());
        requireOneBody(*offscreen, importedTake(*file, family.id), family.id);
    }
}

TEST_CASE("the performer's body is one connected silhouette for every Bandai take", "[render][body]")
{
    auto offscreen = test::makeOffscreenRenderer();
    for (const auto& path : test::bandaiFilesOrSkip()) {
        auto file = analysis::io::readBvh(path);
        REQUIRE(file.ok());
        requireOneBody(*offscreen, importedTake(*file, path.filename().string()), path.filename().string());
    }
}

TEST_CASE("a click on the performer's body picks the bone under it", "[render][body]")
{
    const auto paths = test::bandaiFilesOrSkip();
    if (paths.empty()) return;
    auto file = analysis::io::readBvh(paths.front());
    REQUIRE(file.ok());
    const analysis::Take take = importedTake(*file, paths.front().filename().string());
    auto offscreen = test::makeOffscreenRenderer();
    render::TakeSceneOptions options;
    options.computeAxes = false;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {take}, options);
    REQUIRE(scene.ok());
    render::LayoutOptions layout;
    layout.centreTakes = false;
    REQUIRE(offscreen->setScene(*scene, layout).ok());
    render::Renderer& renderer = offscreen->renderer();
    render::SceneVisibility visibility;
    visibility.figures = {render::FigureStyle::Body, render::FigureStyle::Body};
    visibility.partner = false;
    renderer.setVisibility(visibility);
    renderer.setFrame(0);
    render::Camera camera = renderer.framingCamera();
    camera.angleDeg = 270.0f; // from the front
    const QSize size(500, 500);
    const auto& skeleton = *take.skeleton->skeleton;
    const auto joints = renderer.displayedJointTransforms(0, camera);
    int checked = 0;
    for (const char* name : {"Head", "LowerArm_L", "LowerArm_R", "UpperLeg_L", "LowerLeg_R"}) {
        const int j = skeleton.find(name);
        if (j < 0) continue;
        // The middle of the bone from j to its first child, where the body is the bone's.
        const auto children = skeleton.children(j);
        const glm::vec3 a(joints[std::size_t(j)][3]);
        const glm::vec3 b = children.empty() ? a : glm::vec3(joints[std::size_t(children.front())][3]);
        const glm::vec3 middle = children.empty() ? a : 0.5f * (a + b);
        const QPoint pixel = camera.project(middle, size).pixel.toPoint();
        const auto hit = renderer.pick(camera, size, pixel);
        INFO(name);
        REQUIRE(hit);
        CHECK(hit->takeSlot == 0);
        CHECK(hit->jointName == name);
        ++checked;
    }
    CHECK(checked >= 4);
}
