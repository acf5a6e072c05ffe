// Forward kinematics and import checked on the real Bandai Namco BVH files
// (../shared/data/bandai, read in place, never copied).
#include "tests/support/shared_data.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh_import.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;

namespace {

std::optional<BvhFile> loadBandai(const std::string& name)
{
    const auto path = bunraku::test::bandaiDir() / name;
    if (!std::filesystem::exists(path)) return std::nullopt;
    auto file = readBvh(path);
    REQUIRE(file.ok());
    return std::move(file).value();
}

/// Path length (cm) of a puppet part's position over a take.
double pathLength(const Take& take, int part)
{
    double length = 0.0;
    for (Eigen::Index f = 1; f < take.frameCount(); ++f)
        length += (take.values.row(f).segment(part * 6, 3) - take.values.row(f - 1).segment(part * 6, 3)).norm();
    return length;
}

} // namespace

TEST_CASE("bandai files parse with 22 joints, 5 end sites and 30 fps")
{
    const std::vector<std::string> names{"bye_happy_001.bvh", "bye_normal_001.bvh", "wave-right-hand_active_001.bvh",
                                         "wave-right-hand_exhausted_003.bvh"};
    for (const auto& name : names) {
        auto file = loadBandai(name);
        if (!bunraku::test::requireBandaiData(file.has_value())) return;
        INFO(name);
        CHECK(file->skeleton.jointCount() == 22);
        CHECK(file->skeleton.endSiteCount() == 5);
        CHECK(file->skeleton.channelCount == 22 * 6);
        CHECK(1.0 / file->motion.frameTime == Approx(30.0).epsilon(1e-4));
        CHECK(bvhRateHz(file->motion.frameTime) == 30.0);
        CHECK(file->motion.values.rows() > 30);
        CHECK(file->skeleton.joints[std::size_t(file->skeleton.find("Hand_R"))].parent == file->skeleton.find("LowerArm_R"));
        CHECK(resolveUpAxis(*file, BvhUpAxis::Auto) == BvhUpAxis::Y);
    }
}

TEST_CASE("bandai bone lengths stay constant over every frame and equal the offsets")
{
    auto file = loadBandai("bye_happy_001.bvh");
    if (!bunraku::test::requireBandaiData(file.has_value())) return;
    const auto& joints = file->skeleton.joints;
    const auto first = bvhWorldPoses(*file, 0);
    for (Eigen::Index f = 0; f < file->motion.values.rows(); f += 3) {
        const auto poses = bvhWorldPoses(*file, f);
        for (std::size_t j = 1; j < joints.size(); ++j) {
            const int parent = joints[j].parent;
            if (parent <= 0) continue; // Hips carries the world translation
            const double length = (poses[j].translation - poses[std::size_t(parent)].translation).norm();
            const double reference = (first[j].translation - first[std::size_t(parent)].translation).norm();
            CHECK(length == Approx(reference).margin(1e-3));
            // the position channels hold the bone (ReplaceOffset): length = |OFFSET|
            CHECK(length == Approx(joints[j].offset.norm()).margin(1e-2));
        }
    }
}

TEST_CASE("bandai puppet takes have plausible heights and continuous angles")
{
    auto file = loadBandai("bye_happy_001.bvh");
    if (!bunraku::test::requireBandaiData(file.has_value())) return;
    auto take = bvhToPuppetTake(*file);
    REQUIRE(take.ok());
    CHECK(hasPuppetLayout(*take));
    CHECK(take->frameCount() == file->motion.values.rows());
    CHECK(validateTake(*take).ok());
    for (Eigen::Index f = 0; f < take->frameCount(); ++f) {
        const double head = take->values(f, puppetChannel(0, Dof::Z));
        const double chest = take->values(f, puppetChannel(1, Dof::Z));
        const double hand = take->values(f, puppetChannel(3, Dof::Z));
        CHECK(head > 130.0);
        CHECK(head < 200.0);
        CHECK(chest > 90.0);
        CHECK(chest < head);
        CHECK(hand > 50.0);
        CHECK(hand < 220.0);
    }
    for (int p = 0; p < 4; ++p)
        for (int d = 3; d < 6; ++d)
            for (Eigen::Index f = 1; f < take->frameCount(); ++f)
                CHECK(std::fabs(take->values(f, p * 6 + d) - take->values(f - 1, p * 6 + d)) < 90.0);
    // the all-joint take keeps 22 six-DOF parts and agrees with the puppet take on the hand
    auto all = bvhToJointTake(*file);
    REQUIRE(all.ok());
    CHECK(all->channelCount() == 22 * 6);
    const auto hand = all->channelIndex("Hand_R", "x");
    REQUIRE(hand);
    CHECK((all->values.middleCols(*hand, 3) - take->values.middleCols(18, 3)).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("in the wave files the right hand moves the most")
{
    for (const std::string name : {"wave-right-hand_normal_001.bvh", "wave-right-hand_active_002.bvh", "bye_angry_001.bvh"}) {
        auto file = loadBandai(name);
        if (!bunraku::test::requireBandaiData(file.has_value())) return;
        INFO(name);
        auto take = bvhToPuppetTake(*file);
        REQUIRE(take.ok());
        const double hand = pathLength(*take, 3);
        CHECK(hand > pathLength(*take, 0));
        CHECK(hand > pathLength(*take, 1));
        CHECK(hand > pathLength(*take, 2));
        BvhImportOptions left;
        left.jointMap = parseJointMap("arm=LowerArm_L,hand=Hand_L", *defaultJointMap(file->skeleton)).value();
        auto leftTake = bvhToPuppetTake(*file, left);
        REQUIRE(leftTake.ok());
        CHECK(hand > 2.0 * pathLength(*leftTake, 3));
    }
}

TEST_CASE("a bandai take keeps its whole skeleton, posed as the file's forward kinematics")
{
    auto file = loadBandai("wave-right-hand_active_001.bvh");
    if (!bunraku::test::requireBandaiData(file.has_value())) return;
    auto take = bvhToPuppetTake(*file);
    REQUIRE(take.ok());
    REQUIRE(take->skeleton);
    const SkeletalMotion& motion = *take->skeleton;
    CHECK(motion.frameCount() == take->frameCount());
    CHECK(motion.skeleton->jointCount() == 22);
    CHECK(motion.skeleton->joints.size() == 27);
    CHECK(motion.skeleton->parts.size() == 4);
    // Only Hips moves (its position channels carry the world translation); every bone is rigid.
    REQUIRE(motion.movingJoints.size() == 1);
    CHECK(motion.skeleton->joints[std::size_t(motion.movingJoints[0])].name == "Hips");
    const BvhUpAxis upAxis = resolveUpAxis(*file, BvhUpAxis::Auto);
    for (Eigen::Index f : {Eigen::Index(0), take->frameCount() / 2, take->frameCount() - 1}) {
        const auto expected = bvhWorkbenchPoses(*file, f, upAxis, 1.0);
        const auto actual = motion.worldPoses(f);
        REQUIRE(actual.size() == expected.size());
        for (std::size_t j = 0; j < actual.size(); ++j) {
            INFO("frame " << f << ", joint " << motion.skeleton->joints[j].name);
            CHECK((actual[j].translation - expected[j].translation).norm() < 1e-9);
            CHECK(actual[j].rotation.angularDistance(expected[j].rotation) < 1e-9);
        }
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const auto part = motion.partPose(f, kPuppetParts[std::size_t(p)]);
            REQUIRE(part.has_value());
            CHECK((part->translation - partPose(*take, f, p * kDofCount).translation).norm() < 1e-9);
        }
    }
}
