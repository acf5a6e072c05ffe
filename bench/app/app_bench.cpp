// Benchmarks of the workbench's interactive paths, on the demo corpus:
// - cursor-only update of 48 graphs (two takes side by side): setCursorTime + a synchronous
//   repaint of the plot (target < 4 ms per frame), against a full replot of the same graphs;
// - one playback frame of the whole window with two puppets and 48 graphs;
// - a warp control-point drag step to the designed take shown in the graphs (target < 16 ms).
#include "app/design_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"

#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"

#include <benchmark/benchmark.h>
#include <qcustomplot.h>

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QTest>

#include <memory>

using namespace bunraku;

namespace {

std::unique_ptr<app::MainWindow> g_window;

app::MainWindow& window()
{
    if (!g_window) g_window = [] {
        auto made = std::make_unique<app::MainWindow>();
        made->files().setDialogsEnabled(false);
        made->files().openDemoCorpus();
        made->resize(1600, 1000);
        made->show();
        (void)QTest::qWaitForWindowExposed(made.get());
        made->document().selectTake(app::TakeSlot::B, app::Document::corpusTakeId(7));
        made->graphPanel()->setTwoTakeMode(widgets::TwoTakeMode::SideBySide);
        (void)QTest::qWaitFor([&] { return made->design().ready(); }, 60000);
        QTest::qWait(200);
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
        made->setTakes(document.take(app::Document::corpusTakeId(0)), document.take(app::Document::corpusTakeId(7)));
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

/// Argument 1: the 3D view shown (Mesa's software renderer under Xvfb dominates then), 0: hidden.
void showView(app::MainWindow& main, bool show)
{
    main.dock(QStringLiteral("viewDock"))->setVisible(show);
    QCoreApplication::processEvents();
}

void playbackFrameTwoPuppets48Graphs(benchmark::State& state)
{
    auto& main = window();
    showView(main, state.range(0) != 0);
    double t = 0.0;
    for (auto _ : state) {
        t = t > 19.0 ? 0.0 : t + 0.2;
        main.document().setCurrentTime(t);
        QCoreApplication::processEvents(); // every view's queued paint, the 3D view included
    }
    state.counters["graphs"] = main.graphPanel()->grid()->graphCount();
}
BENCHMARK(playbackFrameTwoPuppets48Graphs)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void warpDragStepToResult(benchmark::State& state)
{
    auto& main = window();
    auto& design = main.design();
    showView(main, state.range(0) != 0);
    main.document().selectTake(app::TakeSlot::A, QStringLiteral("live/designed"));
    main.document().selectTake(app::TakeSlot::B, QString()); // 24 graphs, the original as ghost
    const analysis::WarpCurve base = design.warpCurve();
    const std::size_t index = base.points.size() / 2;
    int step = 0;
    main.document().beginInteraction();
    for (auto _ : state) {
        step = (step + 1) % 6;
        analysis::WarpPoint proposed = base.points[index];
        proposed.source += step * 0.5;
        design.editWarp(analysis::moveControlPoint(base, index, proposed));
        QCoreApplication::processEvents(); // queued replots and paints of every view
        main.graphPanel()->grid()->plot()->repaint();
    }
    main.document().endInteraction();
    state.counters["synthesis_ms"] = design.lastSynthesisMilliseconds();
}
BENCHMARK(warpDragStepToResult)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

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
    g_window.reset();
    return 0;
}
