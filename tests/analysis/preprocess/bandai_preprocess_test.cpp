// Thesis 2.2 preprocessing on the real Bandai waves (read in place): continuous angles without
// branch jumps, and the full skeleton through every step. The checks compare preprocessed with
// raw takes, so they hold for whatever part calibration the importer applies.
#include "analysis/core/angle_channels.h"
#include "analysis/core/rotation.h"
#include "analysis/preprocess/preprocess.h"
#include "tests/support/bandai_data.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numbers>

using namespace bunraku::analysis;
using namespace bunraku::analysis::preprocess;
using bunraku::test::bandaiAvailable;

namespace {

/// Raw frame shown by preprocessed frame t (padding repeats the last frame, then the shift).
Eigen::Index rawFrame(Eigen::Index t, const TakeReport& report, Eigen::Index paddedFrames, Eigen::Index rawFrames)
{
    const Eigen::Index padded = std::clamp<Eigen::Index>(t + report.shiftFrames, 0, paddedFrames - 1);
    return std::min(padded, rawFrames - 1);
}

} // namespace

TEST_CASE("preprocessed Bandai waves have no Euler step the rotation does not make whatever branch they were written on")
{
    if (!bandaiAvailable(bunraku::test::bandaiWaveFiles())) return;
    const Corpus corpus = bunraku::test::bandaiWaveCorpus();
    // The same corpus with every part's angles on other branches frame by frame.
    Corpus jumpy = corpus;
    for (Take& take : jumpy.takes) take = bunraku::test::onOtherBranches(take);
    int rawUnexplained = 0;
    for (const Take& take : jumpy.takes) rawUnexplained += bunraku::test::unexplainedEulerSteps(take);
    CHECK(rawUnexplained > 100); // the rewritten takes jump everywhere

    auto result = preprocessCorpus(corpus);
    auto fromJumpy = preprocessCorpus(jumpy);
    REQUIRE(result.ok());
    REQUIRE(fromJumpy.ok());
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const Take& take = result->corpus.takes[i];
        const Take& other = fromJumpy->corpus.takes[i];
        INFO(take.displayName());
        CHECK(bunraku::test::unexplainedEulerSteps(take) == 0);
        CHECK(bunraku::test::unexplainedEulerSteps(other) == 0);
        // the branch the input was written on changes no orientation
        double worst = 0.0;
        for (const auto& part : sixDofParts(take)) {
            const auto a = partRotations(take, part);
            const auto b = partRotations(other, part);
            for (std::size_t f = 0; f < a.size(); ++f) worst = std::max(worst, rotationDistance(a[f], b[f]));
        }
        CHECK(worst < 1e-9);
        CHECK((take.values.leftCols(3) - other.values.leftCols(3)).cwiseAbs().maxCoeff() < 1e-9);
    }
}

TEST_CASE("the full skeleton goes through every preprocessing step with its take")
{
    if (!bandaiAvailable(bunraku::test::bandaiWaveFiles())) return;
    const Corpus corpus = bunraku::test::bandaiWaveCorpus();
    auto result = preprocessCorpus(corpus);
    REQUIRE(result.ok());
    const Eigen::Index padded = result->report.paddedFrames;
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        const Take& raw = corpus.takes[i];
        const Take& take = result->corpus.takes[i];
        const TakeReport& report = result->report.takes[i];
        INFO(take.displayName() << ": shift " << report.shiftFrames << ", heading " << report.headingOffsetDeg);
        REQUIRE(take.skeleton);
        CHECK(take.skeleton->frameCount() == take.frameCount());
        CHECK(validateTake(take).ok());
        CHECK(bunraku::test::maxBoneLengthChange(*take.skeleton) < 1e-9);
        // Every bound part keeps its relation to the channels: the rotation from the channels to
        // the skeleton's part is what it was at the raw frame shown (the heading turn, the
        // padding and the shift act on both alike).
        const Eigen::Quaterniond turn(Eigen::AngleAxisd(report.headingOffsetDeg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()));
        double worst = 0.0;
        for (const auto& part : sixDofParts(take)) {
            if (!take.skeleton->partPose(0, part.part)) continue;
            const auto channels = partRotations(take, part);
            const auto rawChannels = partRotations(raw, part);
            for (Eigen::Index t = 0; t < take.frameCount(); t += 7) {
                const Eigen::Index s = rawFrame(t, report, padded, raw.frameCount());
                const Eigen::Quaterniond now = channels[std::size_t(t)].conjugate() * take.skeleton->partPose(t, part.part)->rotation;
                const Eigen::Quaterniond before = rawChannels[std::size_t(s)].conjugate() * raw.skeleton->partPose(s, part.part)->rotation;
                worst = std::max(worst, rotationDistance(now, before));
                // and the skeleton's part is the raw one turned by the heading offset
                worst = std::max(worst, rotationDistance(take.skeleton->partPose(t, part.part)->rotation,
                                                         turn * raw.skeleton->partPose(s, part.part)->rotation));
            }
        }
        CHECK(worst < 1e-6);
    }
}

TEST_CASE("as rotation coordinates the preprocessed Bandai waves step no further than their parts turn", "[angles][display]")
{
    if (!bandaiAvailable(bunraku::test::bandaiWaveFiles())) return;
    auto result = preprocessCorpus(bunraku::test::bandaiWaveCorpus());
    REQUIRE(result.ok());
    const Take& first = result->corpus.takes.front();
    double eulerWorst = 0.0;
    for (const Take& take : result->corpus.takes) {
        INFO(take.displayName());
        // Shown about the first take's mean orientations, as the graphs show take B beside A.
        const Take shown = rotationCoordinateTake(take, &first);
        CHECK((shown.values.leftCols(3) - take.values.leftCols(3)).cwiseAbs().maxCoeff() == 0.0);
        const RotationChart chart = meanPartChart({&first});
        CHECK(shown.values == rotationCoordinates(take, chart));
        for (const auto& part : sixDofParts(take)) {
            const auto turns = partRotations(take, part);
            for (Eigen::Index f = 1; f < take.frameCount(); ++f) {
                const double turn = rotationDistance(turns[std::size_t(f - 1)], turns[std::size_t(f)]) * 180.0 / std::numbers::pi;
                const auto step = [&](const Take& t) {
                    return (t.values.block(f, part.firstChannel + 3, 1, 3) - t.values.block(f - 1, part.firstChannel + 3, 1, 3)).norm();
                };
                eulerWorst = std::max(eulerWorst, step(take) - turn);
                // A rotation vector of length r about its base moves at most (r/2) / sin(r/2) times
                // as far as the orientation turns: below pi/2 = 1.571 for |r| <= 180 deg.
                CHECK(step(shown) <= 1.6 * turn + 1e-9);
            }
        }
    }
    // The Euler numbers of the same frames sweep much further than the turn (gimbal regions).
    CHECK(eulerWorst > 45.0);
}
