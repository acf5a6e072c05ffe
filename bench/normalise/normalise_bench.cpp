// Speed of time normalisation (issue 3): one thesis cell, the whole demo corpus, a pair of
// 100,000-frame takes, and the CWT of 100,000 samples. Numbers: docs/PERFORMANCE.md.
#include "analysis/normalise/feature_matching.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/synth/demo_corpus.h"
#include "analysis/wavelet/cwt.h"
#include "bench/normalise/kernels_in_use.h"
#include "bench/normalise/long_takes.h"

#include <benchmark/benchmark.h>

#include <random>
#include <utility>

using namespace bunraku::analysis;

namespace {

const synth::DemoCorpus& demo()
{
    static const synth::DemoCorpus corpus = synth::generateDemoCorpus();
    return corpus;
}

NormaliseOptions thesisOptions(PathMethod path)
{
    NormaliseOptions options; // method2, scales 1..16, tau 4, T_cmp 20
    options.match.path = path;
    return options;
}

// One thesis cell: 5 takes x 24 channels x ~106 frames normalised to take 4, method 2.
void BM_ThesisCell(benchmark::State& state)
{
    const auto takes = demo().corpus.cell("greeting", "none");
    const Take& reference = *takes[3];
    const NormaliseOptions options = thesisOptions(PathMethod(state.range(0)));
    for (auto _ : state) {
        auto result = normaliseTakes(reference, takes, options);
        benchmark::DoNotOptimize(result);
    }
    state.SetLabel(state.range(0) == 0 ? "greedy" : "optimal");
}
BENCHMARK(BM_ThesisCell)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The whole demo corpus: 6 cells x 5 takes, each cell to its take 1.
void BM_DemoCorpus(benchmark::State& state)
{
    const Corpus& corpus = demo().corpus;
    const NormaliseOptions options = thesisOptions(PathMethod(state.range(0)));
    for (auto _ : state) {
        for (const auto& function : corpus.functions())
            for (const auto& emotion : corpus.emotions()) {
                const auto takes = corpus.cell(function, emotion);
                auto result = normaliseTakes(*takes[0], takes, options);
                benchmark::DoNotOptimize(result);
            }
    }
    state.SetLabel(state.range(0) == 0 ? "greedy" : "optimal");
}
BENCHMARK(BM_DemoCorpus)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// A pair of 100,000-frame x 24-channel takes, T_cmp 240, 16 scales, method 2.
void BM_LongPair(benchmark::State& state)
{
    const Eigen::Index frames = state.range(1);
    static const Take reference = bunraku::bench::longTake(100000, 0.0, 1.0, 1);
    static const Take sample = bunraku::bench::longTake(100000, 190.0, 7919.0, 2);
    const Take ref = frames == 100000 ? reference : bunraku::bench::longTake(frames, 0.0, 1.0, 1);
    const Take smp = frames == 100000 ? sample : bunraku::bench::longTake(frames, 190.0, 7919.0, 2);
    NormaliseOptions options = thesisOptions(PathMethod(state.range(0)));
    options.match.searchBand = 240;
    for (auto _ : state) {
        auto result = normaliseTake(ref, smp, options);
        if (!result) state.SkipWithError(result.error().message.c_str());
        benchmark::DoNotOptimize(result);
    }
    state.SetLabel(state.range(0) == 0 ? "greedy" : "optimal");
}
BENCHMARK(BM_LongPair)->Args({0, 100000})->Args({1, 100000})->Args({1, 25000})->Args({1, 50000})
    ->Unit(benchmark::kMillisecond)->Iterations(3);

// The matching engine alone on one coupling set's worth of features: 100,000 frames x 32
// features (2 channels x 16 scales), T_cmp 240, tau 4 - a twelfth of BM_LongPair's matching.
void BM_MatchFeatures(benchmark::State& state)
{
    static const auto features = [] {
        std::mt19937 random(11);
        std::normal_distribution<double> normal;
        std::pair<FeatureMatrix, FeatureMatrix> pair{FeatureMatrix(100000, 32), FeatureMatrix(100000, 32)};
        for (Eigen::Index i = 0; i < pair.first.size(); ++i) pair.first.data()[i] = normal(random);
        for (Eigen::Index i = 0; i < pair.second.size(); ++i) pair.second.data()[i] = normal(random);
        return pair;
    }();
    const FeatureMatchOptions options{4, 240, PathMethod(state.range(0))};
    for (auto _ : state) {
        auto result = matchFeatures(features.first, features.second, options);
        benchmark::DoNotOptimize(result);
    }
    state.SetLabel(state.range(0) == 0 ? "greedy" : "optimal");
}
BENCHMARK(BM_MatchFeatures)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The same work as normaliseTake does it for one coupling set: the set's 32 columns read from
// column-major features of all 24 channels (100,000 frames x 384 features).
void BM_MatchCouplingSet(benchmark::State& state)
{
    static const FeatureSeries reference = FeatureSeries::Random(100000, 384);
    static const FeatureSeries sample = FeatureSeries::Random(100000, 384);
    std::vector<Eigen::Index> columns;
    for (Eigen::Index channel : {8, 14})
        for (Eigen::Index scale = 0; scale < 16; ++scale) columns.push_back(channel * 16 + scale);
    const FeatureMatchOptions options{4, 240, PathMethod(state.range(0))};
    for (auto _ : state) {
        auto result = matchFeatures(reference, sample, columns, options);
        benchmark::DoNotOptimize(result);
    }
    state.SetLabel(state.range(0) == 0 ? "greedy" : "optimal");
}
BENCHMARK(BM_MatchCouplingSet)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// CWT of 100,000 samples at scales 1..16 (sym3).
void BM_Cwt100k(benchmark::State& state)
{
    std::mt19937 random(5);
    std::normal_distribution<double> normal;
    Eigen::VectorXd signal(100000);
    for (auto& v : signal) v = normal(random);
    CwtOptions options;
    options.method = CwtMethod(state.range(0));
    const CwtFilterBank bank = *makeCwtFilterBank(integerScales(16), options);
    for (auto _ : state) {
        auto result = cwt(signal, bank);
        benchmark::DoNotOptimize(result);
    }
    state.SetLabel(state.range(0) == 0 ? "automatic" : state.range(0) == 1 ? "direct" : "fft");
}
BENCHMARK(BM_Cwt100k)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv)
{
    // Printed with the run's context: which kernels ran (AVX-512, AVX2 or plain).
    benchmark::AddCustomContext("kernels", bunraku::bench::kernelsInUse());
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
