// The puppet dressed in its simulated kimono in the 3D view (issue "The kimono", item 2): the
// cloth replaces the skinned skirt and sleeves, the figure stays one silhouette, a frame shows
// the same cloth however it is reached, and a kimono simulated for another take or body is not
// drawn (the skinned kimono is).
#include "analysis/body/body_description.h"
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"
#include "render/take_scene.h"
#include "tests/analysis/axis/puppet_fixture.h"
#include "tests/support/bandai_files.h"
#include "render_test_support.h"

#include <memory>
#include <vector>

using namespace bunraku;

namespace {

std::shared_ptr<const analysis::KimonoSimulation> simulate(const analysis::Take& take, const analysis::BodyDescription& body)
{
    auto simulation = analysis::simulateKimono(take, body);
    INFO((simulation.ok() ? std::string() : simulation.error().message));
    REQUIRE(simulation.ok());
    return std::make_shared<const analysis::KimonoSimulation>(std::move(simulation).value());
}

render::SceneContent dressedScene(const analysis::Take& take, std::shared_ptr<const analysis::KimonoSimulation> kimono)
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    render::TakeSlot slot;
    slot.take = take;
    slot.kimono = std::move(kimono);
    scene.takes.push_back(std::move(slot));
    return scene;
}

/// The figure's pieces in an ID image: 8-connected components of take A's part pixels, not
/// counting specks of one or two pixels (a single-layer cloth seen edge on rasterises into
/// pixels with gaps between them: the sleeve's lowest corner, 2026-11-29, one pixel at a Bandai
/// frame), whose number goes to `specks`.
int silhouette(const render::Renderer& renderer, const QImage& ids, int* pixels, int* specks)
{
    const auto inside = [&renderer](QRgb pixel) {
        const auto hit = renderer.decodePartId(pixel);
        return hit && hit->takeSlot == 0 && hit->partIndex >= 0;
    };
    const int all = test::silhouetteComponents(ids, inside, pixels);
    // The pieces: components of the figure's pixels whose 3 x 3 neighbourhood holds at least 3
    // of its pixels (a one-pixel-wide bridge still joins; an isolated pixel or pair does not).
    QImage solid(ids.size(), QImage::Format_RGB32);
    solid.fill(Qt::black);
    for (int y = 0; y < ids.height(); ++y)
        for (int x = 0; x < ids.width(); ++x) {
            if (!inside(ids.pixel(x, y))) continue;
            int around = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (ids.valid(x + dx, y + dy) && inside(ids.pixel(x + dx, y + dy))) ++around;
            if (around >= 3) solid.setPixel(x, y, qRgb(255, 255, 255));
        }
    const int pieces = test::silhouetteComponents(solid, [](QRgb pixel) { return qRed(pixel) == 255; });
    *specks = all - pieces;
    return pieces;
}

void requireDressedSilhouettes(render::OffscreenRenderer& offscreen, const render::SceneContent& scene, const std::string& name)
{
    REQUIRE(offscreen.setScene(scene).ok());
    render::Renderer& renderer = offscreen.renderer();
    const Eigen::Index frames = scene.takes.front().take.frameCount();
    for (int k = 0; k < 4; ++k) {
        const Eigen::Index frame = Eigen::Index(double(k) / 3.0 * double(frames - 1));
        renderer.setFrame(frame);
        REQUIRE(renderer.clothDrawn(0));
        for (const float angle : {270.0f, 0.0f}) {
            render::Camera camera = renderer.framingCamera();
            camera.angleDeg = angle;
            int pixels = 0, specks = 0;
            const int components = silhouette(renderer, offscreen.partIdImage(camera, QSize(400, 400)), &pixels, &specks);
            INFO(name << ", frame " << frame << ", camera angle " << angle << ": " << pixels << " pixels, " << specks << " specks");
            CHECK(specks <= 2);
            REQUIRE(pixels > 2000);
            CHECK(components == 1);
        }
    }
}

} // namespace

