#include "analysis/core/puppet_layout.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

using namespace bunraku::analysis;
using namespace bunraku::analysis::preprocess;

namespace {

/// The first take frame whose cell time differs from its start value: where the motion begins.
int trueMotionStart(const synth::TakeTruth& take)
{
    for (Eigen::Index t = 1; t < take.takeToCell.size(); ++t)
        if (take.takeToCell(t) != take.takeToCell(0)) return int(t);
    return 0;
}

/// One take of the demo corpus after start alignment, against the ground truth.
struct AlignedTake {
    std::string cell;
    int takeIndex = 0;
    int referenceIndex = 0;
    int lateStart = 0;          ///< TakeTruth::lateStartFrames
    int referenceLateStart = 0; ///< the cell reference's
    int trueShift = 0;          ///< trueMotionStart(take) - trueMotionStart(reference)
    int estimatedShift = 0;     ///< TakeReport::shiftFrames (0 for the reference)
};

std::vector<AlignedTake> alignDemo(std::uint64_t seed, StartAlignMethod method, int referenceTakeIndex = 0,
                                   PreprocessOptions options = {})
{
    synth::DemoOptions demoOptions;
    demoOptions.seed = seed;
    const synth::DemoCorpus demo = synth::generateDemoCorpus(demoOptions);
    options.alignMethod = method;
    options.referenceTakeIndex = referenceTakeIndex;
    auto result = preprocessCorpus(demo.corpus, options);
    REQUIRE(result.ok());
    const PreprocessReport& report = result->report;
    REQUIRE(report.timeReferences.size() == demo.truth.cells.size());
    std::vector<AlignedTake> rows;
    for (std::size_t i = 0; i < demo.corpus.takes.size(); ++i) {
        const TakeLabels& labels = demo.corpus.takes[i].labels;
        const CellTimeReference* reference = nullptr;
        for (const auto& cell : report.timeReferences)
            if (cell.function == labels.function && cell.emotion == labels.emotion) reference = &cell;
        REQUIRE(reference != nullptr);
        TakeLabels referenceLabels = labels;
        referenceLabels.takeIndex = reference->takeIndex;
        const synth::TakeTruth* own = demo.truth.take(labels);
        const synth::TakeTruth* ref = demo.truth.take(referenceLabels);
        REQUIRE(own != nullptr);
        REQUIRE(ref != nullptr);
        CHECK(report.takes[i].isTimeReference == (labels.takeIndex == reference->takeIndex));
        rows.push_back({labels.function + "/" + labels.emotion, labels.takeIndex, reference->takeIndex,
                        own->lateStartFrames, ref->lateStartFrames, trueMotionStart(*own) - trueMotionStart(*ref),
                        report.takes[i].shiftFrames});
        // the coarser truth agrees with the finer one
        CHECK(rows.back().trueShift == own->lateStartFrames - ref->lateStartFrames);
    }
    return rows;
}

/// A noisy take (the demo's sensor noise) that holds still until `start`, then bows: the head
/// and shoulder pitch 40 and 25 deg over 8 frames while positions move by at most 0.5 cm.
Take noisyBow(Eigen::Index frames, int start, std::uint64_t seed)
{
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values = Eigen::MatrixXd::Zero(frames, kPuppetChannelCount);
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    for (Eigen::Index t = 0; t < frames; ++t) {
        const double s = std::clamp((double(t) - start) / 8.0, 0.0, 1.0);
        const double bow = 0.5 * (1.0 - std::cos(M_PI * s));
        take.values(t, puppetChannel(0, Dof::Pitch)) = 40.0 * bow;
        take.values(t, puppetChannel(1, Dof::Pitch)) = 25.0 * bow;
        take.values(t, puppetChannel(0, Dof::X)) = 0.5 * bow;
        for (int c = 0; c < kPuppetChannelCount; ++c)
            take.values(t, c) += gaussian(random) * (c % 6 < 3 ? 0.1 : 0.2);
    }
    take.labels = TakeLabels{"greeting", "none", 1, ""};
    return take;
}

} // namespace

TEST_CASE("activity and departure weigh a rotation in cm per degree and ignore angle wraps")
{
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values = Eigen::MatrixXd::Zero(3, kPuppetChannelCount);
    take.values(0, puppetChannel(0, Dof::Yaw)) = 175.0;
    take.values.block(1, puppetChannel(0, Dof::Yaw), 2, 1).setConstant(-175.0); // +10 deg across the wrap
    take.values(2, puppetChannel(2, Dof::X)) = 3.0;
    take.values(2, puppetChannel(2, Dof::Y)) = 4.0;
    const double c = kDefaultCmPerDegree;
    const Eigen::VectorXd raw = rawActivity(take);
    CHECK(raw[0] == 0.0);
    CHECK(raw[1] == Approx(10.0 * c));
    CHECK(raw[2] == Approx(5.0));
    ActivityOptions unsmoothed;
    unsmoothed.smoothingFrames = 1;
    const Eigen::VectorXd departure = departureSignal(take, unsmoothed);
    CHECK(departure[1] == Approx(10.0 * c));
    CHECK(departure[2] == Approx(10.0 * c + 5.0)); // two parts moved: head turned, arm shifted
    CHECK(activitySignal(take)[1] == Approx((raw[0] + raw[1] + raw[2]) / 3.0));
    CHECK(rawActivity(take, 0.0)[1] == 0.0);
}

