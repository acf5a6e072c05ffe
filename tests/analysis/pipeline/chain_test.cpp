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

TEST_CASE("a take's motion axis is keyed by its content and the axis parameters it depends on", "[pipeline][keys]")
{
    const Take& take = demo().corpus->takes[4];
    const AxisParameters base;
    const StageKey key = takeAxisKey(takeKey(take), base);
    AxisParameters other = base;
    other.tau = 7; // phase matching only: not the axis
    CHECK(takeAxisKey(takeKey(take), other) == key);
    other.massSpacing = 2.0;
    CHECK(takeAxisKey(takeKey(take), other) != key);
    other = base;
    other.frontBack = FrontBackAxis::Principal;
    CHECK(takeAxisKey(takeKey(take), other) != key);
    Take changed = take;
    changed.values(3, 1) += 1e-9;
    CHECK(takeAxisKey(takeKey(changed), base) != key);

    auto axis = runTakeAxis(take, base);
    REQUIRE(axis.ok());
    CHECK(axis->world_T_axis.size() == std::size_t(take.frameCount()));
    CHECK(axis->coordinates.channelCount() == 6);
    CHECK(axis->coordinates.labels.source == "axis of " + take.displayName());
    AxisParameters invalid = base;
    invalid.massSpacing = 0.01;
    CHECK_THAT(runTakeAxis(take, invalid).error().message, Catch::Contains("massSpacing"));
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

TEST_CASE("the axis stage's per-scale approximation error has the shape of Fig. 5.16", "[pipeline][approximation]")
{
    const ChainParameters parameters;
    auto preprocessed = preprocessStage(demo(), parameters.preprocess, nullptr);
    REQUIRE(preprocessed.ok());
    auto normalised = normaliseStage(chainKeys(demo().key, parameters).preprocess, **preprocessed, parameters.normalise, nullptr);
    REQUIRE(normalised.ok());
    auto axes = axisStage(chainKeys(demo().key, parameters).normalise, **normalised, "none", parameters.axis, nullptr);
    REQUIRE(axes.ok());
    REQUIRE((*axes)->cells.size() == 4);
    for (const CellAxis& cell : (*axes)->cells) {
        INFO(cell.function << "/" << cell.emotion);
        const ApproximationError& error = cell.approximation;
        REQUIRE(error.scales.size() == 16);
        REQUIRE(error.relativeError.rows() == 16);
        REQUIRE(error.relativeError.cols() == 6);
        CHECK(error.relativeError.allFinite());
        // falling with the largest scale (thesis: "the approximations grow alike as the scale grows")
        for (Eigen::Index c = 1; c < 16; ++c) CHECK(error.meanRelativeError[c] <= error.meanRelativeError[c - 1] + 1e-12);
        CHECK(error.meanRelativeError[15] < error.meanRelativeError[0]);
        // ... but not to nothing: the emotional axis differs in its slow parts (the amplitude
        // component), so some DOF stay far apart at scale 16 - why 5.4.2 turns to Fourier series
        CHECK(error.relativeError.row(15).maxCoeff() > 0.1);
        // scale 1's approximation is nearly the signal: its error is the relative difference of the axes
        const Eigen::MatrixXd& functional = (*axes)->function(cell.function)->basis->coordinates;
        const Eigen::MatrixXd& emotional = cell.extracted.emotionalOnFunctionalTime;
        for (Eigen::Index q = 0; q < 6; ++q)
            CHECK(error.relativeError(0, q) ==
                  Approx((emotional.col(q) - functional.col(q)).norm() / functional.col(q).norm()).epsilon(0.1));
    }
}

TEST_CASE("the chain runs only the stages the results asked for read, with the same results", "[pipeline][chain]")
{
    // The peer: the whole chain (every stage), with the decomposition of the preprocessed takes,
    // run once for every section (the sections run only what they need).
    ChainParameters parameters;
    parameters.decompose.input = DecomposeInput::Preprocessed;
    parameters.decompose.method = DecomposeMethod::LeastSquares;
    static const Result<ChainResult> whole = runChain(demo(), parameters, nullptr);
    REQUIRE(whole.ok());
    REQUIRE(whole->normalised);
    REQUIRE(whole->axes);

    SECTION("the decomposition of the preprocessed takes, without normalisation")
    {
        ChainOptions options;
        options.normalisation = options.axes = options.fluctuations = false;
        std::vector<Stage> ran;
        options.progress = [&ran](Stage stage, double) {
            if (ran.empty() || ran.back() != stage) ran.push_back(stage);
        };
        auto chain = runChain(demo(), parameters, nullptr, options);
        REQUIRE(chain.ok());
        CHECK_FALSE(chain->normalised);
        CHECK_FALSE(chain->fluctuations);
        CHECK_FALSE(chain->axes);
        CHECK(ran == std::vector<Stage>{Stage::Import, Stage::Preprocess, Stage::Decompose});
        REQUIRE(chain->decomposed);
        REQUIRE(chain->decomposed->components.functions.size() == whole->decomposed->components.functions.size());
        for (std::size_t f = 0; f < chain->decomposed->components.functions.size(); ++f)
            CHECK(chain->decomposed->components.functions[f].values == whole->decomposed->components.functions[f].values);
    }
    SECTION("decomposing the normalised takes normalises them, though normalisation was not asked for")
    {
        ChainParameters normalisedInput = parameters;
        normalisedInput.decompose.input = DecomposeInput::Normalised;
        ChainOptions options;
        options.normalisation = options.axes = false;
        auto chain = runChain(demo(), normalisedInput, nullptr, options);
        REQUIRE(chain.ok());
        REQUIRE(chain->normalised);
        REQUIRE(chain->decomposed);
        CHECK(chain->fluctuations);
        CHECK(chain->normalised->normalised.takes.front().values == whole->normalised->normalised.takes.front().values);
    }
    SECTION("the axes alone: normalisation, no decomposition")
    {
        ChainOptions options;
        options.normalisation = options.decomposition = options.fluctuations = false;
        auto chain = runChain(demo(), parameters, nullptr, options);
        REQUIRE(chain.ok());
        CHECK_FALSE(chain->decomposed);
        CHECK_FALSE(chain->fluctuations);
        REQUIRE(chain->normalised);
        REQUIRE(chain->axes);
        REQUIRE(chain->axes->cells.size() == whole->axes->cells.size());
        for (std::size_t c = 0; c < chain->axes->cells.size(); ++c)
            CHECK(chain->axes->cells[c].approximation.relativeError == whole->axes->cells[c].approximation.relativeError);
    }
    SECTION("the fluctuations ask for the decomposition")
    {
        ChainOptions options;
        options.normalisation = options.decomposition = options.axes = false;
        auto chain = runChain(demo(), parameters, nullptr, options);
        REQUIRE(chain.ok());
        REQUIRE(chain->decomposed);
        REQUIRE(chain->fluctuations);
        CHECK_FALSE(chain->normalised);
    }
}
