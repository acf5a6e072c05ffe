#include "tests/support/shared_data.h"
#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh_export.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/take_reader.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <random>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;

namespace {

/// Angle in degrees between two rotations.
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return Eigen::AngleAxisd(a.conjugate() * b).angle() * 180.0 / M_PI;
}

/// A puppet take with random poses, yaw crossing +-180 and gimbal-adjacent pitches.
Take randomPuppetTake()
{
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> position(-80.0, 150.0), angle(-179.0, 179.0), pitch(-89.0, 89.0);
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values.resize(40, kPuppetChannelCount);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
        for (int p = 0; p < kPuppetPartCount; ++p) {
            for (int d = 0; d < 3; ++d) take.values(f, p * 6 + d) = position(rng);
            take.values(f, p * 6 + 3) = 170.0 + 4.0 * double(f) + double(p); // crosses 180, unwrapped
            take.values(f, p * 6 + 4) = f % 5 == 0 ? 89.99999 : (f % 7 == 0 ? -89.9999 : pitch(rng));
            take.values(f, p * 6 + 5) = angle(rng);
        }
    return take;
}

void requireSamePoses(const Take& a, const Take& b)
{
    REQUIRE(a.frameCount() == b.frameCount());
    double worstPosition = 0.0, worstAngle = 0.0;
    for (Eigen::Index f = 0; f < a.frameCount(); ++f)
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const RigidTransform pa = partPose(a, f, p * 6), pb = partPose(b, f, p * 6);
            worstPosition = std::max(worstPosition, (pa.translation - pb.translation).norm());
            worstAngle = std::max(worstAngle, angleBetween(pa.rotation, pb.rotation));
        }
    CHECK(worstPosition < 1e-6);
    CHECK(worstAngle < 1e-6);
}

} // namespace

TEST_CASE("a take exported to BVH re-imports to the same world poses")
{
    const Take original = randomPuppetTake();
    const auto dir = bunraku::test::scratchDir("bvh_export_round_trip");
    REQUIRE(writeTakeBvh(original, dir / "take.bvh").ok());
    auto file = readBvh(dir / "take.bvh");
    REQUIRE(file.ok());
    CHECK(file->skeleton.jointCount() == 5);
    CHECK(file->skeleton.joints[0].name == kBvhExportRootName);
    CHECK(resolveUpAxis(*file, BvhUpAxis::Auto) == BvhUpAxis::Z);
    auto back = bvhToPuppetTake(*file);
    REQUIRE(back.ok());
    CHECK(back->rateHz == Approx(5.0).epsilon(1e-12));
    requireSamePoses(original, *back);
    // the generic reader dispatches .bvh the same way
    auto viaReader = readTakeFile(dir / "take.bvh");
    REQUIRE(viaReader.ok());
    requireSamePoses(original, *viaReader);
}

TEST_CASE("a bandai take exported as a puppet BVH keeps its world poses")
{
    const auto path = bunraku::test::bandaiDir() / "bye_normal_001.bvh";
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(path))) return;
    auto take = readTakeFile(path);
    REQUIRE(take.ok());
    const auto dir = bunraku::test::scratchDir("bvh_export_bandai");
    REQUIRE(writeTakeFile(*take, dir / "puppet.bvh").ok());
    auto back = readTakeFile(dir / "puppet.bvh");
    REQUIRE(back.ok());
    requireSamePoses(*take, *back);
}

TEST_CASE("bvh export refuses takes without 6-DOF parts and writes nothing")
{
    Take take;
    take.channels = {Channel{"axis", "length", ""}};
    take.values = Eigen::MatrixXd::Ones(3, 1);
    const auto dir = bunraku::test::scratchDir("bvh_export_refuse");
    auto status = writeTakeBvh(take, dir / "x.bvh");
    REQUIRE_FALSE(status.ok());
    CHECK(status.error().code == ErrorCode::Unsupported);
    CHECK_FALSE(std::filesystem::exists(dir / "x.bvh"));
}
