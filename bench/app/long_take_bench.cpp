// An hour-long take in the workbench (issue 17 point 1): a 432,000-frame take at 120 Hz with a
// 22-joint skeleton (analysis/synth/long_take.h, written once into the temporary folder;
// BUNRAKU_LONG_FRAMES changes the length), in the real main window under Xvfb:
// - opening it (File > Import Take, until shown as A in the 24 graphs and the 3D view), with
//   the process's peak memory, then the longest stall of the GUI thread while its motion axes
//   are computed in the background;
// - a scrub step and a playback frame of the whole window, the graphs showing the whole take
//   (argument 0) or a 10 s window (1): target 60 fps (16.7 ms);
// - zooming the 24 graphs from the whole take into a 10 s window (target < 50 ms), and a full
//   replot of the whole take.
#include "bench/app/bench_window.h"
#include "bench/app/long_take_support.h"

#include "app/analysis_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/playback_controller.h"
#include "app/stage_scheduler.h"
#include "app/viewport_panel.h"

#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"
#include "widgets/viewport_widget.h"

#include <benchmark/benchmark.h>
#include <qcustomplot.h>

#include <QApplication>
#include <QDockWidget>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <memory>
#include <random>

using namespace bunraku;

namespace {

std::unique_ptr<app::MainWindow> g_window;
bool g_opened = false;

bool idle(app::MainWindow& main)
{
    return !main.analysis().scheduler().busy();
}

app::MainWindow& window()
{
    if (!g_window) {
        g_window = bench::shownDemoWindow();
        (void)bench::runMeasuringStalls([] { return idle(*g_window); });
    }
    return *g_window;
}

widgets::GraphGrid& grid() { return *window().graphPanel()->grid(); }

/// Opens the long take (once per process): file > import until shown, then until its motion
/// axes are computed. Counters: seconds to shown and to idle, the peak and current memory (MB),
/// the longest GUI stall while the file was read (import_stall_ms) and while the background
/// work ran after it (stall_ms).
void openLongTake(benchmark::State& state)
{
    const auto file = bench::longTakeFile(bench::longTakeFrames());
    if (file.empty()) {
        state.SkipWithError("cannot write the long take");
        return;
    }
    app::MainWindow& main = window();
    for (auto _ : state) {
        if (g_opened) {
            state.SkipWithError("the long take is opened once per process");
            return;
        }
        bench::resetPeakMemory();
        const double before = bench::statusMegabytes("VmRSS");
        // As a user imports it: off the GUI thread behind the progress dialog (the joint map
        // given, as the dialog's automatic preset would choose it); a probe timer measures the
        // longest time the GUI thread did not process events meanwhile.
        QTimer probe;
        probe.setTimerType(Qt::PreciseTimer);
        probe.setInterval(4);
        QElapsedTimer sinceTick;
        double importStall = 0.0;
        QObject::connect(&probe, &QTimer::timeout, [&] {
            importStall = std::max(importStall, double(sinceTick.nsecsElapsed()) * 1e-6);
            sinceTick.restart();
        });
        QElapsedTimer clock;
        clock.start();
        sinceTick.start();
        probe.start();
        main.files().setDialogsEnabled(true);
        const bool imported = main.files().imports().importTakeFile(QString::fromStdString(file.string()),
                                                          QStringLiteral("head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R"));
        main.files().setDialogsEnabled(false);
        probe.stop();
        if (!imported) {
            state.SkipWithError(main.files().lastError().toStdString().c_str());
            return;
        }
        QCoreApplication::processEvents();
        main.repaint();
        const double shown = double(clock.nsecsElapsed()) * 1e-9;
        double background = 0.0;
        const double stall = bench::runMeasuringStalls([&] { return idle(main); }, &background);
        state.SetIterationTime(shown);
        state.counters["shown_s"] = shown;
        state.counters["idle_s"] = shown + background;
        state.counters["stall_ms"] = stall;
        state.counters["import_stall_ms"] = importStall;
        state.counters["rss_before_MB"] = before;
        state.counters["peak_MB"] = bench::statusMegabytes("VmHWM");
        state.counters["rss_MB"] = bench::statusMegabytes("VmRSS");
        state.counters["frames"] = double(main.document().selectedTake(app::TakeSlot::A)->frameCount());
        state.counters["graphs"] = grid().graphCount();
        g_opened = true;
    }
}
BENCHMARK(openLongTake)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(1);

bool requireOpened(benchmark::State& state)
{
    if (g_opened) return true;
    state.SkipWithError("openLongTake must run first");
    return false;
}

/// Argument 0: the whole take in view, 1: a 10 s window (moved with the time).
void showWindow(double t, bool zoomed)
{
    auto& g = grid();
    if (!zoomed) {
        if (g.timeRange().first != 0.0 || g.timeRange().second < window().document().duration() - 1e-6) g.resetTimeRange();
        return;
    }
    const double lower = std::floor(t / 10.0) * 10.0;
    if (g.timeRange().first != lower || g.timeRange().second != lower + 10.0) g.setTimeRange(lower, lower + 10.0);
}

/// One scrub step: the time set from the scrub bar anywhere in view, then every view painted.
void scrubLongTake(benchmark::State& state)
{
    if (!requireOpened(state)) return;
    app::MainWindow& main = window();
    const bool zoomed = state.range(0) != 0;
    std::mt19937 random(7);
    const double duration = main.document().duration();
    const double middle = std::floor(duration / 20.0) * 10.0; // a 10 s window in the middle
    showWindow(middle, zoomed);
    const int samplings = grid().samplingCount();
    const auto* view = main.viewportPanel()->viewport();
    const int framesBefore = view->renderedFrameCount();
    for (auto _ : state) {
        const double t = zoomed ? middle + std::uniform_real_distribution<double>(0.0, 9.99)(random)
                                : std::uniform_real_distribution<double>(0.0, duration)(random);
        main.document().setCurrentTime(t);
        QCoreApplication::processEvents(); // every view's queued paint, the 3D view included
    }
    state.counters["graphs"] = grid().graphCount();
    state.counters["resamplings"] = grid().samplingCount() - samplings; // 0: curves untouched
    state.counters["view_frames"] = double(view->renderedFrameCount() - framesBefore) / double(state.iterations());
}
BENCHMARK(scrubLongTake)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// One playback frame at 60 fps: the clock advanced by 1/60 s, every view painted. Zoomed in,
/// the graphs page to the next 10 s window when the time leaves the view.
void playbackLongTake(benchmark::State& state)
{
    if (!requireOpened(state)) return;
    app::MainWindow& main = window();
    const bool zoomed = state.range(0) != 0;
    const double middle = std::floor(main.document().duration() / 20.0) * 10.0;
    main.document().setCurrentTime(middle);
    showWindow(middle, zoomed);
    const int samplings = grid().samplingCount();
    const auto* view = main.viewportPanel()->viewport();
    const int framesBefore = view->renderedFrameCount();
    for (auto _ : state) {
        main.playback().advance(1.0 / 60.0);
        showWindow(main.document().currentTime(), zoomed);
        QCoreApplication::processEvents();
    }
    state.counters["graphs"] = grid().graphCount();
    state.counters["resamplings"] = grid().samplingCount() - samplings;
    state.counters["view_frames"] = double(view->renderedFrameCount() - framesBefore) / double(state.iterations());
}
BENCHMARK(playbackLongTake)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// From the whole take to a 10 s window anywhere in it: resampled curves and a full replot of
/// the 24 graphs, painted.
void zoomLongTakeTo10s(benchmark::State& state)
{
    if (!requireOpened(state)) return;
    auto& g = grid();
    std::mt19937 random(11);
    const double duration = window().document().duration();
    QElapsedTimer clock;
    for (auto _ : state) {
        g.resetTimeRange();
        g.plot()->repaint();
        const double lower = std::uniform_real_distribution<double>(0.0, duration - 10.0)(random);
        clock.start();
        g.setTimeRange(lower, lower + 10.0);
        g.plot()->repaint();
        state.SetIterationTime(double(clock.nsecsElapsed()) * 1e-9);
    }
    qint64 points = 0;
    for (int k = 0; k < g.graphCount(); ++k) points += g.curve(k, 0) ? g.curve(k, 0)->dataCount() : 0;
    state.counters["points_per_graph"] = double(points) / double(std::max(1, g.graphCount()));
    g.resetTimeRange();
}
BENCHMARK(zoomLongTakeTo10s)->Unit(benchmark::kMillisecond)->UseManualTime();

/// A full replot of the 24 graphs showing the whole take (what a value-scale change costs).
void fullReplotLongTake(benchmark::State& state)
{
    if (!requireOpened(state)) return;
    auto& g = grid();
    g.resetTimeRange();
    for (auto _ : state) g.plot()->replot(QCustomPlot::rpImmediateRefresh);
    qint64 points = 0;
    for (int k = 0; k < g.graphCount(); ++k) points += g.curve(k, 0) ? g.curve(k, 0)->dataCount() : 0;
    state.counters["points_per_graph"] = double(points) / double(std::max(1, g.graphCount()));
}
BENCHMARK(fullReplotLongTake)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv)
{
    return bench::runQtBenchmarks(argc, argv, "bench_long_take", [] { g_window.reset(); });
}
