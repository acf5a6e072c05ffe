// Time operations on the full skeleton, checked on a real Bandai take (read in place).
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/skeleton/skeleton_resample.h"
#include "analysis/skeleton/take_resample.h"
#include "tests/support/bandai_data.h"

#include <catch2/catch.hpp>

#include <numbers>

using namespace bunraku::analysis;
using bunraku::test::bandaiAvailable;
using bunraku::test::readBandai;

namespace {

const std::string kTake = "wave-right-hand_active_002.bvh";

double worstRotation(const SkeletalMotion& a, Eigen::Index fa, const SkeletalMotion& b, Eigen::Index fb)
{
    double worst = 0.0;
    for (int j = 0; j < a.jointSlots(); ++j) worst = std::max(worst, rotationDistance(a.rotation(fa, j), b.rotation(fb, j)));
    return worst;
}

double worstTranslation(const SkeletalMotion& a, Eigen::Index fa, const SkeletalMotion& b, Eigen::Index fb)
{
    double worst = 0.0;
    for (int j = 0; j < a.jointSlots(); ++j) worst = std::max(worst, (a.translation(fa, j) - b.translation(fb, j)).norm());
    return worst;
}

} // namespace

TEST_CASE("a warp of the identity leaves every joint unchanged")
{
    if (!bandaiAvailable({kTake})) return;
    const Take take = readBandai(kTake);
    REQUIRE(take.skeleton);
    const SkeletalMotion& source = *take.skeleton;
    const Eigen::VectorXd identity = Eigen::VectorXd::LinSpaced(source.frameCount(), 0.0, double(source.frameCount() - 1));
    const SkeletalMotionPtr warped = resampleSkeletalMotion(source, identity);
    REQUIRE(warped);
    REQUIRE(warped->frameCount() == source.frameCount());
    CHECK(validateSkeletalMotion(*warped).ok());
    for (Eigen::Index f = 0; f < source.frameCount(); ++f) {
        CHECK(worstRotation(*warped, f, source, f) < 1e-9);
        CHECK(worstTranslation(*warped, f, source, f) < 1e-9);
    }
    // the whole take too: channels and skeleton
    const Take same = resampleTake(take, identity);
    CHECK((same.values - take.values).cwiseAbs().maxCoeff() < 1e-9);
    CHECK(worstRotation(*same.skeleton, 17, source, 17) < 1e-9);
}

TEST_CASE("a constant time scale on a real take gives each joint's rotation at the scaled time")
{
    if (!bandaiAvailable({kTake})) return;
    const Take take = readBandai(kTake);
    REQUIRE(take.skeleton);
    const SkeletalMotion& source = *take.skeleton;
    // The file itself, read independently: each joint's local rotation at a whole frame.
    const auto file = io::readBvh(bunraku::test::bandaiDir() / kTake);
    REQUIRE(file.ok());
    const Eigen::Quaterniond world_R_file = io::bvhAxisChange(io::resolveUpAxis(*file, io::BvhUpAxis::Auto));
    auto fileRotation = [&](Eigen::Index frame, int joint) {
        const auto local = io::bvhLocalPoses(*file, frame);
        return Eigen::Quaterniond(world_R_file * local[std::size_t(joint)].rotation * world_R_file.conjugate());
    };
    // 1.5x faster: output frame u shows source time 1.5 u.
    const double scale = 1.5;
    const Eigen::Index frames = Eigen::Index(double(source.frameCount() - 1) / scale) + 1;
    Eigen::VectorXd at(frames);
    for (Eigen::Index u = 0; u < frames; ++u) at[u] = scale * double(u);
    const SkeletalMotionPtr fast = resampleSkeletalMotion(source, at);
    REQUIRE(fast->frameCount() == frames);
    for (Eigen::Index u = 0; u < frames; ++u) {
        const double s = at[u];
        const auto k = Eigen::Index(std::floor(s));
        for (int j = 0; j < source.jointSlots(); ++j) {
            if (source.skeleton->joints[std::size_t(j)].endSite) continue;
            if (s == double(k)) {
                CHECK(rotationDistance(fast->rotation(u, j), fileRotation(k, j)) < 1e-6);
            } else {
                // half way between two frames: the geodesic midpoint of their rotations
                const Eigen::Quaterniond a = fileRotation(k, j), b = fileRotation(k + 1, j);
                CHECK(rotationDistance(fast->rotation(u, j), a) == Approx(0.5 * rotationDistance(a, b)).margin(1e-6));
                CHECK(rotationDistance(fast->rotation(u, j), b) == Approx(0.5 * rotationDistance(a, b)).margin(1e-6));
            }
        }
        const Eigen::Vector3d expected = 0.5 * (source.translation(k, 1) + source.translation(std::min(k + 1, source.frameCount() - 1), 1));
        if (s != double(k)) CHECK((fast->translation(u, 1) - expected).norm() < 1e-9); // Hips: linear
    }
    CHECK(bunraku::test::maxBoneLengthChange(*fast) < 1e-9);
    // the take: channels at the scaled time, angles continuous
    const Take fastTake = resampleTake(take, at);
    CHECK(fastTake.frameCount() == frames);
    CHECK(validateTake(fastTake).ok());
    CHECK((fastTake.values.row(2) - take.values.row(3)).cwiseAbs().maxCoeff() < 1e-9);
    CHECK(bunraku::test::unexplainedEulerSteps(fastTake) == 0);
}

