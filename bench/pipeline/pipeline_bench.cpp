// The analysis pipeline on the demo corpus (30 takes, 6 cells): the whole chain from scratch,
// and the chain again after one parameter change with a warm cache - the counters say which
// stages ran per iteration (1 = recomputed, 0 = taken from the cache).
#include "analysis/pipeline/chain.h"
#include "analysis/synth/demo_corpus.h"

#include <benchmark/benchmark.h>

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

/// Every stage from scratch: preprocess, normalise all cells (with average takes), KM2O over all
/// M = 1..M_max, motion axes, phase and gains; with or without the spectra and ARMA fits.
void BM_WholeChain(benchmark::State& state)
{
    ChainOptions options;
    options.fluctuations = state.range(0) != 0;
    int M = 0;
    for (auto _ : state) {
        auto chain = runChain(demo(), {}, nullptr, options);
        if (!chain) state.SkipWithError(chain.error().message.c_str());
        M = chain->decomposed->km2o->correlationLength;
        benchmark::DoNotOptimize(chain);
    }
    state.counters["M_chosen"] = M;
}
BENCHMARK(BM_WholeChain)->ArgName("with_arma")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

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

} // namespace

BENCHMARK_MAIN();
