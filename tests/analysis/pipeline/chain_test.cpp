#include "analysis/pipeline/chain.h"

#include "analysis/decompose/km2o.h"
#include "analysis/normalise/average_take.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;

namespace {

const CorpusInput& demo()
{
    static const CorpusInput input = [] {
        auto made = makeCorpusInput(synth::generateDemoCorpus().corpus);
        REQUIRE(made.ok());
        return std::move(made).value();
    }();
    return input;
}

} // namespace

TEST_CASE("a parameter changes the keys of its stage and those below it, nothing upstream", "[pipeline][keys]")
{
    const ChainParameters base;
    const ChainKeys before = chainKeys(demo().key, base);

    ChainParameters tau = base;
    tau.normalise.tau = 5;
    const ChainKeys afterTau = chainKeys(demo().key, tau);
    CHECK(afterTau.preprocess == before.preprocess);
    CHECK(afterTau.normalise != before.normalise);
    CHECK(afterTau.decompose != before.decompose);
    CHECK(afterTau.fluctuations != before.fluctuations);
    CHECK(afterTau.axes != before.axes);

    ChainParameters order = base;
    order.decompose.correlationLength = 2;
    const ChainKeys afterOrder = chainKeys(demo().key, order);
    CHECK(afterOrder.normalise == before.normalise);
    CHECK(afterOrder.axes == before.axes);
    CHECK(afterOrder.decompose != before.decompose);
    CHECK(afterOrder.fluctuations != before.fluctuations);

    ChainParameters weight = base; // the emotion weight and design edits are in no stage's key
    weight.design.emotionWeight = 2.5;
    weight.design.boundaries = {false, {40}};
    CHECK(chainKeys(demo().key, weight).of(Stage::Axes) == before.axes);
    CHECK(chainKeys(demo().key, weight).of(Stage::Decompose) == before.decompose);

    Corpus changed = *demo().corpus;
    changed.takes[3].values(10, 2) += 1e-9;
    CHECK(corpusKey(changed) != demo().key);
}

TEST_CASE("the whole chain on the demo corpus follows the thesis and reruns only what a change invalidates", "[pipeline][chain]")
{
    StageCache cache;
    const ChainParameters parameters;
    auto chain = runChain(demo(), parameters, &cache);
    INFO((chain ? "" : chain.error().message));
    REQUIRE(chain.ok());
    for (Stage stage : {Stage::Preprocess, Stage::Normalise, Stage::Decompose, Stage::Fluctuations, Stage::Axes})
        CHECK(cache.runs(stage) == 1);
    REQUIRE(chain->normalised->cells.size() == 6);
    for (const auto& cell : chain->normalised->cells) {
        INFO(cell.function << "/" << cell.emotion);
        CHECK(cell.normalisations.size() == 5);
        // thesis 3.8: normalisation lowers the summed variance to the reference
        CHECK(cell.variance.totalAfter.sum() < cell.variance.totalBefore.sum());
        CHECK(cell.average.frameCount() == cell.referenceTake.frameCount());
    }
    // Chapter 4 by default: KM2O with M chosen by P over 1..M_max, on the normalised takes.
    REQUIRE(chain->decomposed->km2o.has_value());
    const auto& km2o = *chain->decomposed->km2o;
    const Eigen::Index frames = chain->normalised->normalised.takes.front().frameCount();
    CHECK(int(km2o.candidateLengths.size()) == maxCorrelationLength(frames));
    CHECK(km2o.meanErrorPercent[std::size_t(km2o.correlationLength - 1)] ==
          *std::min_element(km2o.meanErrorPercent.begin(), km2o.meanErrorPercent.end()));
    CHECK(chain->axes->functions.size() == 2);
    CHECK(chain->axes->cells.size() == 4);
    for (const auto& cell : chain->axes->cells) CHECK(cell.designRelativeError < cell.undesignedRelativeError);
    CHECK(chain->fluctuations->armaTables.size() == 24);

    // The same inputs again: nothing recomputed.
    cache.resetCounters();
    auto again = runChain(demo(), parameters, &cache);
    REQUIRE(again.ok());
    CHECK(again->decomposed == chain->decomposed);
    for (Stage stage : kStages) CHECK(cache.runs(stage) == 0);

    // M given: decomposition and fluctuations only.
    ChainParameters order = parameters;
    order.decompose.correlationLength = 2;
    cache.resetCounters();
    auto withOrder = runChain(demo(), order, &cache);
    REQUIRE(withOrder.ok());
    CHECK(withOrder->decomposed->km2o->correlationLength == 2);
    CHECK(cache.runs(Stage::Preprocess) == 0);
    CHECK(cache.runs(Stage::Normalise) == 0);
    CHECK(cache.runs(Stage::Axes) == 0);
    CHECK(cache.runs(Stage::Decompose) == 1);
    CHECK(cache.runs(Stage::Fluctuations) == 1);
}

TEST_CASE("the normalise stage is the analysis functions it wraps, bit for bit", "[pipeline][normalise]")
{
    NormaliseParameters parameters;
    parameters.reference = {ReferenceKind::Take, 2};
    auto preprocessed = runPreprocess(*demo().corpus, {});
    REQUIRE(preprocessed.ok());
    auto stage = runNormalise(preprocessed->corpus, parameters);
    REQUIRE(stage.ok());
    const auto takes = preprocessed->corpus.cell("greeting", "friendly");
    auto direct = normaliseTakes(*takes[1], takes, parameters.options());
    REQUIRE(direct.ok());
    const CellNormalisation* cell = stage->cell("greeting", "friendly");
    REQUIRE(cell);
    CHECK(cell->referenceName == "take 2");
    for (std::size_t k = 0; k < takes.size(); ++k) CHECK(cell->normalisations[k].normalised.values == (*direct)[k].normalised.values);
    const Take* inCorpus = stage->normalised.find("greeting", "friendly", 3);
    REQUIRE(inCorpus);
    CHECK(inCorpus->values == (*direct)[2].normalised.values);

    parameters.cellReferences["greeting/friendly"] = {ReferenceKind::Take, 9};
    auto missing = runNormalise(preprocessed->corpus, parameters);
    REQUIRE_FALSE(missing.ok());
    CHECK_THAT(missing.error().message, Catch::Contains("greeting/friendly") && Catch::Contains("no take 9"));
}

TEST_CASE("a cancelled chain stops with Cancelled", "[pipeline][chain]")
{
    std::stop_source stop;
    stop.request_stop();
    ChainOptions options;
    options.stop = stop.get_token();
    auto chain = runChain(demo(), {}, nullptr, options);
    REQUIRE_FALSE(chain.ok());
    CHECK(chain.error().code == ErrorCode::Cancelled);
}
