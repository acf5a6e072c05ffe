#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/bvh_export.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/bvh_skeleton_export.h"
#include "analysis/io/take_reader.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;

namespace {

std::optional<BvhFile> loadBandai(const std::string& name)
{
    const auto path = bunraku::test::bandaiDir() / name;
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(path))) return std::nullopt;
    auto file = readBvh(path);
    REQUIRE(file.ok());
    return std::move(file).value();
}

/// Difference of two angles in degrees, whole turns ignored.
double angleDifference(double a, double b) { return std::fabs(std::remainder(a - b, 360.0)); }

bool isRotation(BvhChannel c) { return c == BvhChannel::Xrotation || c == BvhChannel::Yrotation || c == BvhChannel::Zrotation; }

/// The motion of every `step`-th frame: a derived take built through the skeleton API.
SkeletalMotion everyNthFrame(const SkeletalMotion& motion, Eigen::Index step)
{
    const Eigen::Index frames = (motion.frameCount() + step - 1) / step;
    SkeletalMotion out = makeRestMotion(motion.skeleton, frames);
    out.staticTranslations = motion.staticTranslations;
    out.movingJoints = motion.movingJoints;
    out.movingTranslations.resize(frames, motion.movingTranslations.cols());
    for (Eigen::Index f = 0; f < frames; ++f) {
        for (int j = 0; j < motion.jointSlots(); ++j) out.rotation(f, j) = motion.rotation(f * step, j);
        out.movingTranslations.row(f) = motion.movingTranslations.row(f * step);
    }
    return out;
}

} // namespace

TEST_CASE("euler angles give the rotation back in all six orders, also at gimbal lock")
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI), pitch(-M_PI / 2, M_PI / 2);
    const std::vector<std::array<int, 3>> orders{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& axes : orders) {
        for (int trial = 0; trial < 200; ++trial) {
            const double b = trial % 10 == 0 ? (trial % 20 == 0 ? M_PI / 2 : -M_PI / 2) : pitch(rng);
            const Eigen::Vector3d truth(angle(rng), b, angle(rng));
            const Eigen::Matrix3d r = (Eigen::AngleAxisd(truth[0], Eigen::Vector3d::Unit(axes[0])) *
                                       Eigen::AngleAxisd(truth[1], Eigen::Vector3d::Unit(axes[1])) *
                                       Eigen::AngleAxisd(truth[2], Eigen::Vector3d::Unit(axes[2])))
                                          .toRotationMatrix();
            for (const auto& previous : {std::optional<Eigen::Vector3d>(), std::optional<Eigen::Vector3d>(truth)}) {
                const Eigen::Vector3d e = eulerAngles(r, axes, previous);
                const Eigen::Matrix3d back = (Eigen::AngleAxisd(e[0], Eigen::Vector3d::Unit(axes[0])) *
                                              Eigen::AngleAxisd(e[1], Eigen::Vector3d::Unit(axes[1])) *
                                              Eigen::AngleAxisd(e[2], Eigen::Vector3d::Unit(axes[2])))
                                                 .toRotationMatrix();
                INFO("axes " << axes[0] << axes[1] << axes[2] << ", truth " << truth.transpose() << ", got " << e.transpose());
                CHECK((back - r).cwiseAbs().maxCoeff() < 1e-12);
                if (!previous) CHECK(std::fabs(e[1]) <= M_PI / 2 + 1e-12);
                else if (std::fabs(std::fabs(b) - M_PI / 2) > 1e-3) CHECK((e - truth).cwiseAbs().maxCoeff() < 1e-9); // continuity
            }
        }
    }
}

TEST_CASE("an untouched bandai take exported as BVH gives the file back on its 22-joint skeleton")
{
    for (const std::string name : {"bye_angry_001.bvh", "wave-right-hand_normal_001.bvh"}) {
        INFO(name);
        auto source = loadBandai(name);
        if (!source) return;
        auto take = bvhToPuppetTake(*source);
        REQUIRE(take.ok());
        const auto out = bunraku::test::scratchDir("bvh_skeleton_export") / name;
        REQUIRE(writeTakeFile(*take, out).ok());
        auto written = readBvh(out);
        REQUIRE(written.ok());
        const BvhSkeleton& a = source->skeleton;
        const BvhSkeleton& b = written->skeleton;
        REQUIRE(b.joints.size() == a.joints.size());
        CHECK(b.jointCount() == 22);
        CHECK(b.channelCount == a.channelCount);
        double worstOffset = 0.0;
        for (std::size_t j = 0; j < a.joints.size(); ++j) {
            INFO("joint " << a.joints[j].name);
            CHECK(b.joints[j].name == a.joints[j].name);
            CHECK(b.joints[j].parent == a.joints[j].parent);
            CHECK(b.joints[j].endSite == a.joints[j].endSite);
            CHECK(b.joints[j].channels == a.joints[j].channels);
            worstOffset = std::max(worstOffset, (b.joints[j].offset - a.joints[j].offset).cwiseAbs().maxCoeff());
        }
        CHECK(worstOffset < 1e-6);
        CHECK(std::fabs(written->motion.frameTime - source->motion.frameTime) < 1e-6);
        REQUIRE(written->motion.values.rows() == source->motion.values.rows());
        double worstPosition = 0.0, worstAngle = 0.0;
        for (const BvhJoint& joint : a.joints)
            for (std::size_t k = 0; k < joint.channels.size(); ++k) {
                const Eigen::Index c = joint.firstChannel + Eigen::Index(k);
                for (Eigen::Index f = 0; f < source->motion.values.rows(); ++f) {
                    const double x = source->motion.values(f, c), y = written->motion.values(f, c);
                    if (isRotation(joint.channels[k])) worstAngle = std::max(worstAngle, angleDifference(x, y));
                    else worstPosition = std::max(worstPosition, std::fabs(x - y));
                }
            }
        CHECK(worstPosition < 1e-6); // cm
        CHECK(worstAngle < 1e-6);    // deg
        // And it imports as the same take.
        auto again = bvhToPuppetTake(*written);
        REQUIRE(again.ok());
        CHECK((again->values - take->values).cwiseAbs().maxCoeff() < 1e-6);
    }
}

