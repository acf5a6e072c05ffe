// Digests that compare whole stage results bit for bit.
#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/stage_digest.h"

#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;

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
