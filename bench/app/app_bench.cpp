// Benchmarks of the workbench's interactive paths, on the demo corpus:
// - cursor-only update of 48 graphs (two takes side by side): setCursorTime + a synchronous
//   repaint of the plot (target < 4 ms per frame), against a full replot of the same graphs;
// - one playback frame of the whole window with two puppets and 48 graphs;
// - a warp control-point drag step to the designed take shown in the graphs and the 3D view
//   (target < 16 ms; counters: every step changed the take, 3D frames drawn per step);
// - the 3D view alone: a moving frame, a still (multisampled) frame, a replaced scene;
// - the drag step and the playback frame with a Bandai take's 22-joint skeleton shown as take B
//   beside the puppet (issue 12 point 5), against the same take B shown as a puppet.
#include "bench/app/bench_window.h"
#include "app/analysis_controller.h"
#include "app/design_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/viewport_panel.h"

#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"
#include "widgets/viewport_widget.h"

#include "analysis/body/body_description.h"
#include "analysis/io/corpus_builder.h"
#include "analysis/io/corpus_io.h"

#include <benchmark/benchmark.h>
#include <qcustomplot.h>

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>

using namespace bunraku;

namespace {

std::unique_ptr<app::MainWindow> g_window;

/// Waits until no background recomputation (normalisation, decomposition, design, motion axes)
/// is pending or running: a job still running when a drag starts is made stale by every step
/// and reruns, so it would load the CPU for the whole measurement.
void waitIdle(app::MainWindow& main)
{
    (void)QTest::qWaitFor([&] { return !main.analysis().scheduler().busy(); }, 120000);
    QTest::qWait(200);
}

app::MainWindow& window()
{
    if (!g_window) g_window = [] {
        auto made = bench::shownDemoWindow();
        made->document().selectTake(app::TakeSlot::B, app::TakeId::corpus(7));
        made->graphPanel()->setTwoTakeMode(widgets::TwoTakeMode::SideBySide);
        (void)QTest::qWaitFor([&] { return made->design().ready(); }, 60000);
        waitIdle(*made);
        return made;
    }();
    return *g_window;
}

/// 48 graphs of two demo takes side by side in a window of their own (no OpenGL widget in it:
/// Qt composes a window holding a QOpenGLWidget through OpenGL, which under Xvfb is Mesa's
/// software rasteriser and then costs more than the graphs themselves).
std::unique_ptr<widgets::GraphGrid> g_grid;

widgets::GraphGrid& standaloneGrid()
{
    if (!g_grid) g_grid = [] {
        auto made = std::make_unique<widgets::GraphGrid>();
        const auto& document = window().document();
        made->setTakes(document.take(app::TakeId::corpus(0)), document.take(app::TakeId::corpus(7)));
        made->setTwoTakeMode(widgets::TwoTakeMode::SideBySide);
        made->resize(1200, 900);
        made->show();
        (void)QTest::qWaitForWindowExposed(made.get());
        made->plot()->replot();
        QCoreApplication::processEvents();
        return made;
    }();
    return *g_grid;
}

void cursorOnly48GraphsStandalone(benchmark::State& state)
{
    auto& grid = standaloneGrid();
    double t = 0.0;
    for (auto _ : state) {
        t = t > 19.0 ? 0.0 : t + 0.2;
        grid.setCursorTime(t);
        grid.plot()->repaint();
    }
    state.counters["graphs"] = grid.graphCount();
}
BENCHMARK(cursorOnly48GraphsStandalone)->Unit(benchmark::kMillisecond);

void fullReplot48GraphsStandalone(benchmark::State& state)
{
    auto& grid = standaloneGrid();
    for (auto _ : state) grid.plot()->replot(QCustomPlot::rpImmediateRefresh);
    state.counters["graphs"] = grid.graphCount();
}
BENCHMARK(fullReplot48GraphsStandalone)->Unit(benchmark::kMillisecond);

void cursorOnly48Graphs(benchmark::State& state)
{
    auto* grid = window().graphPanel()->grid();
    double t = 0.0;
    for (auto _ : state) {
        t = t > 19.0 ? 0.0 : t + 0.2;
        grid->setCursorTime(t);
        grid->plot()->repaint();
    }
    state.counters["graphs"] = grid->graphCount();
}
BENCHMARK(cursorOnly48Graphs)->Unit(benchmark::kMillisecond);

void fullReplot48Graphs(benchmark::State& state)
{
    auto* grid = window().graphPanel()->grid();
    for (auto _ : state) {
        grid->plot()->replot(QCustomPlot::rpImmediateRefresh);
    }
    state.counters["graphs"] = grid->graphCount();
}
BENCHMARK(fullReplot48Graphs)->Unit(benchmark::kMillisecond);

/// The 3D view alone in its own window, 420 x 900 (about its dock in the window), two puppets;
/// one per multisampling count (4: the workbench's view, 0: none).
std::map<int, std::unique_ptr<widgets::ViewportWidget>> g_views;

render::SceneContent demoScene()
{
    render::SceneContent scene;
    scene.body = analysis::defaultBodyDescription();
    const auto& document = window().document();
    for (std::size_t index : {0, 7}) scene.takes.push_back(render::TakeSlot{*document.take(app::TakeId::corpus(index)), {}});
    return scene;
}

widgets::ViewportWidget& standaloneView(int samples)
{
    auto& view = g_views[samples];
    if (!view) view = [samples] {
        auto made = std::make_unique<widgets::ViewportWidget>(nullptr, samples);
        made->setScene(demoScene());
        made->resize(420, 900);
        made->show();
        (void)QTest::qWaitForWindowExposed(made.get());
        made->repaint();
        return made;
    }();
    return *view;
}

/// One frame of the 3D view while it moves (frames back to back, as in playback or a drag): pose
/// at a new time, draw (without multisampling: a moving frame), read back and paint.
/// Argument: the view's samples.
void viewFrame(benchmark::State& state)
{
    auto& view = standaloneView(int(state.range(0)));
    double t = 0.0;
    const int before = view.renderedFrameCount();
    for (auto _ : state) {
        t = t > 19.0 ? 0.0 : t + 0.2;
        view.setTime(t);
        view.repaint();
    }
    state.counters["rendered"] = double(view.renderedFrameCount() - before) / double(state.iterations());
}
BENCHMARK(viewFrame)->Arg(4)->Arg(0)->Unit(benchmark::kMillisecond);

/// One still frame at the view's multisampling (what grabFramebuffer, frame export and the
/// redraw after a motion cost). Argument: samples.
void viewStillFrame(benchmark::State& state)
{
    auto& view = standaloneView(int(state.range(0)));
    double t = 0.0;
    for (auto _ : state) {
        t = t > 19.0 ? 0.0 : t + 0.2;
        view.setTime(t);
        benchmark::DoNotOptimize(view.grabFramebuffer());
    }
}
BENCHMARK(viewStillFrame)->Arg(4)->Arg(0)->Unit(benchmark::kMillisecond);

/// A new scene (what a changed take costs when the whole scene is replaced), then one frame.
void viewSceneReplaced(benchmark::State& state)
{
    auto& view = standaloneView(int(state.range(0)));
    const render::SceneContent scene = demoScene();
    for (auto _ : state) {
        view.setScene(scene);
        view.repaint();
    }
}
BENCHMARK(viewSceneReplaced)->Arg(4)->Unit(benchmark::kMillisecond);

/// Argument 1: the 3D view shown (Mesa's software renderer under Xvfb dominates then), 0: hidden.
void showView(app::MainWindow& main, bool show)
{
    main.dock(QStringLiteral("viewDock"))->setVisible(show);
    QCoreApplication::processEvents();
    waitIdle(main);
}

void playbackFrameTwoPuppets48Graphs(benchmark::State& state)
{
    auto& main = window();
    showView(main, state.range(0) != 0);
    const auto* view = main.viewportPanel()->viewport();
    const int framesBefore = view->renderedFrameCount();
    double t = 0.0;
    for (auto _ : state) {
        t = t > 19.0 ? 0.0 : t + 0.2;
        main.document().setCurrentTime(t);
        QCoreApplication::processEvents(); // every view's queued paint, the 3D view included
    }
    state.counters["graphs"] = main.graphPanel()->grid()->graphCount();
    state.counters["view_frames"] = double(view->renderedFrameCount() - framesBefore) / double(state.iterations());
}
BENCHMARK(playbackFrameTwoPuppets48Graphs)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void warpDragStepToResult(benchmark::State& state)
{
    auto& main = window();
    auto& design = main.design();
    showView(main, state.range(0) != 0);
    main.document().selectTake(app::TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    main.document().selectTake(app::TakeSlot::B, {}); // 24 graphs, the original as ghost
    waitIdle(main);
    // Every run drags the same point of the same curve (the curve as first found; a run that
    // started where the previous one left the point could clamp every step to no change).
    static const analysis::WarpCurve base = design.warpCurve();
    design.editWarp(base);
    QCoreApplication::processEvents();
    waitIdle(main);
    const std::size_t index = base.points.size() / 2;
    int changed = 0;
    const auto* view = main.viewportPanel()->viewport();
    const int framesBefore = view->renderedFrameCount();
    int step = 0;
    main.document().beginInteraction();
    QElapsedTimer clock;
    double phases[3] = {0.0, 0.0, 0.0}; // edit (synchronous updates), queued events, graph repaint
    for (auto _ : state) {
        step = (step + 1) % 6;
        analysis::WarpPoint proposed = base.points[index];
        proposed.source += step * 0.5;
        clock.start();
        const auto before = main.document().selectedTake(app::TakeSlot::A);
        design.editWarp(analysis::moveControlPoint(base, index, proposed));
        changed += main.document().selectedTake(app::TakeSlot::A) != before ? 1 : 0;
        phases[0] += double(clock.nsecsElapsed());
        clock.start();
        QCoreApplication::processEvents(); // queued replots and paints of every view
        phases[1] += double(clock.nsecsElapsed());
        clock.start();
        main.graphPanel()->grid()->plot()->repaint();
        phases[2] += double(clock.nsecsElapsed());
    }
    main.document().endInteraction();
    state.counters["synthesis_ms"] = design.lastSynthesisMilliseconds();
    const double perStep = 1e6 * double(state.iterations());
    state.counters["edit_ms"] = phases[0] / perStep;
    state.counters["events_ms"] = phases[1] / perStep;
    state.counters["repaint_ms"] = phases[2] / perStep;
    state.counters["changed"] = double(changed) / double(state.iterations()); // 1: every step redesigned
    // 3D frames drawn per step (1 when shown: the new pose every step; 0 when hidden).
    state.counters["view_frames"] = double(view->renderedFrameCount() - framesBefore) / double(state.iterations());
    design.editWarp(base);
    QCoreApplication::processEvents();
}
BENCHMARK(warpDragStepToResult)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

/// Take B: a Bandai take (its 22-joint skeleton and 24 part channels, imported once), drawn as
/// its skeleton (`skeleton` true) or as the puppet. False when the file is missing.
bool showBandaiAsB(app::MainWindow& main, bool skeleton)
{
    static app::TakeId id;
    if (id.isEmpty()) {
        const auto file = std::filesystem::path(BUNRAKU_SHARED_DIR) / "data" / "bandai" / "bye_angry_001.bvh";
        if (!main.files().imports().importTakeFile(QString::fromStdString(file.string()))) return false;
        for (const auto& derived : main.document().derivedTakes())
            if (derived.id.isImported()) id = derived.id;
    }
    main.document().selectTake(app::TakeSlot::B, id);
    QComboBox* figure = main.viewportPanel()->figureBox(1);
    figure->setCurrentIndex(figure->findData(int(skeleton ? render::FigureStyle::Skeleton : render::FigureStyle::Puppet)));
    showView(main, true);
    return true;
}

/// Drags the middle control point of `base` up and down in half-frame steps, one step per
/// iteration, each to the designed take A in every view (the graphs repainted); then puts the
/// curve back. Counters: steps that redesigned, 3D frames and graphs per step.
void dragWarpPoint(benchmark::State& state, app::MainWindow& main, const analysis::WarpCurve& base)
{
    auto& design = main.design();
    design.editWarp(base);
    QCoreApplication::processEvents();
    waitIdle(main);
    const std::size_t index = base.points.size() / 2;
    const auto* view = main.viewportPanel()->viewport();
    const int framesBefore = view->renderedFrameCount();
    int changed = 0, step = 0, slotsBuilt = 0;
    main.document().beginInteraction();
    for (auto _ : state) {
        step = (step + 1) % 6;
        analysis::WarpPoint proposed = base.points[index];
        proposed.source += step * 0.5;
        const auto before = main.document().selectedTake(app::TakeSlot::A);
        design.editWarp(analysis::moveControlPoint(base, index, proposed));
        changed += main.document().selectedTake(app::TakeSlot::A) != before ? 1 : 0;
        QCoreApplication::processEvents();
        main.graphPanel()->grid()->plot()->repaint();
        slotsBuilt += view->renderer() ? view->renderer()->slotsBuilt() : 0;
    }
    main.document().endInteraction();
    state.counters["changed"] = double(changed) / double(state.iterations());
    // Scene slots the 3D view built per step: 1 when take B's is kept (render::TakeSlot::sources).
    state.counters["slots_built"] = double(slotsBuilt) / double(state.iterations());
    state.counters["view_frames"] = double(view->renderedFrameCount() - framesBefore) / double(state.iterations());
    state.counters["graphs"] = main.graphPanel()->grid()->graphCount();
    design.editWarp(base);
    QCoreApplication::processEvents();
}

/// A warp drag step to the designed take A (puppet) with take B beside it: argument 1 its
/// 22-joint skeleton, 0 its puppet. 48 graphs (B's 24 beside A's).
void warpDragStepBesideSkeleton(benchmark::State& state)
{
    auto& main = window();
    auto& design = main.design();
    main.document().selectTake(app::TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    if (!showBandaiAsB(main, state.range(0) != 0)) {
        state.SkipWithError("Bandai take not found");
        return;
    }
    waitIdle(main);
    static const analysis::WarpCurve base = design.warpCurve();
    dragWarpPoint(state, main, base);
    const auto* view = main.viewportPanel()->viewport();
    state.counters["skeleton_drawn"] = view->renderer() && view->renderer()->takeCount() > 1 && view->renderer()->skeletonDrawn(1) ? 1 : 0;
    main.document().selectTake(app::TakeSlot::B, {});
    waitIdle(main);
}
BENCHMARK(warpDragStepBesideSkeleton)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

/// The workbench on a whole-body corpus (issue 25): the Bandai bye takes with every joint (132
/// channels, built from the shared files into a temporary folder once), its design on the
/// performer's segments. Null when the files are missing.
std::unique_ptr<app::MainWindow> g_wholeBody;

app::MainWindow* wholeBodyWindow()
{
    auto& made = g_wholeBody;
    static bool tried = false;
    if (tried) return made.get();
    tried = true;
    std::vector<std::filesystem::path> files;
    for (const char* style : {"normal", "happy", "angry"})
        files.push_back(std::filesystem::path(BUNRAKU_SHARED_DIR) / "data" / "bandai" / ("bye_" + std::string(style) + "_001.bvh"));
    auto sources = analysis::io::labelTakeFiles(files, "{function}_{emotion}_{take}");
    if (!sources) return nullptr;
    analysis::io::CorpusBuildOptions options;
    options.import.bvhLayout = analysis::io::BvhTakeLayout::AllJoints;
    auto built = analysis::io::buildCorpus(*sources, options);
    if (!built) return nullptr;
    const auto folder = std::filesystem::temp_directory_path() / "bunraku-bench-wholebody";
    std::filesystem::remove_all(folder);
    if (!analysis::io::writeCorpus(built->corpus, folder)) return nullptr;
    auto window = bench::shownDemoWindow();
    if (!window->files().corpora().openCorpusFolder(QString::fromStdString(folder.string()))) return nullptr;
    (void)QTest::qWaitFor([&] { return window->design().ready(); }, 120000);
    waitIdle(*window);
    made = std::move(window);
    return made.get();
}

/// A warp drag step to the designed whole-body take A (every joint re-timed, the performer's
/// skeleton and puppet in the 3D view): argument 1 the 3D view shown, 0 hidden; the graphs of
/// one joint (6, the 'one part' layout) and of all channels (96 of 132).
void warpDragStepWholeBody(benchmark::State& state)
{
    app::MainWindow* main = wholeBodyWindow();
    if (!main || !main->design().ready()) {
        state.SkipWithError("the whole-body Bandai corpus could not be made or designed");
        return;
    }
    main->document().selectTake(app::TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    main->graphPanel()->setGraphLayout(state.range(1) != 0 ? widgets::GraphLayout::AllChannels : widgets::GraphLayout::OnePart);
    showView(*main, state.range(0) != 0);
    static const analysis::WarpCurve base = main->design().warpCurve();
    dragWarpPoint(state, *main, base);
    state.counters["channels"] = double(main->document().selectedTake(app::TakeSlot::A)->channels.size());
}
BENCHMARK(warpDragStepWholeBody)->ArgNames({"view", "all_channels"})->Args({1, 0})->Args({0, 0})->Args({0, 1})->Unit(benchmark::kMillisecond);

/// A playback frame of the whole window: take A a demo take's puppet, take B the Bandai take
/// beside it (argument 1: its skeleton, 0: its puppet), 48 graphs.
void playbackFrameBesideSkeleton(benchmark::State& state)
{
    auto& main = window();
    main.document().selectTake(app::TakeSlot::A, app::TakeId::corpus(0));
    if (!showBandaiAsB(main, state.range(0) != 0)) {
        state.SkipWithError("Bandai take not found");
        return;
    }
    waitIdle(main);
    const auto* view = main.viewportPanel()->viewport();
    const int framesBefore = view->renderedFrameCount();
    double t = 0.0;
    for (auto _ : state) {
        t = t > 3.5 ? 0.0 : t + 1.0 / 60.0;
        main.document().setCurrentTime(t);
        QCoreApplication::processEvents();
    }
    state.counters["graphs"] = main.graphPanel()->grid()->graphCount();
    state.counters["view_frames"] = double(view->renderedFrameCount() - framesBefore) / double(state.iterations());
    state.counters["skeleton_drawn"] = view->renderer() && view->renderer()->takeCount() > 1 && view->renderer()->skeletonDrawn(1) ? 1 : 0;
    main.document().selectTake(app::TakeSlot::B, app::TakeId::corpus(7));
    waitIdle(main);
}
BENCHMARK(playbackFrameBesideSkeleton)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("BunrakuBench"));
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    g_grid.reset(); // before the QApplication goes
    g_views.clear();
    g_window.reset();
    g_wholeBody.reset();
    return 0;
}
