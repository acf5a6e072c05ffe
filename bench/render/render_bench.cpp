// Frame time of the 3D view: two puppets of the demo corpus (the modelled, skinned puppet) with their motion axes and orbits
// at 1280x720, offscreen (Xvfb + llvmpipe). Each iteration advances the frame (CPU poses and
// uniforms only) and draws; glFinish makes the GPU's work part of the time. Per-frame times are
// collected so the median and 95th percentile can be reported (target: 60 fps = 16.7 ms).
#include "analysis/body/puppet_model.h"
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/synth/demo_corpus.h"
#include "render/offscreen_renderer.h"
#include "render/take_scene.h"

#include <benchmark/benchmark.h>

#include <QGuiApplication>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

using namespace bunraku;

namespace {

struct Stage {
    std::unique_ptr<render::OffscreenRenderer> offscreen;
    render::SceneContent scene;
};

/// The renderers outlive no QGuiApplication: main() frees them before it returns. The last
/// index: the puppets dressed in their simulated kimonos (1) or not (0).
std::unique_ptr<Stage> g_stages[3][2][2];

Stage& stage(int takes, int multisampled = 1, int kimono = 0)
{
    auto& slot = g_stages[takes][multisampled][kimono];
    if (!slot) {
        slot = std::make_unique<Stage>();
        const auto demo = analysis::synth::generateDemoCorpus();
        std::vector<analysis::Take> chosen{*demo.corpus.find("greeting", "none", 1)};
        if (takes > 1) chosen.push_back(*demo.corpus.find("greeting", "friendly", 1));
        slot->scene = render::makeTakeScene(analysis::defaultBodyDescription(), chosen).value();
        if (kimono)
            for (auto& shown : slot->scene.takes)
                shown.kimono = std::make_shared<const analysis::KimonoSimulation>(
                    analysis::simulateKimono(shown.take, shown.body ? *shown.body : slot->scene.body).value());
        auto created = render::OffscreenRenderer::create(render::OffscreenOptions{multisampled != 0 ? 4 : 0});
        if (!created.ok()) {
            std::fprintf(stderr, "bench_render: %s\n", created.error().message.c_str());
            std::exit(1);
        }
        slot->offscreen = std::move(created).value();
        if (!slot->offscreen->setScene(slot->scene).ok()) std::exit(1);
        render::SceneVisibility all;
        all.orbitVisibility = render::OrbitVisibility::Always;
        slot->offscreen->renderer().setVisibility(all);
    }
    return *slot;
}

void reportPercentiles(benchmark::State& state, std::vector<double>& milliseconds)
{
    if (milliseconds.empty()) return;
    std::sort(milliseconds.begin(), milliseconds.end());
    const auto at = [&](double q) { return milliseconds[std::size_t(q * double(milliseconds.size() - 1))]; };
    state.counters["median_ms"] = at(0.5);
    state.counters["p95_ms"] = at(0.95);
    state.counters["fps_median"] = 1000.0 / at(0.5);
}

/// Frame time of a full scene (puppets, axes, orbits, floor, shadows, partner) at WxH; the
/// fourth argument says what of the lit stage is drawn: 1 the shadows, 2 the partners, 3 both
/// (0: the scene before the lit stage).
void drawFrames(benchmark::State& state, int takes, int kimono = 0)
{
    Stage& s = stage(takes, int(state.range(2)), kimono);
    const QSize size(int(state.range(0)), int(state.range(1)));
    render::SceneVisibility visibility = s.offscreen->renderer().visibility();
    visibility.shadows = (state.range(3) & 1) != 0;
    visibility.partner = (state.range(3) & 2) != 0;
    s.offscreen->renderer().setVisibility(visibility);
    render::Camera camera;
    camera.angleDeg = 300.0f;
    camera.elevationDeg = 15.0f;
    camera.distance = 300.0f;
    camera.target = {0.0f, 0.0f, 60.0f};
    const Eigen::Index frames = s.scene.takes.front().take.frameCount();
    std::vector<double> milliseconds;
    Eigen::Index frame = 0;
    s.offscreen->draw(camera, size); // allocate the framebuffer outside the timing
    s.offscreen->finish();
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        s.offscreen->makeCurrent();
        s.offscreen->renderer().setFrame(frame);
        camera.angleDeg += 0.5f; // the camera moves too: the take roots follow the screen's right
        s.offscreen->draw(camera, size);
        s.offscreen->finish();
        milliseconds.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        frame = (frame + 1) % frames;
    }
    reportPercentiles(state, milliseconds);
}