TEST_CASE("the puppet dressed in its simulated kimono is one silhouette on demo takes and a Bandai take", "[render][kimono]")
{
    auto offscreen = test::makeOffscreenRenderer();
    const analysis::synth::DemoCorpus demo = analysis::synth::generateDemoCorpus();
    for (const std::size_t t : {std::size_t(0), demo.corpus.takes.size() / 2}) {
        const analysis::Take& take = demo.corpus.takes[t];
        requireDressedSilhouettes(*offscreen, dressedScene(take, simulate(take, analysis::defaultBodyDescription())), take.displayName());
    }
    const auto path = test::bandaiDir() / "bye_normal_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(path))) return;
    auto take = analysis::io::readTakeFile(path);
    REQUIRE(take.ok());
    render::TakeSceneOptions options;
    options.computeAxes = false;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {*take}, options);
    REQUIRE(scene.ok());
    REQUIRE(scene->takes.front().body);
    scene->takes.front().kimono = simulate(*take, *scene->takes.front().body); // on the puppet fitted to the performer
    requireDressedSilhouettes(*offscreen, *scene, path.filename().string());
}

TEST_CASE("playing jumping and scrubbing to a frame draw the same cloth", "[render][kimono]")
{
    analysis::Take take = test::livelyTake(106);
    take.rateHz = 30.0;
    const auto kimono = simulate(take, analysis::defaultBodyDescription());
    auto offscreen = test::makeOffscreenRenderer();
    REQUIRE(offscreen->setScene(dressedScene(take, kimono)).ok());
    render::Renderer& renderer = offscreen->renderer();
    render::Camera camera = renderer.framingCamera();
    camera.angleDeg = 300.0f;
    const QSize size(360, 360);
    const auto at = [&](std::vector<Eigen::Index> path) {
        for (const Eigen::Index frame : path) renderer.setFrame(frame);
        REQUIRE(renderer.clothDrawn(0));
        return offscreen->render(camera, size);
    };
    std::vector<Eigen::Index> playing;
    for (Eigen::Index f = 0; f <= 47; ++f) playing.push_back(f);
    const QImage played = at(playing);
    const QImage jumped = at({100, 47});
    const QImage scrubbed = at({60, 55, 50, 49, 48, 47});
    CHECK(played == jumped);
    CHECK(played == scrubbed);
    // A take too long to keep every frame's cloth: the view steps it on from the checkpoints
    // (the same simulation without its stored frames) and draws the same pixels.
    auto unstored = std::make_shared<analysis::KimonoSimulation>(*kimono);
    unstored->particleFrames.clear();
    REQUIRE(unstored->storedFrame(47) == nullptr);
    REQUIRE(offscreen->setScene(dressedScene(take, unstored)).ok());
    CHECK(at(playing) == played);
    CHECK(at({100, 47}) == played);
    CHECK(at({60, 55, 50, 49, 48, 47}) == played);
    // The cloth is what differs from the skinned kimono at that frame.
    REQUIRE(offscreen->setScene(dressedScene(take, nullptr)).ok());
    renderer.setFrame(47);
    CHECK_FALSE(renderer.clothDrawn(0));
    const QImage skinned = offscreen->render(camera, size);
    int differing = 0;
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) differing += played.pixel(x, y) != skinned.pixel(x, y) ? 1 : 0;
    INFO(differing << " pixels differ between the cloth and the skinned kimono");
    CHECK(differing > 500);
}

TEST_CASE("a kimono simulated for another take or another body is not drawn", "[render][kimono]")
{
    analysis::Take take = test::livelyTake(60);
    take.rateHz = 30.0;
    analysis::Take shorter = test::livelyTake(50);
    shorter.rateHz = 30.0;
    auto offscreen = test::makeOffscreenRenderer();
    REQUIRE(offscreen->setScene(dressedScene(take, simulate(shorter, analysis::defaultBodyDescription()))).ok());
    offscreen->renderer().setFrame(10);
    CHECK_FALSE(offscreen->renderer().clothDrawn(0));
    analysis::BodyDescription stretched = analysis::defaultBodyDescription();
    stretched.parts[std::size_t(stretched.partIndex("shoulder"))].fit = Eigen::Affine3d(Eigen::Scaling(1.1));
    REQUIRE(offscreen->setScene(dressedScene(take, simulate(take, stretched))).ok());
    offscreen->renderer().setFrame(10);
    CHECK_FALSE(offscreen->renderer().clothDrawn(0));
    REQUIRE(offscreen->setScene(dressedScene(take, simulate(take, analysis::defaultBodyDescription()))).ok());
    offscreen->renderer().setFrame(10);
    CHECK(offscreen->renderer().clothDrawn(0));
}
