#include "analysis/core/puppet_layout.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/preprocess/start_position.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <string>

using namespace bunraku::analysis;
using namespace bunraku::analysis::preprocess;

namespace {

/// Position of part p at frame t.
Eigen::Vector3d partPosition(const Take& take, int p, Eigen::Index t)
{
    return take.values.row(t).segment(puppetChannel(p, Dof::X), 3).transpose();
}

/// Largest change of any inter-part vector (part q minus part p) between two takes over all frames.
double interPartChange(const Take& a, const Take& b)
{
    double worst = 0.0;
    for (Eigen::Index t = 0; t < a.frameCount(); ++t)
        for (int p = 0; p < kPuppetPartCount; ++p)
            for (int q = p + 1; q < kPuppetPartCount; ++q) {
                const Eigen::Vector3d before = partPosition(a, q, t) - partPosition(a, p, t);
                const Eigen::Vector3d after = partPosition(b, q, t) - partPosition(b, p, t);
                worst = std::max(worst, (after - before).norm());
            }
    return worst;
}

Eigen::Vector3d startCentroid(const Take& take)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int p = 0; p < kPuppetPartCount; ++p) sum += partPosition(take, p, 0);
    return sum / kPuppetPartCount;
}

} // namespace

TEST_CASE("the start-position step moves each demo take rigidly and keeps its inter-part geometry to 1e-9")
{
    const synth::DemoCorpus demo = synth::generateDemoCorpus();
    PreprocessOptions without;
    without.alignPosition = false;
    auto unaligned = preprocessCorpus(demo.corpus, without);
    REQUIRE(unaligned.ok());
    PreprocessOptions rigid; // the default
    REQUIRE(rigid.positionAlignment == PositionAlignment::Rigid);
    auto aligned = preprocessCorpus(demo.corpus, rigid);
    REQUIRE(aligned.ok());
    const auto& before = unaligned->corpus.takes;
    const auto& after = aligned->corpus.takes;
    REQUIRE(before.size() == after.size());
    int moved = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        INFO(after[i].displayName());
        // arm to hand, shoulder to head...: every inter-part vector unchanged, at frame 0 and after
        CHECK(interPartChange(before[i], after[i]) < 1e-9);
        // one translation: every part of every frame moved by the reported offset
        const auto& offsets = aligned->report.takes[i].positionOffsets;
        REQUIRE(offsets.size() == std::size_t(kPuppetPartCount));
        for (int p = 0; p < kPuppetPartCount; ++p) {
            CHECK((offsets[std::size_t(p)] - offsets[0]).norm() == 0.0);
            for (Eigen::Index t : {Eigen::Index(0), after[i].frameCount() / 2, after[i].frameCount() - 1})
                CHECK((partPosition(after[i], p, t) - partPosition(before[i], p, t) - offsets[0]).norm() < 1e-9);
        }
        if (offsets[0].norm() > 1.0) ++moved;
        // angles are untouched by the position step
        for (int p = 0; p < kPuppetPartCount; ++p)
            CHECK(after[i].values.col(puppetChannel(p, Dof::Yaw)) == before[i].values.col(puppetChannel(p, Dof::Yaw)));
    }
    CHECK(moved > 10); // the demo takes start up to several cm apart
    // the start centroid of every take is its function's reference's
    for (const auto& function : aligned->corpus.functions()) {
        const Take* reference = nullptr;
        for (std::size_t i = 0; i < after.size(); ++i)
            if (after[i].labels.function == function && aligned->report.takes[i].isPositionReference) reference = &after[i];
        REQUIRE(reference != nullptr);
        for (const Take& take : after)
            if (take.labels.function == function) CHECK((startCentroid(take) - startCentroid(*reference)).norm() < 1e-9);
    }
}

TEST_CASE("per-part start alignment is kept as an option: every part starts at the reference's")
{
    const synth::DemoCorpus demo = synth::generateDemoCorpus();
    PreprocessOptions options;
    options.positionAlignment = PositionAlignment::PerPart;
    auto perPart = preprocessCorpus(demo.corpus, options);
    REQUIRE(perPart.ok());
    PreprocessOptions without;
    without.alignPosition = false;
    auto unaligned = preprocessCorpus(demo.corpus, without);
    REQUIRE(unaligned.ok());
    double largestChange = 0.0;
    for (std::size_t i = 0; i < perPart->corpus.takes.size(); ++i) {
        const Take& take = perPart->corpus.takes[i];
        const Take* reference = nullptr;
        for (std::size_t r = 0; r < perPart->corpus.takes.size(); ++r)
            if (perPart->corpus.takes[r].labels.function == take.labels.function && perPart->report.takes[r].isPositionReference)
                reference = &perPart->corpus.takes[r];
        REQUIRE(reference != nullptr);
        for (int p = 0; p < kPuppetPartCount; ++p) CHECK((partPosition(take, p, 0) - partPosition(*reference, p, 0)).norm() < 1e-9);
        largestChange = std::max(largestChange, interPartChange(unaligned->corpus.takes[i], take));
    }
    // which changes the geometry between the parts (the reason it is not the default)
    CHECK(largestChange > 0.5);
}