void BM_TwoPuppetsAxesOrbits(benchmark::State& state) { drawFrames(state, 2); }
/// The same two puppets playing, each dressed in its simulated kimono (issue "The kimono": the
/// cloth of each frame stepped on by its player, its positions and normals sent to the GPU).
void BM_TwoKimonosAxesOrbits(benchmark::State& state) { drawFrames(state, 2, 1); }

/// The floor under every frame time: clearing and finishing an empty frame (everything hidden).
void BM_EmptyFrame(benchmark::State& state)
{
    Stage& s = stage(2, 0);
    const render::SceneVisibility shown = s.offscreen->renderer().visibility();
    render::SceneVisibility none;
    none.puppet = none.axis = none.orbits = none.grid = none.partner = false;
    s.offscreen->renderer().setVisibility(none);
    const QSize size(1280, 720);
    render::Camera camera;
    for (auto _ : state) {
        s.offscreen->draw(camera, size);
        s.offscreen->finish();
    }
    s.offscreen->renderer().setVisibility(shown);
}
void BM_OnePuppetAxisOrbits(benchmark::State& state) { drawFrames(state, 1); }

/// The CPU side of a frame alone: poses of both takes (worldPartPoses).
void BM_SetFrameTwoTakes(benchmark::State& state)
{
    Stage& s = stage(2);
    const Eigen::Index frames = s.scene.takes.front().take.frameCount();
    Eigen::Index frame = 0;
    for (auto _ : state) {
        s.offscreen->renderer().setFrame(frame);
        frame = (frame + 1) % frames;
    }
}

/// Picking: an ID pass and a one-pixel read back.
void BM_PickTwoPuppets(benchmark::State& state)
{
    Stage& s = stage(2);
    const QSize size(1280, 720);
    render::Camera camera;
    camera.target = {0.0f, 0.0f, 60.0f};
    camera.distance = 300.0f;
    for (auto _ : state) benchmark::DoNotOptimize(s.offscreen->pick(camera, size, QPoint(640, 360)));
}

/// A screenshot: draw and read back into a QImage (what `bunraku render` does per frame).
void BM_ScreenshotTwoPuppets(benchmark::State& state)
{
    Stage& s = stage(2);
    const QSize size(1280, 720);
    render::Camera camera;
    camera.target = {0.0f, 0.0f, 60.0f};
    camera.distance = 300.0f;
    for (auto _ : state) benchmark::DoNotOptimize(s.offscreen->render(camera, size));
}

/// Generating the modelled puppet (analysis/body/puppet_model.h): the signed distance field
/// polygonised by surface nets at the shipped 0.5 cm cells, weights and materials; what the
/// first scene of a process pays once (shippedPuppetMesh caches it). Argument: threads.
void BM_GeneratePuppetMesh(benchmark::State& state)
{
    analysis::PuppetMeshOptions options;
    options.threads = int(state.range(0));
    std::size_t triangles = 0;
    for (auto _ : state) {
        const analysis::PuppetMesh mesh = analysis::generatePuppetMesh(options);
        triangles = mesh.triangleCount();
        benchmark::DoNotOptimize(triangles);
    }
    state.counters["triangles"] = double(triangles);
}

/// The puppet fitted to a performer's proportions (each vertex mapped by its parts' fits): once
/// per take with a skeleton shown.
void BM_FitPuppetMesh(benchmark::State& state)
{
    analysis::BodyDescription body = analysis::defaultBodyDescription();
    for (auto& part : body.parts) part.fit.linear() *= 1.3;
    const analysis::PuppetMesh& shipped = analysis::shippedPuppetMesh();
    for (auto _ : state) benchmark::DoNotOptimize(analysis::fittedPuppetMesh(shipped, body));
}

