// Motion design on real Bandai takes (read in place): the designed take carries the full
// skeleton, and takes of different lengths (138 and 90 frames) go through phase, gains and design.
#include "analysis/design/motion_design.h"
#include "analysis/skeleton/take_resample.h"
#include "tests/support/bandai_data.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;
using bunraku::test::bandaiAvailable;
using bunraku::test::readBandai;

namespace {

const AxisModel& model()
{
    static const AxisModel m = makeAxisModel(defaultBodyDescription(), {{2.0}});
    return m;
}

/// A 106-frame cell's functional take: a Bandai wave resampled to 106 frames.
Take functional106()
{
    const Take wave = readBandai("wave-right-hand_normal_001.bvh", {"wave", "normal", 1, ""});
    return resampleTake(wave, evenlySpacedFrames(wave.frameCount(), 106));
}

double worstLocalRotation(const SkeletalMotion& a, Eigen::Index fa, const SkeletalMotion& b, Eigen::Index fb, bool skipRoots = false)
{
    double worst = 0.0;
    for (int j = 0; j < a.jointSlots(); ++j) {
        if (skipRoots && a.skeleton->joints[std::size_t(j)].parent < 0) continue;
        worst = std::max(worst, rotationDistance(a.rotation(fa, j), b.rotation(fb, j)));
    }
    return worst;
}

GainSet someGains(const DesignBasis& basis)
{
    const Eigen::Index last = basis.coordinates.rows() - 1;
    GainSet gains = unitGains({0, last / 3, 2 * last / 3, last}, {"x", "y", "z", "rx", "ry", "rz"});
    gains.phrases[0].dofs[2].g1 = 0.6; // less up and down in the first phrase
    gains.phrases[1].dofs[5].g1 = 1.8; // more turning in the second
    gains.phrases[2].dofs[0].g0 = 0.9;
    return gains;
}

} // namespace

TEST_CASE("a design with the identity warp and unit gains leaves every joint unchanged")
{
    if (!bandaiAvailable({"wave-right-hand_normal_001.bvh"})) return;
    const Take functional = functional106();
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    const DesignedMotion designed = designMotion(*basis, identityWarp(106), GainSet{});
    REQUIRE(designed.take.skeleton);
    CHECK(validateTake(designed.take).ok());
    const SkeletalMotion& source = *functional.skeleton;
    for (Eigen::Index f = 0; f < 106; ++f) {
        CHECK(worstLocalRotation(*designed.take.skeleton, f, source, f) < 1e-9);
        for (int j = 0; j < source.jointSlots(); ++j) CHECK((designed.take.skeleton->translation(f, j) - source.translation(f, j)).norm() < 1e-9);
    }
}

TEST_CASE("a designed constant time scale shows every joint at the scaled time")
{
    if (!bandaiAvailable({"wave-right-hand_normal_001.bvh"})) return;
    const Take functional = functional106();
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    // 71 output frames showing functional time 1.5 u: a third faster
    WarpCurve faster;
    faster.outputFrames = 71;
    for (int u = 0; u <= 70; u += 10) faster.points.push_back({double(u), 1.5 * u});
    const DesignedMotion designed = designMotion(*basis, faster, GainSet{});
    REQUIRE(designed.take.frameCount() == 71);
    REQUIRE(designed.take.skeleton);
    const SkeletalMotion& source = *functional.skeleton;
    for (Eigen::Index u = 0; u < 71; u += 2) // even u: whole functional frames 1.5 u
        CHECK(worstLocalRotation(*designed.take.skeleton, u, source, Eigen::Index(1.5 * double(u)), true) < 1e-6);
    CHECK(bunraku::test::maxBoneLengthChange(*designed.take.skeleton) < 1e-9);
    CHECK(bunraku::test::unexplainedEulerSteps(designed.take) == 0);
}

