#include "analysis/core/puppet_layout.h"
#include "analysis/preprocess/preprocess.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;
using namespace bunraku::analysis::preprocess;

namespace {

/// A smooth bump of motion lasting 20 frames from `start`: still before and after.
double motion(double t, double start)
{
    if (t < start || t > start + 20.0) return 0.0;
    return 30.0 * (1.0 - std::cos(2.0 * M_PI * (t - start) / 20.0));
}

/// A puppet take whose parts stay still until `start`, then move; positions offset by `offset`.
Take movingTake(Eigen::Index frames, double start, const std::string& function, const std::string& emotion, int k,
                double offset = 0.0)
{
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values = Eigen::MatrixXd::Zero(frames, kPuppetChannelCount);
    for (Eigen::Index t = 0; t < frames; ++t)
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const double m = motion(double(t), start) * (1.0 + 0.3 * p);
            take.values(t, p * 6 + 0) = 10.0 * p + m + offset;
            take.values(t, p * 6 + 1) = 0.5 * m - offset;
            take.values(t, p * 6 + 2) = 100.0 + 0.2 * m + 2.0 * offset;
            take.values(t, p * 6 + 3) = 0.3 * m;
        }
    take.labels = TakeLabels{function, emotion, k, ""};
    return take;
}

} // namespace

TEST_CASE("padding repeats the last frame up to the longest take")
{
    Corpus corpus;
    corpus.takes = {movingTake(20, 2, "f", "none", 1), movingTake(26, 2, "f", "none", 2)};
    PreprocessOptions options;
    options.unwrap = options.alignStart = options.alignPosition = false;
    auto result = preprocessCorpus(corpus, options);
    REQUIRE(result.ok());
    CHECK(result->report.paddedFrames == 26);
    CHECK(result->report.takes[0].framesPadded == 6);
    CHECK(result->report.takes[1].framesPadded == 0);
    const Take& padded = result->corpus.takes[0];
    REQUIRE(padded.frameCount() == 26);
    CHECK(padded.values.topRows(20) == corpus.takes[0].values);
    for (Eigen::Index t = 20; t < 26; ++t) CHECK(padded.values.row(t) == corpus.takes[0].values.row(19));
}

TEST_CASE("unwrapping removes 360-degree jumps and counts them")
{
    Eigen::VectorXd yaw(6);
    yaw << 170, 178, -175, -170, 175, 179;
    CHECK(unwrapDegrees(yaw) == 2);
    Eigen::VectorXd expected(6);
    expected << 170, 178, 185, 190, 175, 179;
    CHECK((yaw - expected).cwiseAbs().maxCoeff() < 1e-12);

    Take take = movingTake(10, 0, "f", "none", 1);
    take.values(5, puppetChannel(2, Dof::Roll)) = 0.0;
    take.values.col(puppetChannel(2, Dof::Roll)) << 0, 100, 179, -100, -1, 120, -120, -1, 100, 179;
    take.values.col(puppetChannel(0, Dof::X)) << 0, 100, 179, -100, -1, 120, -120, -1, 100, 179; // cm: untouched
    const Eigen::VectorXd xBefore = take.values.col(0);
    CHECK(unwrapAngles(take) == 2); // 179 -> -100 and 120 -> -120
    CHECK(take.values.col(0) == xBefore);
    const auto roll = take.values.col(puppetChannel(2, Dof::Roll));
    for (Eigen::Index t = 1; t < roll.size(); ++t) CHECK(std::fabs(roll[t] - roll[t - 1]) <= 180.0);
    CHECK(roll[9] == Approx(179.0 + 720.0));
}

TEST_CASE("both start alignment methods recover a known shift of a signal")
{
    const int shift = GENERATE(-6, -2, 0, 3, 7, 11);
    const auto method = GENERATE(StartAlignMethod::Onset, StartAlignMethod::CrossCorrelation);
    const Take reference = movingTake(60, 12, "f", "none", 1);
    const Take shifted = movingTake(60, 12 + shift, "f", "none", 2);
    PreprocessOptions options;
    options.alignMethod = method;
    CHECK(estimateStartShift(shifted, reference, options) == shift);

    Take aligned = shifted;
    shiftTake(aligned, shift);
    // after the shift the motion starts where the reference's does
    const Eigen::Index late = 30;
    CHECK(aligned.values.row(late) == reference.values.row(late));
}

TEST_CASE("cross-correlation finds the lag of a shifted noisy signal")
{
    Eigen::VectorXd reference(80);
    for (Eigen::Index t = 0; t < 80; ++t) reference[t] = std::exp(-0.5 * std::pow((double(t) - 30.0) / 4.0, 2)) + 0.02 * std::sin(7.3 * double(t));
    for (int lag : {-9, -1, 0, 4, 12}) {
        Eigen::VectorXd signal(80);
        for (Eigen::Index t = 0; t < 80; ++t) signal[t] = reference[std::clamp<Eigen::Index>(t - lag, 0, 79)];
        CHECK(crossCorrelationShift(signal, reference, 20) == lag);
    }
}

