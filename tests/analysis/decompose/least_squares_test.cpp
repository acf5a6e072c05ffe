#include "analysis/decompose/least_squares.h"
#include "tests/analysis/decompose/test_corpus.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

TEST_CASE("least squares recovers the known function, emotion and fluctuation components")
{
    const auto known = bunraku::test::knownComponentsCorpus();
    auto result = decomposeLeastSquares(known.corpus);
    REQUIRE(result.ok());
    const Decomposition& d = *result;
    REQUIRE(d.functions.size() == 2);
    REQUIRE(d.emotions.size() == 6);
    CHECK(d.neutralEmotion == "calm");
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK((d.functions[i].values - known.y[i]).cwiseAbs().maxCoeff() < 1e-12);
        const std::vector<std::string> emotions{"calm", "warm", "cold"};
        for (std::size_t j = 0; j < 3; ++j) {
            const auto* z = d.emotion(d.functions[i].function, emotions[j]);
            REQUIRE(z != nullptr);
            CHECK((z->values - known.z[i][j]).cwiseAbs().maxCoeff() < 1e-12);
        }
    }
    for (const auto& eta : d.fluctuations) {
        const Take* take = known.corpus.find(eta.labels.function, eta.labels.emotion, eta.labels.takeIndex);
        REQUIRE(take != nullptr);
        const auto* y = d.function(eta.labels.function);
        const auto* z = d.emotion(eta.labels.function, eta.labels.emotion);
        CHECK((y->values + z->values + eta.values - take->values).cwiseAbs().maxCoeff() < 1e-12);
    }
}

TEST_CASE("the neutral emotion label comes from the corpus, not from the code")
{
    auto known = bunraku::test::knownComponentsCorpus(20, 2, 1);
    known.corpus.neutralEmotion = "none"; // no take carries it
    auto result = decomposeLeastSquares(known.corpus);
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().message.find("'none'") != std::string::npos);
}

TEST_CASE("takes of different lengths are rejected with a message naming the take")
{
    auto known = bunraku::test::knownComponentsCorpus(20, 2, 1);
    known.corpus.takes[3].values.conservativeResize(15, Eigen::NoChange);
    auto result = decomposeLeastSquares(known.corpus);
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().message.find("15 frames") != std::string::npos);
}