TEST_CASE("per-phrase gains on the axis move every bound part's joint with its designed part")
{
    if (!bandaiAvailable({"wave-right-hand_normal_001.bvh"})) return;
    const Take functional = functional106();
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    const DesignedMotion designed = designMotion(*basis, identityWarp(106), someGains(*basis));
    REQUIRE(designed.take.skeleton);
    const SkeletalMotion& source = *functional.skeleton;
    const SkeletalMotion& result = *designed.take.skeleton;
    CHECK(validateTake(designed.take).ok());
    CHECK(bunraku::test::maxBoneLengthChange(result) < 1e-9);
    CHECK(bunraku::test::unexplainedEulerSteps(designed.take) == 0);
    // The part moved by the design (channels) and the skeleton's part move by the same rigid
    // transform, whatever calibration binds the part to its joint.
    double worstRotation = 0.0, worstPosition = 0.0;
    for (const auto& part : sixDofParts(functional)) {
        for (Eigen::Index f = 0; f < 106; f += 5) {
            const RigidTransform channelMove = partPose(designed.take, f, part.firstChannel) * partPose(functional, f, part.firstChannel).inverse();
            const auto after = result.partPose(f, part.part);
            const auto before = source.partPose(f, part.part);
            if (!after || !before) continue;
            const RigidTransform skeletonMove = *after * before->inverse();
            worstRotation = std::max(worstRotation, rotationDistance(channelMove.rotation, skeletonMove.rotation));
            worstPosition = std::max(worstPosition, (channelMove.translation - skeletonMove.translation).norm());
        }
    }
    CHECK(worstRotation < 1e-6);
    CHECK(worstPosition < 1e-6);
    // the design did change something, and joints keep their local motion below the root
    CHECK((designed.take.values - functional.values).cwiseAbs().maxCoeff() > 1.0);
    for (Eigen::Index f = 0; f < 106; f += 5) CHECK(worstLocalRotation(result, f, source, f, true) < 1e-9);
}

TEST_CASE("phase, gains and design accept a reference and a sample of 138 and 90 frames")
{
    if (!bandaiAvailable({"bye_happy_001.bvh", "bye_angry_001.bvh"})) return;
    // A 138-frame functional take and an angry take hurried into 90 frames.
    const Take happy = readBandai("bye_happy_001.bvh", {"bye", "normal", 1, ""});
    const Take functional = resampleTake(happy, Eigen::VectorXd::LinSpaced(138, 0.0, 137.0));
    const Take angry = readBandai("bye_angry_001.bvh", {"bye", "angry", 1, ""});
    const Take emotional = resampleTake(angry, evenlySpacedFrames(angry.frameCount(), 90));
    REQUIRE(functional.frameCount() == 138);
    REQUIRE(emotional.frameCount() == 90);
    const auto basis = prepareDesign(model(), functional);
    const auto emotionalBasis = prepareDesign(model(), emotional);
    REQUIRE(basis.ok());
    REQUIRE(emotionalBasis.ok());
    // the thesis's band alone cannot match them
    PhaseOptions bandOnly;
    bandOnly.match.timeScaling = TimeScaling::None;
    CHECK_FALSE(extractPhase(basis->coordinates, emotionalBasis->coordinates, bandOnly).ok());
    auto parameters = extractDesign(basis->coordinates, emotionalBasis->coordinates);
    REQUIRE(parameters.ok());
    const PhaseResult& phase = parameters->phase;
    CHECK(phase.emotionalToFunctional.size() == 90);
    CHECK(phase.curve.points.back().source <= 137.0 + 1e-9);
    CHECK(phase.curve.points.back().source > 100.0); // the whole functional take is used
    const DesignedMotion designed = designMotion(*basis, phase.curve, parameters->gains);
    CHECK(designed.take.frameCount() == 90);
    CHECK(validateTake(designed.take).ok());
    REQUIRE(designed.take.skeleton);
    CHECK(bunraku::test::maxBoneLengthChange(*designed.take.skeleton) < 1e-9);
    CHECK(bunraku::test::unexplainedEulerSteps(designed.take) == 0);
}
