// Decomposition speed on the demo corpus shape (30 takes x 24 channels x 106 frames):
// least squares, KM2O over all initial times, M selection, spectra, ARMA, and the emotion
// weight re-synthesis the workbench's slider needs (< 1 ms). Results: docs/PERFORMANCE.md.
#include "analysis/decompose/arma.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/km2o_experiment.h"
#include "analysis/decompose/least_squares.h"
#include "analysis/decompose/spectrum.h"
#include "analysis/synth/demo_corpus.h"

#include <benchmark/benchmark.h>

using namespace bunraku::analysis;

namespace {

/// The demo corpus with every take padded to the longest by repeating its last frame.
const Corpus& demoCorpus()
{
    static const Corpus corpus = [] {
        Corpus c = synth::generateDemoCorpus().corpus;
        Eigen::Index longest = 0;
        for (const auto& take : c.takes) longest = std::max(longest, take.frameCount());
        for (auto& take : c.takes) {
            const Eigen::Index old = take.frameCount();
            take.values.conservativeResize(longest, Eigen::NoChange);
            for (Eigen::Index f = old; f < longest; ++f) take.values.row(f) = take.values.row(old - 1);
        }
        return c;
    }();
    return corpus;
}

void BM_LeastSquares(benchmark::State& state)
{
    const Corpus& corpus = demoCorpus();
    for (auto _ : state) benchmark::DoNotOptimize(decomposeLeastSquares(corpus));
    state.counters["takes"] = double(corpus.takes.size());
    state.counters["frames"] = double(corpus.takes.front().frameCount());
}
BENCHMARK(BM_LeastSquares)->Unit(benchmark::kMillisecond);

/// The full decomposition at a given M: least squares layout, then KM2O data and Markov
/// estimates for every channel, function and initial time T0 = 0..T-M, components and P^{ij}.
void BM_Km2oDecompositionFixedM(benchmark::State& state)
{
    const Corpus& corpus = demoCorpus();
    Km2oDecompositionOptions options;
    options.correlationLength = int(state.range(0));
    for (auto _ : state) {
        auto result = decomposeKm2o(corpus, options);
        if (!result) state.SkipWithError(result.error().message.c_str());
        benchmark::DoNotOptimize(result);
    }
}
BENCHMARK(BM_Km2oDecompositionFixedM)->Arg(2)->Arg(10)->Arg(29)->Unit(benchmark::kMillisecond);

/// M chosen by reconstruction error over every M = 1..M_max (29): 29 full decompositions.
void BM_Km2oDecompositionChooseM(benchmark::State& state)
{
    const Corpus& corpus = demoCorpus();
    for (auto _ : state) benchmark::DoNotOptimize(decomposeKm2o(corpus));
}
BENCHMARK(BM_Km2oDecompositionChooseM)->Unit(benchmark::kMillisecond);

void BM_SpectraAllFluctuations(benchmark::State& state)
{
    const auto d = decomposeLeastSquares(demoCorpus());
    for (auto _ : state) {
        for (const auto& eta : d->fluctuations)
            for (Eigen::Index ch = 0; ch < eta.values.cols(); ++ch) {
                benchmark::DoNotOptimize(periodogram(eta.values.col(ch), d->rateHz));
                benchmark::DoNotOptimize(welch(eta.values.col(ch), d->rateHz));
            }
    }
}
BENCHMARK(BM_SpectraAllFluctuations)->Unit(benchmark::kMillisecond);

/// Table 4.1 for one channel: ARMA(2,2) for the 30 takes, averaged per cell.
void BM_ArmaTableOneChannel(benchmark::State& state)
{
    const auto d = decomposeLeastSquares(demoCorpus());
    for (auto _ : state) benchmark::DoNotOptimize(armaCellTable(*d, 0, 2, 2));
}
BENCHMARK(BM_ArmaTableOneChannel)->Unit(benchmark::kMillisecond);

/// The emotion slider: y^i + a z^{ij} into a preallocated buffer (eq. 4.45).
void BM_EmotionWeightResynthesis(benchmark::State& state)
{
    const auto d = decomposeLeastSquares(demoCorpus());
    Eigen::MatrixXd out;
    double a = 0.0;
    for (auto _ : state) {
        weightEmotionInto(*d, 1, 4, a, out);
        benchmark::DoNotOptimize(out.data());
        a = a > 2.9 ? 0.0 : a + 0.1;
    }
}
BENCHMARK(BM_EmotionWeightResynthesis)->Unit(benchmark::kMicrosecond);

/// The same through the labelled API that builds a Take (allocates).
void BM_EmotionWeightTake(benchmark::State& state)
{
    const auto d = decomposeLeastSquares(demoCorpus());
    for (auto _ : state) benchmark::DoNotOptimize(weightEmotion(*d, "serving-tea", "friendly", 1.7));
}
BENCHMARK(BM_EmotionWeightTake)->Unit(benchmark::kMicrosecond);

/// One seed of the km2o experiment at T = 300, M = 3..20.
void BM_Km2oExperimentOneSeed(benchmark::State& state)
{
    Km2oExperimentOptions options;
    options.finalTime = int(state.range(0));
    options.seeds = 1;
    for (auto _ : state) benchmark::DoNotOptimize(runKm2oExperiment(options));
}
BENCHMARK(BM_Km2oExperimentOneSeed)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
