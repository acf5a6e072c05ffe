// Opening a long real take in the workbench (issue "Real motion capture in", point 6: a
// 108,000-frame Bandai-like take, 135 MB, opens in under 3 s): File > Import of the BVH file
// with the automatic part map, from the call until the take is shown as A in the graphs and the
// 3D view (the window repainted once the queued updates ran); a second figure also waits for its
// motion axis, computed in the background. The take is made from a shared Bandai file
// (bench/io/big_bvh.h) and never committed.
#include "bench/app/bench_window.h"
#include "bench/app/long_take_support.h"
#include "bench/io/big_bvh.h"

#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/analysis_controller.h"
#include "app/stage_scheduler.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <memory>

using namespace bunraku;

namespace {

std::unique_ptr<app::MainWindow> g_window;

app::MainWindow& window()
{
    if (!g_window) {
        g_window = bench::shownDemoWindow();
    }
    return *g_window;
}

bool idle(app::MainWindow& main)
{
    return !main.analysis().scheduler().busy();
}

/// Argument 0: until shown; 1: until its motion axis is computed too.
void openLongBvhTake(benchmark::State& state)
{
    const auto file = bench::bigBandaiLikeTake(std::filesystem::temp_directory_path() / "bunraku-bench-io", 108000);
    if (file.empty()) {
        state.SkipWithError(("the Bandai take is missing: " + bench::bandaiTake().string()).c_str());
        return;
    }
    app::MainWindow& main = window();
    (void)QTest::qWaitFor([&] { return idle(main); }, 120000);
    for (auto _ : state) {
        QElapsedTimer timer;
        timer.start();
        if (!main.files().imports().importTakeFile(QString::fromStdString(file.string()))) {
            state.SkipWithError(main.files().lastError().toStdString().c_str());
            return;
        }
        QCoreApplication::processEvents();
        main.repaint();
        if (state.range(0) == 1) (void)QTest::qWaitFor([&] { return idle(main); }, 120000);
        state.SetIterationTime(double(timer.nsecsElapsed()) * 1e-9);
        main.document().undoStack()->undo(); // back to the demo take, the long one released at the next import
        (void)QTest::qWaitFor([&] { return idle(main); }, 120000);
    }
    state.counters["MB"] = double(std::filesystem::file_size(file)) / 1e6;
}
BENCHMARK(openLongBvhTake)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(2);

} // namespace

int main(int argc, char** argv)
{
    return bench::runQtBenchmarks(argc, argv, "bench_open_take", [] { g_window.reset(); });
}
