// Function / emotion decomposition (thesis 4.3, 4.4) and emotion weights (eq. 4.45) of the real
// Bandai waves (read in place and labelled here): every weighted take has continuous angles and
// the full skeleton, computed on rotations, whatever branch or part frames the takes use.
#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/preprocess/preprocess.h"
#include "tests/support/bandai_data.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using bunraku::test::bandaiAvailable;

namespace {

Corpus preprocessed(const Corpus& corpus)
{
    auto result = preprocess::preprocessCorpus(corpus);
    REQUIRE(result.ok());
    return std::move(result->corpus);
}

double worstPartRotation(const Take& a, const Take& b, const std::vector<Eigen::Quaterniond>& calibration = {})
{
    double worst = 0.0;
    const auto parts = sixDofParts(a);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const auto ra = partRotations(a, parts[p]);
        const auto rb = partRotations(b, parts[p]);
        const Eigen::Quaterniond c = calibration.empty() ? Eigen::Quaterniond::Identity() : calibration[p];
        for (std::size_t f = 0; f < ra.size(); ++f) worst = std::max(worst, rotationDistance(ra[f] * c, rb[f]));
    }
    return worst;
}

double worstJoint(const SkeletalMotion& a, const SkeletalMotion& b)
{
    double worst = 0.0;
    for (Eigen::Index f = 0; f < a.frameCount(); ++f)
        for (int j = 0; j < a.jointSlots(); ++j) {
            worst = std::max(worst, rotationDistance(a.rotation(f, j), b.rotation(f, j)));
            worst = std::max(worst, (a.translation(f, j) - b.translation(f, j)).norm());
        }
    return worst;
}

} // namespace

TEST_CASE("emotion weights 0 1 and 2 of the Bandai waves give continuous angles and the full skeleton")
{
    if (!bandaiAvailable(bunraku::test::bandaiWaveFiles())) return;
    const Corpus corpus = preprocessed(bunraku::test::bandaiWaveCorpus());
    auto decomposition = decomposeLeastSquares(corpus);
    REQUIRE(decomposition.ok());
    REQUIRE(decomposition->skeleton);
    for (const std::string emotion : {"active", "exhausted"}) {
        const auto cell = corpus.cell("wave", emotion);
        for (double a : {0.0, 1.0, 2.0}) {
            INFO(emotion << " a = " << a);
            auto take = weightEmotion(*decomposition, "wave", emotion, a);
            REQUIRE(take.ok());
            CHECK(validateTake(*take).ok());
            CHECK(bunraku::test::unexplainedEulerSteps(*take) == 0);
            REQUIRE(take->skeleton);
            CHECK(take->skeleton->frameCount() == take->frameCount());
            CHECK(bunraku::test::maxBoneLengthChange(*take->skeleton) < 1e-9);
            if (a != 1.0) continue;
            // a = 1: each joint's rotation is the cell's mean (of its rotation vectors about the
            // function's mean rotation), inside the spread of the cell's takes
            for (Eigen::Index f = 0; f < take->frameCount(); f += 9)
                for (int j = 0; j < take->skeleton->jointSlots(); ++j) {
                    double spread = 0.0;
                    std::vector<Eigen::Quaterniond> rotations;
                    for (const Take* member : cell) rotations.push_back(member->skeleton->rotation(f, j));
                    const Eigen::Quaterniond mean = meanRotation(rotations);
                    for (const auto& q : rotations) spread = std::max(spread, rotationDistance(q, mean));
                    CHECK(rotationDistance(take->skeleton->rotation(f, j), mean) <= spread + 1e-6);
                }
        }
    }
    // y as a take: Euler angles and the skeleton
    auto y = functionComponentTake(*decomposition, "wave");
    REQUIRE(y.ok());
    CHECK(bunraku::test::unexplainedEulerSteps(*y) == 0);
    REQUIRE(y->skeleton);
}