TEST_CASE("a derived take is written as its own motion on the source skeleton")
{
    auto source = loadBandai("bye_normal_001.bvh");
    if (!source) return;
    auto take = bvhToPuppetTake(*source);
    REQUIRE(take.ok());
    // Every second frame at half the rate: the same motion in time, resampled.
    auto derived = std::make_shared<SkeletalMotion>(everyNthFrame(*take->skeleton, 2));
    Take half;
    half.channels = take->channels;
    half.rateHz = take->rateHz / 2.0;
    half.values.resize(derived->frameCount(), take->channelCount());
    for (Eigen::Index f = 0; f < half.frameCount(); ++f) half.values.row(f) = take->values.row(2 * f);
    half.skeleton = derived;
    half.labels.source = "every second frame of bye_normal_001";

    const auto out = bunraku::test::scratchDir("bvh_skeleton_derived") / "half.bvh";
    REQUIRE(writeTakeFile(half, out).ok());
    auto written = readBvh(out);
    REQUIRE(written.ok());
    CHECK(written->skeleton.jointCount() == 22);
    CHECK(written->motion.values.rows() == derived->frameCount());
    CHECK(std::fabs(written->motion.frameTime - 2.0 / 30.0) < 1e-12);
    auto again = bvhToSkeletalMotion(*written);
    REQUIRE(again.ok());
    double worstPosition = 0.0, worstAngle = 0.0;
    for (Eigen::Index f = 0; f < derived->frameCount(); ++f) {
        const auto expected = derived->worldPoses(f), actual = (*again)->worldPoses(f);
        for (std::size_t j = 0; j < expected.size(); ++j) {
            worstPosition = std::max(worstPosition, (expected[j].translation - actual[j].translation).norm());
            worstAngle = std::max(worstAngle, expected[j].rotation.angularDistance(actual[j].rotation) * 180.0 / M_PI);
        }
    }
    CHECK(worstPosition < 1e-6);
    CHECK(worstAngle < 1e-6);
}

TEST_CASE("a take without a skeleton is still written in the part layout")
{
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values = Eigen::MatrixXd::Zero(3, kPuppetChannelCount);
    const auto out = bunraku::test::scratchDir("bvh_skeleton_none") / "parts.bvh";
    REQUIRE(writeTakeFile(take, out).ok());
    auto written = readBvh(out);
    REQUIRE(written.ok());
    CHECK(written->skeleton.joints.front().name == kBvhExportRootName);
    CHECK(written->skeleton.channelCount == 30);
}

TEST_CASE("motion the source's channels cannot hold is refused, naming the joint and frame")
{
    auto skeleton = std::make_shared<Skeleton>();
    skeleton->name = "two";
    SkeletonJoint root{"root", -1, Eigen::Vector3d::Zero(),
                       {JointChannel::Xposition, JointChannel::Yposition, JointChannel::Zposition, JointChannel::Zrotation,
                        JointChannel::Xrotation, JointChannel::Yrotation}};
    SkeletonJoint elbow{"elbow", 0, Eigen::Vector3d(10, 0, 0), {JointChannel::Zrotation}};
    skeleton->joints = {root, elbow};
    auto motion = std::make_shared<SkeletalMotion>(makeRestMotion(skeleton, 3));
    SECTION("a hinge turned about its own axis is written")
    {
        motion->rotation(1, 1) = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()));
        auto bvh = skeletalMotionToBvh(*motion, 30.0);
        REQUIRE(bvh.ok());
        CHECK(bvh->motion.values(1, 6) == Approx(0.5 * 180.0 / M_PI).margin(1e-9));
    }
    SECTION("a hinge turned about another axis is refused")
    {
        motion->rotation(2, 1) = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));
        auto bvh = skeletalMotionToBvh(*motion, 30.0);
        REQUIRE_FALSE(bvh.ok());
        CHECK_THAT(bvh.error().message, Catch::Contains("frame 2") && Catch::Contains("'elbow'"));
    }
    SECTION("a joint without position channels that moves is refused")
    {
        motion->movingJoints = {1};
        motion->movingTranslations = Eigen::MatrixXd::Zero(3, 3);
        auto bvh = skeletalMotionToBvh(*motion, 30.0);
        REQUIRE_FALSE(bvh.ok());
        CHECK_THAT(bvh.error().message, Catch::Contains("'elbow'") && Catch::Contains("no position channels"));
    }
}