TEST_CASE("a start shift repeats the edge frames and keeps the whole frames")
{
    const Eigen::VectorXd later = shiftedFrames(10, 10, 3);
    CHECK(later[0] == 3.0);
    CHECK(later[9] == 9.0);
    const Eigen::VectorXd earlier = shiftedFrames(10, 12, -2);
    CHECK(earlier[0] == 0.0);
    CHECK(earlier[2] == 0.0);
    CHECK(earlier[3] == 1.0);
    CHECK(earlier[11] == 9.0);
}

TEST_CASE("a rigid move turns every joint's world pose and keeps bone lengths")
{
    if (!bandaiAvailable({kTake})) return;
    const Take take = readBandai(kTake);
    const SkeletalMotion& source = *take.skeleton;
    const RigidTransform move{Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ())), Eigen::Vector3d(10, -4, 2)};
    const SkeletalMotionPtr moved = moveSkeletalMotion(source, move);
    for (Eigen::Index f : {Eigen::Index(0), source.frameCount() / 2}) {
        const auto before = source.worldPoses(f);
        const auto after = moved->worldPoses(f);
        for (std::size_t j = 0; j < before.size(); ++j) {
            const RigidTransform expected = move * before[j];
            CHECK((after[j].translation - expected.translation).norm() < 1e-9);
            CHECK(rotationDistance(after[j].rotation, expected.rotation) < 1e-9);
        }
    }
    CHECK(bunraku::test::maxBoneLengthChange(*moved) < 1e-9);
    // per frame corrections on the roots of the parts' chains
    std::vector<RigidTransform> corrections(std::size_t(source.frameCount()));
    for (std::size_t f = 0; f < corrections.size(); ++f)
        corrections[f] = RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * double(f), Eigen::Vector3d::UnitY())),
                                        Eigen::Vector3d(0, 0, 0.1 * double(f))};
    const std::vector<int> roots = partChainRoots(*source.skeleton);
    REQUIRE(roots == std::vector<int>{0});
    const SkeletalMotionPtr corrected = moveSkeletalRoots(source, corrections, roots);
    CHECK(validateSkeletalMotion(*corrected).ok());
    const auto hand = source.skeleton->find("Hand_R");
    const Eigen::Index f = 40;
    const RigidTransform expected = corrections[40] * source.worldPoses(f)[std::size_t(hand)];
    CHECK((corrected->worldPoses(f)[std::size_t(hand)].translation - expected.translation).norm() < 1e-9);
    CHECK(bunraku::test::maxBoneLengthChange(*corrected) < 1e-9);
}