TEST_CASE("a = 0 on a cell of identical takes returns them")
{
    if (!bandaiAvailable({"wave-right-hand_normal_002.bvh", "wave-right-hand_active_003.bvh"})) return;
    const Take normal = bunraku::test::readBandai("wave-right-hand_normal_002.bvh");
    Take active = bunraku::test::readBandai("wave-right-hand_active_003.bvh");
    Corpus corpus;
    corpus.neutralEmotion = "normal";
    corpus.rateHz = normal.rateHz;
    for (int k = 1; k <= 3; ++k) {
        Take copy = normal;
        copy.labels = {"wave", "normal", k, "copy"};
        corpus.takes.push_back(copy);
        Take other = active;
        other.labels = {"wave", "active", k, "copy"};
        corpus.takes.push_back(other);
    }
    corpus = preprocessed(corpus);
    const Take& neutral = *corpus.cell("wave", "normal").front();
    const Take& emotional = *corpus.cell("wave", "active").front();
    for (bool km2o : {false, true}) {
        INFO((km2o ? "KM2O" : "least squares"));
        Decomposition decomposition;
        if (km2o) {
            Km2oDecompositionOptions options;
            options.correlationLength = 2;
            auto result = decomposeKm2o(corpus, options);
            REQUIRE(result.ok());
            decomposition = std::move(result->components);
        } else {
            auto result = decomposeLeastSquares(corpus);
            REQUIRE(result.ok());
            decomposition = std::move(result).value();
        }
        REQUIRE(decomposition.skeleton);
        auto y = weightEmotion(decomposition, "wave", "active", 0.0);
        REQUIRE(y.ok());
        CHECK(worstPartRotation(*y, neutral) < 1e-9);
        CHECK((y->values.leftCols(3) - neutral.values.leftCols(3)).cwiseAbs().maxCoeff() < 1e-9);
        CHECK((y->values - neutral.values).cwiseAbs().maxCoeff() < 1e-6); // on the neutral take's branch
        CHECK(worstJoint(*y->skeleton, *neutral.skeleton) < 1e-9);
        auto x = weightEmotion(decomposition, "wave", "active", 1.0);
        REQUIRE(x.ok());
        CHECK(worstPartRotation(*x, emotional) < 1e-9);
        CHECK(worstJoint(*x->skeleton, *emotional.skeleton) < 1e-9);
    }
}

TEST_CASE("the weighted Bandai takes depend neither on the Euler branch nor on the part frames")
{
    if (!bandaiAvailable(bunraku::test::bandaiWaveFiles())) return;
    const Corpus raw = bunraku::test::bandaiWaveCorpus();
    Corpus jumpy = raw, recalibrated = raw;
    for (Take& take : jumpy.takes) take = bunraku::test::onOtherBranches(take);
    for (Take& take : recalibrated.takes) take = bunraku::test::recalibrated(take);
    // the constant part-frame turns recalibrated() applies, recovered from the first frame
    std::vector<Eigen::Quaterniond> calibration;
    for (const auto& part : sixDofParts(raw.takes.front()))
        calibration.push_back(partRotations(raw.takes.front(), part)[0].conjugate() *
                              partRotations(recalibrated.takes.front(), part)[0]);
    auto base = decomposeLeastSquares(preprocessed(raw));
    auto fromJumpy = decomposeLeastSquares(preprocessed(jumpy));
    auto fromRecalibrated = decomposeLeastSquares(preprocessed(recalibrated));
    REQUIRE(base.ok());
    REQUIRE(fromJumpy.ok());
    REQUIRE(fromRecalibrated.ok());
    for (double a : {0.0, 2.0}) {
        const Take x = weightEmotion(*base, "wave", "active", a).value();
        const Take xJumpy = weightEmotion(*fromJumpy, "wave", "active", a).value();
        const Take xRecalibrated = weightEmotion(*fromRecalibrated, "wave", "active", a).value();
        CHECK(worstPartRotation(x, xJumpy) < 1e-9);
        CHECK(worstPartRotation(x, xRecalibrated, calibration) < 1e-9);
        CHECK((x.values.leftCols(3) - xRecalibrated.values.leftCols(3)).cwiseAbs().maxCoeff() < 1e-9);
        CHECK(worstJoint(*x.skeleton, *xJumpy.skeleton) < 1e-9);
    }
}
