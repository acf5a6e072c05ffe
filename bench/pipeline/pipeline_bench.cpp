// The analysis pipeline on the demo corpus (30 takes, 6 cells): the whole chain from scratch,
// and the chain again after one parameter change with a warm cache - the counters say which
// stages ran per iteration (1 = recomputed, 0 = taken from the cache).
#include "analysis/core/skeleton_take.h"
#include "analysis/io/corpus_builder.h"
#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/stage_digest.h"
#include "analysis/synth/demo_corpus.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <filesystem>
#include <optional>

namespace {

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;

const CorpusInput& demo()
{
    static const CorpusInput input = std::move(makeCorpusInput(synth::generateDemoCorpus().corpus)).value();
    return input;
}

void report(benchmark::State& state, const StageCache& cache)
{
    for (Stage stage : kStages)
        if (stage != Stage::Import)
            state.counters[stageName(stage)] = benchmark::Counter(double(cache.runs(stage)), benchmark::Counter::kAvgIterations);
}

/// One run of the whole chain with `options`: the stage digests of the first run into `digest`,
/// the chosen M into `chosenM`; false (and the benchmark skipped) when the chain fails.
bool runChainOnce(benchmark::State& state, const ChainOptions& options, std::string& digest, int* chosenM = nullptr)
{
    auto chain = runChain(demo(), {}, nullptr, options);
    if (!chain) {
        state.SkipWithError(chain.error().message.c_str());
        return false;
    }
    if (chosenM) *chosenM = chain->decomposed->km2o->correlationLength;
    if (digest.empty()) digest = chainDigest(*chain).text();
    benchmark::DoNotOptimize(chain);
    return true;
}

/// Every stage from scratch: preprocess, normalise all cells (with average takes), KM2O over all
/// M = 1..M_max, motion axes, phase and gains; with or without the spectra and ARMA fits.
void BM_WholeChain(benchmark::State& state)
{
    ChainOptions options;
    options.fluctuations = state.range(0) != 0;
    int M = 0;
    std::string digest;
    for (auto _ : state)
        if (!runChainOnce(state, options, digest, &M)) break;
    state.counters["M_chosen"] = M;
    // The stage results' digests (stage_digest.h): equal before and after a change to how a
    // stage computes means bit-identical results.
    state.SetLabel(digest);
}
BENCHMARK(BM_WholeChain)->ArgName("with_arma")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/// The whole chain with its cells and channels split over `threads` threads (ChainOptions::threads,
/// `bunraku analyse --threads`): wall-clock time (the speed-up) and the CPU time of every thread
/// of the process (the cost of splitting). The label is the stage digests, the same for every
/// thread count.
void BM_WholeChainThreads(benchmark::State& state)
{
    ChainOptions options;
    options.threads = int(state.range(0));
    std::string digest;
    for (auto _ : state)
        if (!runChainOnce(state, options, digest)) break;
    state.SetLabel(digest);
}
BENCHMARK(BM_WholeChainThreads)->ArgName("threads")->Arg(1)->Arg(2)->MeasureProcessCPUTime()->UseRealTime()->Unit(benchmark::kMillisecond);

/// One threaded stage alone from its cached inputs, on 1 and 2 threads (wall-clock and process CPU).
void BM_StageThreads(benchmark::State& state)
{
    static const ChainResult inputs = std::move(runChain(demo(), {}, nullptr)).value();
    const ChainParameters parameters;
    const auto stage = Stage(state.range(0));
    RunControl control;
    control.threads = int(state.range(1));
    for (auto _ : state) {
        switch (stage) {
        case Stage::Normalise:
            benchmark::DoNotOptimize(runNormalise(inputs.preprocessed->corpus, parameters.normalise, control));
            break;
        case Stage::Fluctuations:
            benchmark::DoNotOptimize(runFluctuations(inputs.decomposed->components, parameters.fluctuations, control));
            break;
        case Stage::Axes:
            benchmark::DoNotOptimize(runAxes(*inputs.normalised, demo().corpus->neutralEmotion, parameters.axis, control));
            break;
        default: break;
        }
    }
    state.SetLabel(stageName(stage));
}
BENCHMARK(BM_StageThreads)
    ->ArgNames({"stage", "threads"})
    ->ArgsProduct({{int(Stage::Normalise), int(Stage::Fluctuations), int(Stage::Axes)}, {1, 2}})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

/// One stage alone from its (cached) inputs: where the whole chain's time goes.
void BM_Stage(benchmark::State& state)
{
    static const ChainResult inputs = std::move(runChain(demo(), {}, nullptr)).value();
    const ChainParameters parameters;
    const auto stage = Stage(state.range(0));
    for (auto _ : state) {
        switch (stage) {
        case Stage::Preprocess: benchmark::DoNotOptimize(runPreprocess(*demo().corpus, parameters.preprocess)); break;
        case Stage::Normalise: benchmark::DoNotOptimize(runNormalise(inputs.preprocessed->corpus, parameters.normalise)); break;
        case Stage::Decompose: benchmark::DoNotOptimize(runDecompose(inputs.normalised->normalised, parameters.decompose)); break;
        case Stage::Fluctuations:
            benchmark::DoNotOptimize(runFluctuations(inputs.decomposed->components, parameters.fluctuations));
            break;
        case Stage::Axes:
            benchmark::DoNotOptimize(runAxes(*inputs.normalised, demo().corpus->neutralEmotion, parameters.axis));
            break;
        case Stage::Import: break;
        }
    }
    state.SetLabel(stageName(stage));
}
BENCHMARK(BM_Stage)->ArgName("stage")->DenseRange(1, 5)->Unit(benchmark::kMillisecond);

/// One parameter changes between two values every iteration; a cache of one result per stage
/// keeps what the change does not touch.
void BM_CachedChange(benchmark::State& state)
{
    StageCache cache(1);
    ChainParameters parameters;
    ChainOptions options;
    options.fluctuations = false;
    (void)runChain(demo(), parameters, &cache, options);
    cache.resetCounters();
    int flip = 0;
    for (auto _ : state) {
        flip ^= 1;
        switch (state.range(0)) {
        case 0: parameters.normalise.tau = 4 + flip; break;            // normalisation and below
        case 1: parameters.decompose.correlationLength = 2 + flip; break; // decomposition only
        case 2: parameters.axis.refinementPasses = 2 - flip; break;   // motion axes only
        case 3: parameters.design.emotionWeight = 1.0 + flip; break;  // no stage
        }
        auto chain = runChain(demo(), parameters, &cache, options);
        if (!chain) state.SkipWithError(chain.error().message.c_str());
        benchmark::DoNotOptimize(chain);
    }
    report(state, cache);
}
BENCHMARK(BM_CachedChange)->ArgName("changed")->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

/// One body per take: the Emotion dock's weighted take (eq. 4.45 on the channels and on the
/// skeleton's coordinates) and the body motion the workbench shows and exports (forward
/// kinematics of its skeleton, analysis::bodyTake), for a 106-frame demo cell; arg 1 also
/// designs the function with the cell's extracted warp (the Design dock's drag result).
void BM_BodyTake(benchmark::State& state)
{
    static const ChainResult inputs = std::move(runChain(demo(), {}, nullptr)).value();
    const bool design = state.range(0) == 1;
    const auto& cell = inputs.axes->cells.front();
    const FunctionAxis* function = inputs.axes->function(cell.function);
    DesignEdits edits;
    edits.warp = cell.extracted.phase.curve;
    double a = 0.0;
    Eigen::Index frames = 0;
    for (auto _ : state) {
        Take take = design ? designFunction(*function, edits).take
                           : std::move(weightedTake(*inputs.decomposed, cell.function, cell.emotion, a)).value();
        a = a > 2.9 ? 0.0 : a + 0.1;
        const Take body = bodyTake(std::move(take));
        frames = body.frameCount();
        benchmark::DoNotOptimize(body.values.data());
    }
    state.counters["frames"] = double(frames);
    state.SetLabel(design ? "designed" : "weighted");
}
BENCHMARK(BM_BodyTake)->ArgName("designed")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

/// The body of an hour-long derived take (432,000 frames at 120 Hz: a weighted demo take and its
/// skeleton repeated), what the workbench makes off the GUI thread (AnalysisController's
/// backgroundBodyFrames): forward kinematics and the 24 channels, one pass.
void BM_BodyMotionHour(benchmark::State& state)
{
    static const ChainResult inputs = std::move(runChain(demo(), {}, nullptr)).value();
    const auto& cell = inputs.axes->cells.front();
    const Take weighted = std::move(weightedTake(*inputs.decomposed, cell.function, cell.emotion, 2.0)).value();
    const Eigen::Index frames = 432000;
    const Eigen::Index copies = (frames + weighted.frameCount() - 1) / weighted.frameCount();
    Take hour = weighted;
    hour.values = weighted.values.replicate(copies, 1).topRows(frames);
    auto motion = std::make_shared<SkeletalMotion>(*weighted.skeleton);
    const std::size_t slots = std::size_t(motion->jointSlots());
    motion->rotations.clear();
    for (Eigen::Index f = 0; f < frames; ++f) {
        const std::size_t source = std::size_t(f % weighted.frameCount()) * slots;
        motion->rotations.insert(motion->rotations.end(), weighted.skeleton->rotations.begin() + std::ptrdiff_t(source),
                                 weighted.skeleton->rotations.begin() + std::ptrdiff_t(source + slots));
    }
    motion->movingTranslations = weighted.skeleton->movingTranslations.replicate(copies, 1).topRows(frames);
    hour.skeleton = motion;
    for (auto _ : state) {
        const BodyMotion body = bodyMotion(hour);
        if (!body.perChannel) state.SkipWithError("the weighted take is its body already");
        benchmark::DoNotOptimize(body.take.values.data());
    }
    state.counters["frames"] = double(frames);
}
BENCHMARK(BM_BodyMotionHour)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

/// Issue 25's target: `bunraku analyse` of the 15 Bandai waves with all 22 joints (132 channels)
/// in under 2 s wall - the chain as analyse runs it (the chains coupling, the optimal path, KM2O
/// over all M, spectra and ARMA, the motion axes on the performers' segments) on 2 threads, wall
/// time; peak resident memory of the process as a counter (MB).
void BM_WholeBodyChain(benchmark::State& state)
{
    static const std::optional<CorpusInput> waves = []() -> std::optional<CorpusInput> {
        std::vector<std::filesystem::path> files;
        for (const std::string style : {"normal", "active", "exhausted"})
            for (int k = 1; k <= 5; ++k)
                files.push_back(std::filesystem::path(BUNRAKU_SHARED_DIR) / "data/bandai" /
                                ("wave-right-hand_" + style + "_00" + std::to_string(k) + ".bvh"));
        auto sources = io::labelTakeFiles(files, "{function}_{emotion}_{take}");
        if (!sources) return std::nullopt;
        io::CorpusBuildOptions options;
        options.import.bvhLayout = io::BvhTakeLayout::AllJoints;
        auto built = io::buildCorpus(*sources, options);
        if (!built) return std::nullopt;
        auto input = makeCorpusInput(std::move(built->corpus));
        if (!input) return std::nullopt;
        return std::move(input).value();
    }();
    if (!waves) {
        state.SkipWithError("needs the shared Bandai data (" BUNRAKU_SHARED_DIR "/data/bandai)");
        return;
    }
    ChainOptions options;
    options.threads = int(state.range(0));
    std::size_t axes = 0;
    for (auto _ : state) {
        auto chain = runChain(*waves, {}, nullptr, options);
        if (!chain) {
            state.SkipWithError(chain.error().message.c_str());
            break;
        }
        axes = chain->axes ? chain->axes->cells.size() : 0;
        benchmark::DoNotOptimize(chain);
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    state.counters["peak_rss_MB"] = double(usage.ru_maxrss) / 1024.0;
    state.counters["axis_cells"] = double(axes);
    state.counters["channels"] = double(waves->corpus->takes.front().channels.size());
}
BENCHMARK(BM_WholeBodyChain)->ArgName("threads")->Arg(2)->MeasureProcessCPUTime()->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