/// A scene replaced because take A changed (a step of a drag) beside a long take B, 20,000
/// frames (the demo take repeated): argument 1, B's slot kept (render::TakeSlot::sources: its
/// posed take, binding, orbits and bounds are those of the scene before); 0, every slot built.
void BM_SceneReplacedBesideLongTake(benchmark::State& state)
{
    auto created = render::OffscreenRenderer::create(render::OffscreenOptions{0});
    if (!created.ok()) {
        state.SkipWithError(created.error().message.c_str());
        return;
    }
    auto offscreen = std::move(created).value();
    const auto demo = analysis::synth::generateDemoCorpus();
    const analysis::Take& short1 = *demo.corpus.find("greeting", "none", 1);
    analysis::Take longTake = *demo.corpus.find("greeting", "friendly", 1);
    const Eigen::MatrixXd once = longTake.values;
    longTake.values.resize(20000, once.cols());
    for (Eigen::Index f = 0; f < longTake.values.rows(); ++f) longTake.values.row(f) = once.row(f % once.rows());
    const auto takeB = std::make_shared<const analysis::Take>(longTake);
    const std::shared_ptr<const void> body(&analysis::defaultBodyDescription(), [](const void*) {});
    std::shared_ptr<const analysis::Take> takesA[2] = {std::make_shared<const analysis::Take>(short1),
                                                       std::make_shared<const analysis::Take>(*demo.corpus.find("greeting", "hostile", 1))};
    const bool keep = state.range(0) != 0;
    int step = 0, built = 0;
    for (auto _ : state) {
        render::SceneContent scene;
        scene.body = analysis::defaultBodyDescription();
        scene.bodySource = body;
        const auto& takeA = takesA[step++ % 2];
        scene.takes.push_back(render::TakeSlot{*takeA, {}});
        scene.takes.push_back(render::TakeSlot{*takeB, {}});
        if (keep) {
            scene.takes[0].sources = {takeA};
            scene.takes[1].sources = {takeB};
        }
        if (!offscreen->setScene(scene).ok()) state.SkipWithError("setScene failed");
        built += offscreen->renderer().slotsBuilt();
    }
    state.counters["slots_built"] = double(built) / double(state.iterations());
    offscreen.reset();
}

} // namespace

BENCHMARK(BM_SceneReplacedBesideLongTake)->ArgName("keep")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeneratePuppetMesh)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_FitPuppetMesh)->Unit(benchmark::kMillisecond);
// Arguments: width, height, multisampling (0 = none, 1 = 4x), lit stage (1 shadows + 2 partners).
BENCHMARK(BM_TwoPuppetsAxesOrbits)
    ->ArgNames({"w", "h", "msaa4", "lit"})
    ->Args({1280, 720, 0, 3})
    ->Args({1280, 720, 0, 1})
    ->Args({1280, 720, 0, 2})
    ->Args({1280, 720, 0, 0})
    ->Args({1280, 720, 1, 3})
    ->Args({1280, 720, 1, 0})
    ->Args({640, 360, 1, 3})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(300);
BENCHMARK(BM_TwoKimonosAxesOrbits)
    ->ArgNames({"w", "h", "msaa4", "lit"})
    ->Args({1280, 720, 0, 3})
    ->Args({1280, 720, 0, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(300);
BENCHMARK(BM_OnePuppetAxisOrbits)->ArgNames({"w", "h", "msaa4", "lit"})->Args({1280, 720, 0, 3})->Unit(benchmark::kMillisecond)->Iterations(300);
BENCHMARK(BM_EmptyFrame)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SetFrameTwoTakes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PickTwoPuppets)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScreenshotTwoPuppets)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv)
{
    QGuiApplication application(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    for (auto& row : g_stages)
        for (auto& pair : row)
            for (auto& stageSlot : pair) stageSlot.reset();
    return 0;
}