TEST_CASE("a bow that is mostly rotation is found under sensor noise")
{
    const Take early = noisyBow(40, 3, 11);
    for (int late : {3, 6, 10, 14}) {
        INFO("late start " << late);
        const Take shifted = noisyBow(40, late, 100 + std::uint64_t(late));
        PreprocessOptions options;
        CHECK(estimateStartShift(shifted, early, options) == late - 3);
        // the noise alone stays below the onset threshold: the onset is not in the held frames
        CHECK(onsetTime(activitySignal(shifted), options.onsetFraction) > double(late) - 1.0);
    }
}

TEST_CASE("the automatic time reference is a long take with the median onset")
{
    std::vector<ReferenceCandidate> candidates{{101, 4.5}, {106, 9.5}, {90, 1.0}, {104, 4.0}, {102, 3.2}};
    // 90 frames is not long (< 0.95 * 106); onsets of the others 3.2 4.0 4.5 9.5: lower median 4.0
    CHECK(chooseTimeReference(candidates) == 3);
    CHECK(chooseTimeReference(candidates, 0.0) == 3);     // every take counts: 1.0 3.2 4.0 4.5 9.5
    candidates[0].onset = 4.0;
    CHECK(chooseTimeReference(candidates) == 3);          // tie of onsets: the longer take
    candidates[3].frames = 100;
    CHECK(chooseTimeReference(candidates) == 0);
    CHECK(chooseTimeReference({{50, 7.0}}) == 0);
    CHECK(chooseTimeReference({}) == -1);
}

TEST_CASE("onset alignment recovers every late start of the demo corpus within a frame")
{
    for (std::uint64_t seed : {1, 2, 3}) {
        for (const AlignedTake& row : alignDemo(seed, StartAlignMethod::Onset)) {
            INFO("seed " << seed << " " << row.cell << " take " << row.takeIndex << " (reference take "
                         << row.referenceIndex << ", late start " << row.lateStart << ")");
            CHECK(std::abs(row.estimatedShift - row.trueShift) <= 1);
            // the automatic reference of a cell (the median onset) is never its late-start take
            CHECK(row.referenceLateStart == 0);
        }
    }
}

TEST_CASE("cross-correlation of the start edges recovers the demo corpus's late starts within two frames")
{
    int offByTwo = 0, takes = 0;
    for (std::uint64_t seed : {1, 2, 3}) {
        for (const AlignedTake& row : alignDemo(seed, StartAlignMethod::CrossCorrelation)) {
            INFO("seed " << seed << " " << row.cell << " take " << row.takeIndex << " (reference take "
                         << row.referenceIndex << ", late start " << row.lateStart << ")");
            CHECK(std::abs(row.estimatedShift - row.trueShift) <= 2);
            offByTwo += std::abs(row.estimatedShift - row.trueShift) > 1;
            ++takes;
        }
    }
    // coarser than the onset method (a few takes off by 2), but no take is missed by more
    CHECK(offByTwo * 10 <= takes);
}

TEST_CASE("a named late-start reference take gives negative shifts to the others")
{
    // seed 1: serving-tea/none starts take 1 seven frames late (review of issue 2)
    const auto rows = alignDemo(1, StartAlignMethod::Onset, 1);
    int checked = 0;
    for (const AlignedTake& row : rows) {
        INFO(row.cell << " take " << row.takeIndex);
        CHECK(row.referenceIndex == 1);
        CHECK(std::abs(row.estimatedShift - row.trueShift) <= 1);
        if (row.referenceLateStart > 0 && row.takeIndex != 1) {
            CHECK(row.estimatedShift < 0);
            ++checked;
        }
    }
    CHECK(checked > 0);
}

TEST_CASE("across seeds, onset alignment finds every take's start within a frame, xcorr within two", "[preprocess][demo]")
{
    for (std::uint64_t seed : {1, 2, 3}) {
        const auto onset = alignDemo(seed, StartAlignMethod::Onset);
        const auto xcorr = alignDemo(seed, StartAlignMethod::CrossCorrelation);
        REQUIRE(onset.size() == xcorr.size());
        REQUIRE_FALSE(onset.empty());
        for (std::size_t i = 0; i < onset.size(); ++i) {
            const auto& row = onset[i];
            INFO("seed " << seed << ", " << row.cell << " take " << row.takeIndex << " (reference " << row.referenceIndex
                         << "): true shift " << row.trueShift << ", onset " << row.estimatedShift << ", xcorr "
                         << xcorr[i].estimatedShift);
            // xcorr's shift is against its own reference, which is the same (chosen by onset)
            CHECK(std::abs(row.estimatedShift - row.trueShift) <= 1);
            CHECK(std::abs(xcorr[i].estimatedShift - row.trueShift) <= 2);
        }
    }
}
