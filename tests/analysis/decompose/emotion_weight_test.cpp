#include "analysis/decompose/emotion_weight.h"
#include "tests/analysis/decompose/test_corpus.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

TEST_CASE("emotion weight 0 gives the function component and 1 the cell mean")
{
    const auto known = bunraku::test::knownComponentsCorpus();
    auto d = decomposeLeastSquares(known.corpus);
    REQUIRE(d.ok());
    auto zero = weightEmotion(*d, "walk", "cold", 0.0);
    REQUIRE(zero.ok());
    CHECK((zero->values - known.y[1]).cwiseAbs().maxCoeff() < 1e-12);
    auto one = weightEmotion(*d, "walk", "cold", 1.0);
    REQUIRE(one.ok());
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(one->values.rows(), one->values.cols());
    const auto takes = known.corpus.cell("walk", "cold");
    for (const Take* take : takes) mean += take->values;
    mean /= double(takes.size());
    CHECK((one->values - mean).cwiseAbs().maxCoeff() < 1e-12);
    CHECK(one->labels.function == "walk");
    CHECK(one->labels.emotion == "cold");
    CHECK(one->channels == known.corpus.takes.front().channels);
    CHECK(validateTake(*one).ok());
}

TEST_CASE("emotion weight 2.5 emphasises z linearly")
{
    const auto known = bunraku::test::knownComponentsCorpus();
    auto d = decomposeLeastSquares(known.corpus);
    REQUIRE(d.ok());
    auto take = weightEmotion(*d, "bow", "warm", 2.5);
    REQUIRE(take.ok());
    CHECK((take->values - (known.y[0] + 2.5 * known.z[0][1])).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("emotion weights outside [0, 3] and unknown labels are errors")
{
    const auto known = bunraku::test::knownComponentsCorpus(20, 2, 1);
    auto d = decomposeLeastSquares(known.corpus);
    REQUIRE(d.ok());
    CHECK_FALSE(weightEmotion(*d, "bow", "warm", 3.5).ok());
    CHECK_FALSE(weightEmotion(*d, "bow", "warm", -0.1).ok());
    auto unknown = weightEmotion(*d, "bow", "angry", 1.0);
    REQUIRE_FALSE(unknown.ok());
    CHECK(unknown.error().message.find("warm") != std::string::npos); // lists what exists
    CHECK_FALSE(weightEmotion(*d, "dance", "warm", 1.0).ok());
}