TEST_CASE("preprocessing a corpus aligns start times per cell and positions per function")
{
    Corpus corpus;
    corpus.takes = {movingTake(50, 10, "greeting", "none", 1), movingTake(50, 14, "greeting", "none", 2, 5.0),
                    movingTake(44, 8, "greeting", "hostile", 1, -3.0), movingTake(50, 8, "greeting", "hostile", 2),
                    movingTake(50, 10, "tea", "none", 1, 7.0), movingTake(48, 13, "tea", "none", 2, 1.0)};
    PreprocessOptions options;
    options.alignMethod = GENERATE(StartAlignMethod::Onset, StartAlignMethod::CrossCorrelation);
    auto result = preprocessCorpus(corpus, options);
    REQUIRE(result.ok());
    const auto& report = result->report;
    REQUIRE(report.takes.size() == 6);
    CHECK(report.paddedFrames == 50);
    CHECK(report.takes[2].framesPadded == 6);
    CHECK(report.takes[0].isTimeReference);
    CHECK(report.takes[1].shiftFrames == 4);
    // hostile: take 1 (44 frames) is too short to be the automatic reference; take 2 (50) is
    CHECK(report.takes[3].isTimeReference);
    CHECK_FALSE(report.takes[2].isTimeReference);
    CHECK(report.takes[2].shiftFrames == 0);
    CHECK(report.takes[5].shiftFrames == 3);
    REQUIRE(report.timeReferences.size() == 3);
    CHECK(report.timeReferences[0].function == "greeting");
    CHECK(report.timeReferences[0].emotion == "none");
    CHECK(report.timeReferences[0].takeIndex == 1);
    CHECK(report.timeReferences[1].emotion == "hostile");
    CHECK(report.timeReferences[1].takeIndex == 2);
    CHECK(report.timeReferences[1].automatic);
    CHECK(report.timeReferences[2].function == "tea");
    CHECK(report.timeReferences[2].takeIndex == 1);
    CHECK(report.takes[0].isPositionReference);
    CHECK(report.takes[4].isPositionReference);
    CHECK_FALSE(report.takes[2].isPositionReference);

    // every take of a function starts where its reference starts, part by part
    const auto& takes = result->corpus.takes;
    for (std::size_t i : {1, 2, 3})
        for (int p = 0; p < kPuppetPartCount; ++p)
            CHECK((takes[i].values.row(0).segment(p * 6, 3) - takes[0].values.row(0).segment(p * 6, 3)).norm() < 1e-9);
    CHECK((takes[5].values.row(0).segment(0, 3) - takes[4].values.row(0).segment(0, 3)).norm() < 1e-9);
    // the reported offset is what was added
    CHECK(report.takes[1].positionOffsets[0].x() == Approx(-5.0));
    CHECK(report.takes[1].positionOffsets[0].z() == Approx(-10.0));
    // angles are only shifted in time, never translated
    Take shiftedOnly = corpus.takes[1];
    shiftTake(shiftedOnly, report.takes[1].shiftFrames);
    CHECK(takes[1].values.col(3) == shiftedOnly.values.col(3));
    CHECK(validateCorpus(result->corpus).ok());
}

TEST_CASE("each preprocessing step can be switched off")
{
    Corpus corpus;
    corpus.takes = {movingTake(30, 5, "f", "none", 1), movingTake(25, 9, "f", "none", 2, 4.0)};
    corpus.takes[1].values(3, puppetChannel(0, Dof::Yaw)) = 200.0 - 360.0;
    corpus.takes[1].values(4, puppetChannel(0, Dof::Yaw)) = 200.0;
    PreprocessOptions off;
    off.pad = off.unwrap = off.alignStart = off.alignPosition = false;
    auto untouched = preprocessCorpus(corpus, off);
    REQUIRE(untouched.ok());
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        CHECK(untouched->corpus.takes[i].values == corpus.takes[i].values);
        CHECK(untouched->report.takes[i].framesPadded == 0);
        CHECK(untouched->report.takes[i].shiftFrames == 0);
        CHECK(untouched->report.takes[i].anglesUnwrapped == 0);
    }
    PreprocessOptions unwrapOnly = off;
    unwrapOnly.unwrap = true;
    auto unwrapped = preprocessCorpus(corpus, unwrapOnly);
    REQUIRE(unwrapped.ok());
    CHECK(unwrapped->report.takes[1].anglesUnwrapped == 2);
    // -160 -> 200 -> ~0: the spike at frame 4 is one turn away, so it is brought back to -160
    CHECK(unwrapped->corpus.takes[1].values(4, puppetChannel(0, Dof::Yaw)) == Approx(-160.0));
}

