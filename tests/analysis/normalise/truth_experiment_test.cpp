#include "analysis/normalise/truth_experiment.h"

#include "analysis/core/puppet_layout.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

TEST_CASE("on the synthetic corpus the optimal wavelet path recovers the true warps within a frame", "[experiment][truth]")
{
    const synth::DemoCorpus demo = synth::generateDemoCorpus();
    auto result = runTruthExperiment(demo.corpus, demo.truth);
    REQUIRE(result.ok());
    CHECK(result->cells == 6);
    CHECK(result->pairs == 24);
    const auto find = [&](const std::string& name) {
        for (const auto& method : result->methods)
            if (method.name == name) return method;
        FAIL("no method " << name);
        return TruthMethodResult{};
    };
    const TruthMethodResult greedy = find("wavelet-greedy");
    const TruthMethodResult optimal = find("wavelet-optimal");
    const TruthMethodResult amplitude = find("amplitude-dp");
    INFO("greedy " << greedy.meanAbsErrorFrames << ", optimal " << optimal.meanAbsErrorFrames << ", amplitude "
                   << amplitude.meanAbsErrorFrames);
    CHECK(optimal.meanAbsErrorFrames < 1.0);
    CHECK(optimal.meanAbsErrorFrames < amplitude.meanAbsErrorFrames);
    CHECK(optimal.meanAbsErrorFrames <= greedy.meanAbsErrorFrames);
    // Coupled arm and hand stay together: their receiver distance stays in the measured range.
    CHECK(optimal.armHandWithinRange > 0.99);
}

TEST_CASE("the truth experiment rejects a corpus without the puppet layout", "[experiment][truth]")
{
    Corpus corpus;
    Take take;
    take.channels = sixDofChannels("axis");
    take.values = Eigen::MatrixXd::Zero(10, 6);
    take.labels = {"greeting", "none", 1, "test"};
    corpus.takes.push_back(take);
    auto result = runTruthExperiment(corpus, synth::DemoGroundTruth{});
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().message.find("puppet") != std::string::npos);
}
