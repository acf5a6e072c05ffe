#include "analysis/axis/axis_channels.h"

#include "tests/analysis/axis/puppet_fixture.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using bunraku::test::rotationAbout;

TEST_CASE("the thesis's axis channels determine the pose")
{
    // An index is generated rather than the vectors themselves: Catch2's GENERATE keeps Eigen
    // temporaries past their scope (AddressSanitizer: stack-use-after-scope).
    static const Eigen::Vector3d directions[] = {{0.2, -0.5, 1}, {1, 0.3, -0.4}, {0, 1, 0}};
    const Eigen::Vector3d direction = directions[GENERATE(0, 1, 2)];
    const double degrees = GENERATE(-170.0, -35.0, 0.0, 12.0, 179.0);
    const RigidTransform pose = rotationAbout(direction, degrees, Eigen::Vector3d(1, -2, 95));
    const auto values = axisChannelValues(pose);
    CHECK(values.head<3>().transpose().isApprox(pose.translation));
    CHECK(values[5] > -180.0);
    CHECK(values[5] <= 180.0);
    CHECK(Eigen::Vector2d(values[3], values[4]).norm() <= 1.0 + 1e-12);
    const RigidTransform back = axisFromChannelValues(values);
    CHECK(back.rotation.angularDistance(pose.rotation) < 1e-9);
    CHECK((back.translation - pose.translation).norm() < 1e-12);
}

TEST_CASE("an axis take has the six thesis channels and reads back")
{
    MotionAxis axis;
    axis.labels.function = "greeting";
    for (int f = 0; f < 10; ++f) axis.world_T_axis.push_back(rotationAbout(Eigen::Vector3d(0.1, 0.2, 1), 20.0 * f, Eigen::Vector3d(f, 0, 90)));
    const Take take = axisTake(axis);
    REQUIRE(take.channelCount() == 6);
    CHECK(take.channels[5].name() == "axis.angle");
    CHECK(take.channels[3].name() == "axis.axis_x");
    CHECK(validateTake(take).ok());
    const auto poses = axisPosesFromTake(take);
    REQUIRE(poses.ok());
    for (std::size_t f = 0; f < poses->size(); ++f) CHECK((*poses)[f].rotation.angularDistance(axis.world_T_axis[f].rotation) < 1e-9);
}

TEST_CASE("axis coordinates are continuous through a full turn and invert exactly")
{
    std::vector<RigidTransform> poses;
    for (int f = 0; f < 100; ++f) poses.push_back(rotationAbout(Eigen::Vector3d(0.1, 0.2, 1), 7.0 * f, Eigen::Vector3d(0, f, 0)));
    const Eigen::MatrixXd coordinates = axisCoordinates(poses);
    for (Eigen::Index f = 1; f < coordinates.rows(); ++f) {
        INFO("frame " << f);
        CHECK((coordinates.row(f).tail<3>() - coordinates.row(f - 1).tail<3>()).norm() == Approx(7.0).epsilon(1e-9));
        CHECK(axisFromCoordinates(coordinates.row(f)).rotation.angularDistance(poses[std::size_t(f)].rotation) < 1e-9);
    }
    CHECK(coordinates.bottomRows(1).rightCols(3).norm() == Approx(7.0 * 99).epsilon(1e-9));
}