TEST_CASE("preprocessing rejects invalid corpora and options and honours cancellation")
{
    Corpus corpus;
    corpus.takes = {movingTake(30, 5, "f", "none", 1), movingTake(30, 5, "f", "none", 1)};
    CHECK_FALSE(preprocessCorpus(corpus).ok()); // duplicate labels
    corpus.takes[1].labels.takeIndex = 2;
    PreprocessOptions bad;
    bad.onsetFraction = 0.0;
    CHECK(preprocessCorpus(corpus, bad).error().code == ErrorCode::InvalidArgument);
    bad = {};
    bad.referenceTakeIndex = -1;
    CHECK(preprocessCorpus(corpus, bad).error().code == ErrorCode::InvalidArgument);
    bad = {};
    bad.quietFraction = 1.5;
    CHECK(preprocessCorpus(corpus, bad).error().code == ErrorCode::InvalidArgument);
    bad = {};
    bad.activity.cmPerDegree = std::nan("");
    CHECK(preprocessCorpus(corpus, bad).error().code == ErrorCode::InvalidArgument);
    std::stop_source stop;
    stop.request_stop();
    RunControl control;
    control.stop = stop.get_token();
    CHECK(preprocessCorpus(corpus, {}, control).error().code == ErrorCode::Cancelled);
}

TEST_CASE("angle channels are brought onto the reference's branch and headings are aligned")
{
    Corpus corpus;
    corpus.takes.push_back(movingTake(40, 5.0, "greeting", "none", 1));
    corpus.takes.push_back(movingTake(40, 5.0, "greeting", "none", 2));
    corpus.takes.push_back(movingTake(40, 5.0, "greeting", "friendly", 1));
    // Take 2 turned by 170 deg as a whole (every yaw channel) and its head yaw one turn up.
    Take& turned = corpus.takes[1];
    for (int p = 0; p < kPuppetPartCount; ++p) turned.values.col(p * 6 + 3).array() += 170.0;
    turned.values.col(3).array() += 360.0;
    // The friendly take's head is turned 40 deg away relative to its body: that must survive.
    corpus.takes[2].values.col(3).array() -= 40.0;

    PreprocessOptions options;
    options.alignStart = false;
    options.alignPosition = false;
    auto result = preprocessCorpus(corpus, options);
    REQUIRE(result.ok());
    const auto& out = result->corpus;
    const auto& report = result->report.takes;
    CHECK(report[1].branchTurns == 1);
    CHECK(report[1].headingOffsetDeg == Approx(-170.0));
    for (int p = 0; p < kPuppetPartCount; ++p)
        CHECK((out.takes[1].values.col(p * 6 + 3) - out.takes[0].values.col(p * 6 + 3)).cwiseAbs().maxCoeff() < 1e-9);
    CHECK(report[2].headingOffsetDeg == Approx(0.0).margin(1e-12));
    CHECK(out.takes[2].values(0, 3) == Approx(out.takes[0].values(0, 3) - 40.0));

    options.alignHeading = false;
    auto kept = preprocessCorpus(corpus, options);
    REQUIRE(kept.ok());
    CHECK(kept->report.takes[1].headingOffsetDeg == 0.0);
    CHECK(kept->corpus.takes[1].values(0, 9) == Approx(corpus.takes[1].values(0, 9)));
}

TEST_CASE("a reference take that is itself turned round does not turn the other takes")
{
    Corpus corpus;
    for (const std::string emotion : {"none", "friendly"})
        for (int k = 1; k <= 3; ++k) corpus.takes.push_back(movingTake(40, 5.0, "greeting", emotion, k));
    // The position reference (none, take 1) faces the other way: every yaw channel + 179 deg.
    for (int p = 0; p < kPuppetPartCount; ++p) corpus.takes[0].values.col(p * 6 + 3).array() += 179.0;
    // Another take turned by a few degrees, on the other branch (-360).
    for (int p = 0; p < kPuppetPartCount; ++p) corpus.takes[4].values.col(p * 6 + 3).array() += 3.0 - 360.0;

    PreprocessOptions options;
    options.alignStart = false;
    auto result = preprocessCorpus(corpus, options);
    REQUIRE(result.ok());
    const auto& report = result->report.takes;
    CHECK(report[0].isPositionReference);
    CHECK_FALSE(report[0].isHeadingReference);
    CHECK(report[0].headingOffsetDeg == Approx(-179.0));
    CHECK(report[4].headingOffsetDeg == Approx(-3.0));
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        INFO("take " << i);
        if (i != 0 && i != 4) CHECK(report[i].headingOffsetDeg == Approx(0.0).margin(1e-12));
        // Every take now has the untouched takes' yaw, on their branch.
        for (int p = 0; p < kPuppetPartCount; ++p)
            CHECK((result->corpus.takes[i].values.col(p * 6 + 3) - corpus.takes[1].values.col(p * 6 + 3)).cwiseAbs().maxCoeff() <
                  1e-9);
    }
}