TEST_CASE("alignStartPosition matches parts by name and moves parts the reference lacks with the body")
{
    Take reference;
    reference.channels = sixDofChannels("head");
    for (const auto& channel : sixDofChannels("hand")) reference.channels.push_back(channel);
    reference.values = Eigen::MatrixXd::Zero(2, 12);
    reference.values.row(0).segment(0, 3) << 0.0, 0.0, 100.0; // head
    reference.values.row(0).segment(6, 3) << 20.0, 0.0, 80.0; // hand
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(2, kPuppetChannelCount);
    take.values.row(0).segment(puppetChannel(0, Dof::X), 3) << 10.0, 5.0, 102.0;  // head: +10 +5 +2
    take.values.row(0).segment(puppetChannel(1, Dof::X), 3) << 10.0, 5.0, 90.0;   // shoulder: not in the reference
    take.values.row(0).segment(puppetChannel(3, Dof::X), 3) << 32.0, 3.0, 84.0;   // hand: +12 +3 +4
    take.values.row(1) = take.values.row(0);
    take.values(0, puppetChannel(0, Dof::Yaw)) = 30.0;

    Take rigid = take;
    const auto offsets = alignStartPosition(rigid, reference, PositionAlignment::Rigid);
    REQUIRE(offsets.size() == 4);
    const Eigen::Vector3d expected(-11.0, -4.0, -3.0); // mean of the head's and hand's differences
    for (const auto& offset : offsets) CHECK((offset - expected).norm() < 1e-12);
    CHECK(interPartChange(take, rigid) < 1e-12);
    CHECK(rigid.values(0, puppetChannel(0, Dof::Yaw)) == 30.0);

    Take perPart = take;
    const auto own = alignStartPosition(perPart, reference, PositionAlignment::PerPart);
    CHECK((partPosition(perPart, 0, 0) - Eigen::Vector3d(0.0, 0.0, 100.0)).norm() < 1e-12);
    CHECK((partPosition(perPart, 3, 0) - Eigen::Vector3d(20.0, 0.0, 80.0)).norm() < 1e-12);
    CHECK(own[1].norm() == 0.0); // the shoulder has no counterpart: left where it was
    CHECK(partPosition(perPart, 1, 0) == partPosition(take, 1, 0));

    PositionAlignment parsed = PositionAlignment::Rigid;
    CHECK(parsePositionAlignment("per-part", parsed));
    CHECK(parsed == PositionAlignment::PerPart);
    CHECK_FALSE(parsePositionAlignment("rigid ", parsed));
    CHECK(std::string(positionAlignmentName(PositionAlignment::Rigid)) == "rigid");
}

TEST_CASE("points carried by the body (the kimono's) turn and move with its parts when a take is aligned")
{
    // Take 2 of a demo cell turned by 40 deg and moved, with a point 6 cm in front of and 9 cm
    // below the hand at every frame (as the kimono's sleeve tip is carried): aligned to take 1,
    // the point stays where the hand carries it.
    const auto demo = synth::generateDemoCorpus();
    Take reference = *demo.corpus.find("greeting", "none", 1);
    Take take = *demo.corpus.find("greeting", "none", 2);
    const Eigen::Matrix2d turn = Eigen::Rotation2Dd(40.0 * M_PI / 180.0).toRotationMatrix();
    const Eigen::Index yaw = puppetChannel(0, Dof::Yaw);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const Eigen::Index x = puppetChannel(p, Dof::X);
            const Eigen::Vector2d xy = turn * take.values.row(f).segment(x, 2).transpose() + Eigen::Vector2d(25.0, -10.0);
            take.values(f, x) = xy.x();
            take.values(f, x + 1) = xy.y();
            take.values(f, yaw + p * kDofCount) += 40.0;
        }
    const auto withPoint = [](Take t) {
        const Eigen::Index hand = puppetChannel(3, Dof::X);
        t.channels.push_back({"sleeve_right_tip", "x", "cm"});
        t.channels.push_back({"sleeve_right_tip", "y", "cm"});
        t.channels.push_back({"sleeve_right_tip", "z", "cm"});
        t.values.conservativeResize(t.frameCount(), t.channelCount() + 3);
        t.values.rightCols(3) = t.values.middleCols(hand, 3);
        t.values.col(t.channelCount() - 3).array() += 6.0;
        t.values.col(t.channelCount() - 1).array() -= 9.0;
        return t;
    };
    reference = withPoint(reference);
    take = withPoint(take);
    REQUIRE(pointParts(take).size() == 1);
    REQUIRE(pointParts(take)[0].part == "sleeve_right_tip");
    const Eigen::Vector3d carriedBefore = take.values.row(0).tail<3>().transpose() - take.values.row(0).segment(puppetChannel(3, Dof::X), 3).transpose();
    Take aligned = take;
    const double offset = alignStartHeading(aligned, reference, "shoulder");
    CHECK(std::abs(offset) > 10.0);
    alignStartPosition(aligned, reference, PositionAlignment::Rigid);
    // The hand-to-point vector turned by the heading offset, its length kept, at every frame.
    const Eigen::Matrix2d back = Eigen::Rotation2Dd(offset * M_PI / 180.0).toRotationMatrix();
    double worst = 0.0;
    for (Eigen::Index f = 0; f < aligned.frameCount(); ++f) {
        const Eigen::Vector3d before = take.values.row(f).tail<3>().transpose() - take.values.row(f).segment(puppetChannel(3, Dof::X), 3).transpose();
        const Eigen::Vector3d after = aligned.values.row(f).tail<3>().transpose() - aligned.values.row(f).segment(puppetChannel(3, Dof::X), 3).transpose();
        Eigen::Vector3d expected = before;
        expected.head<2>() = back * before.head<2>();
        worst = std::max(worst, (after - expected).norm());
    }
    INFO("the point off where the hand carries it by at most " << worst << " cm; before alignment " << carriedBefore.transpose());
    CHECK(worst < 1e-9);
}
