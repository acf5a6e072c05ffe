#include "analysis/axis/relative_motion.h"

#include "analysis/axis/axis_channels.h"
#include "tests/analysis/axis/puppet_fixture.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

TEST_CASE("axis plus relative motion reconstructs the take exactly")
{
    const Take take = bunraku::test::livelyTake(106);
    const auto axis = computeMotionAxis(makeAxisModel(defaultBodyDescription(), {{2.0}}), take);
    REQUIRE(axis.ok());
    const auto relative = relativeMotion(take, axis->world_T_axis);
    REQUIRE(relative.ok());
    CHECK(relative->parts == std::vector<std::string>{"head", "shoulder", "arm", "hand"});
    const Take rebuilt = recombine(take, axis->world_T_axis, *relative);
    REQUIRE(rebuilt.frameCount() == take.frameCount());
    CHECK((rebuilt.values - take.values).cwiseAbs().maxCoeff() < 1e-9);

    SECTION("also through the axis coordinates")
    {
        const Eigen::MatrixXd coordinates = axisCoordinates(axis->world_T_axis);
        std::vector<RigidTransform> poses;
        for (Eigen::Index f = 0; f < coordinates.rows(); ++f) poses.push_back(axisFromCoordinates(coordinates.row(f)));
        CHECK((recombine(take, poses, *relative).values - take.values).cwiseAbs().maxCoeff() < 1e-9);
    }
    SECTION("the relative motion is what moves in the axis frame")
    {
        const Take inAxis = relativeMotionTake(*relative, take);
        const RigidTransform world_T_head = partPose(take, 40, 0);
        const RigidTransform axis_T_head = partPose(inAxis, 40, 0);
        CHECK(((axis->world_T_axis[40] * axis_T_head).translation - world_T_head.translation).norm() < 1e-9);
    }
}

TEST_CASE("a rigidly moving puppet has constant relative motion")
{
    const Take take = bunraku::test::puppetTake(30, [](Eigen::Index f) {
        return bunraku::test::rotationAbout(Eigen::Vector3d(0.3, 0.2, 1), 6.0 * double(f), Eigen::Vector3d(double(f), 0, 0));
    });
    const auto axis = computeMotionAxis(makeAxisModel(defaultBodyDescription(), {{2.0}}), take);
    REQUIRE(axis.ok());
    const auto relative = relativeMotion(take, axis->world_T_axis);
    REQUIRE(relative.ok());
    for (Eigen::Index f = 1; f < 30; ++f)
        for (std::size_t p = 0; p < 4; ++p) {
            CHECK((relative->axis_T_part[std::size_t(f)][p].translation - relative->axis_T_part[0][p].translation).norm() < 1e-6);
            CHECK(relative->axis_T_part[std::size_t(f)][p].rotation.angularDistance(relative->axis_T_part[0][p].rotation) < 1e-6);
        }
}

TEST_CASE("relative motion rejects an axis of the wrong length")
{
    const Take take = bunraku::test::livelyTake(10);
    const auto relative = relativeMotion(take, std::vector<RigidTransform>(4));
    REQUIRE_FALSE(relative.ok());
    CHECK(relative.error().code == ErrorCode::InvalidArgument);
}
