// What the stages reuse instead of recomputing gives the bits of computing it again: the average
// take from the normalisation's matchings, and the digests that compare whole stage results.
#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/stage_digest.h"

#include "analysis/normalise/average_take.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;

namespace {

const PreprocessOutput& preprocessedDemo()
{
    static const PreprocessOutput output = [] {
        auto made = runPreprocess(synth::generateDemoCorpus().corpus, {});
        REQUIRE(made.ok());
        return std::move(made).value();
    }();
    return output;
}

AverageOptions averageOptionsOf(const CellNormalisation& cell, const std::vector<const Take*>& takes, const NormaliseParameters& p)
{
    AverageOptions options;
    options.normalise = p.options();
    for (std::size_t k = 0; k < takes.size(); ++k) {
        const bool member = std::find(cell.averageMembers.begin(), cell.averageMembers.end(), takes[k]->labels.takeIndex) !=
                            cell.averageMembers.end();
        if (!member) options.excludedTakes.push_back(int(k));
        if (p.averageBase > 0 ? takes[k]->labels.takeIndex == p.averageBase : int(k) == cell.suggestion.takeIndex)
            options.baseTake = int(k);
    }
    return options;
}

} // namespace

TEST_CASE("the normalise stage's average takes and normalisations are those computed on their own, bit for bit",
          "[pipeline][normalise]")
{
    const Corpus& corpus = preprocessedDemo().corpus;
    for (int base : {0, 2}) { // the suggested reference as the base (matched once), or take 2 (matched twice)
        NormaliseParameters parameters;
        parameters.averageBase = base;
        auto stage = runNormalise(corpus, parameters);
        REQUIRE(stage.ok());
        for (const auto& cell : stage->cells) {
            INFO(cell.function << "/" << cell.emotion << ", average base " << base);
            const auto takes = corpus.cell(cell.function, cell.emotion);
            auto average = averageTake(takes, averageOptionsOf(cell, takes, parameters));
            REQUIRE(average.ok());
            CHECK(cell.average.values == average->values);
            CHECK(cell.average.labels == average->labels);
            auto direct = normaliseTakes(*takes[std::size_t(cell.suggestion.takeIndex)], takes, parameters.options());
            REQUIRE(direct.ok());
            for (std::size_t k = 0; k < takes.size(); ++k) {
                CHECK(cell.normalisations[k].normalised.values == (*direct)[k].normalised.values);
                CHECK(cell.normalisations[k].correspondence == (*direct)[k].correspondence);
                CHECK(cell.normalisations[k].cost == (*direct)[k].cost);
            }
        }
    }
}

TEST_CASE("an average from given matchings needs one on the base's frames per take", "[pipeline][normalise]")
{
    const auto takes = preprocessedDemo().corpus.cell("greeting", "hostile");
    AverageOptions options;
    options.baseTake = 1;
    auto toBase = normaliseTakes(*takes[1], takes, options.normalise);
    REQUIRE(toBase.ok());
    auto reused = averageTakeFrom(takes, options, *toBase);
    auto computed = averageTake(takes, options);
    REQUIRE(reused.ok());
    REQUIRE(computed.ok());
    CHECK(reused->values == computed->values);

    auto fewer = *toBase;
    fewer.pop_back();
    CHECK_THAT(averageTakeFrom(takes, options, fewer).error().message, Catch::Contains("4 normalisations for 5 takes"));
    auto shorter = *toBase;
    shorter[3].correspondence.conservativeResize(shorter[3].correspondence.rows() - 1, Eigen::NoChange);
    CHECK_THAT(averageTakeFrom(takes, options, shorter).error().message, Catch::Contains("not on the base take's frames"));
    options.baseTake = 7;
    CHECK_THAT(averageTakeFrom(takes, options, *toBase).error().message, Catch::Contains("base take index 7"));
}

TEST_CASE("stage digests are equal for equal results and change with any bit", "[pipeline][digest]")
{
    auto input = makeCorpusInput(synth::generateDemoCorpus().corpus);
    REQUIRE(input.ok());
    ChainOptions options;
    options.fluctuations = false;
    auto first = runChain(*input, {}, nullptr, options);
    auto second = runChain(*input, {}, nullptr, options);
    REQUIRE(first.ok());
    REQUIRE(second.ok());
    const ChainDigest digest = chainDigest(*first);
    CHECK(digest == chainDigest(*second));
    CHECK(digest.fluctuations.empty());
    CHECK(digest.text().find("fluctuations") == std::string::npos);
    CHECK_THAT(digest.text(), Catch::StartsWith("preprocess=") && Catch::Contains(" normalise=") && Catch::Contains(" axes="));

    NormaliseOutput normalised = *first->normalised;
    CHECK(resultDigest(normalised) == digest.normalise);
    double& value = normalised.cells[3].normalisations[2].normalised.values(40, 5);
    value = std::nextafter(value, 1e300); // one bit of one value of one take
    CHECK(resultDigest(normalised) != digest.normalise);

    DecomposeOutput decomposed = *first->decomposed;
    decomposed.km2o->meanErrorPercent[4] = -decomposed.km2o->meanErrorPercent[4];
    CHECK(resultDigest(decomposed) != digest.decompose);
    AxisOutput axes = *first->axes;
    axes.cells[1].extracted.gains.phrases[0].dofs[2].g1 *= 1.0 + 1e-15;
    CHECK(resultDigest(axes) != digest.axes);
}
