#include "analysis/core/angle_channels.h"
#include "analysis/core/rotation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace bunraku::analysis;

namespace {

/// A 24-channel take whose parts turn through the gimbal region (pitch passing +-90) and
/// around (yaw over a full turn), written with the continuous filter.
Take turningTake(Eigen::Index frames = 120)
{
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(frames, kPuppetChannelCount);
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double t = double(f) / double(frames - 1);
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const Eigen::Quaterniond q = Eigen::AngleAxisd(2.0 * std::numbers::pi * t * (p + 1) / 2.0, Eigen::Vector3d::UnitZ()) *
                                         Eigen::AngleAxisd(2.2 * std::sin(3.0 * t + p), Eigen::Vector3d::UnitY()) *
                                         Eigen::AngleAxisd(0.7 * std::cos(5.0 * t), Eigen::Vector3d::UnitX());
            setPartPose(take, f, p * kDofCount, RigidTransform{q, Eigen::Vector3d(p, 2.0 * t, 100.0 - p)});
        }
    }
    return take;
}

/// Each angle triple replaced by an equivalent one (mirrored every other frame, whole turns).
Take otherBranches(Take take)
{
    for (const auto& part : sixDofParts(take))
        for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
            const Eigen::Index c = part.firstChannel;
            if (f % 2) {
                take.values(f, c + 3) += 180.0 - 360.0;
                take.values(f, c + 4) = 180.0 - take.values(f, c + 4);
                take.values(f, c + 5) += 180.0 + 720.0;
            } else {
                take.values(f, c + 3) += 360.0 * double(f % 3);
            }
        }
    return take;
}

double maxRotationDifference(const Take& a, const Take& b)
{
    double worst = 0.0;
    for (const auto& part : sixDofParts(a)) {
        const auto ra = partRotations(a, part);
        const auto rb = partRotations(b, part);
        for (std::size_t f = 0; f < ra.size(); ++f) worst = std::max(worst, rotationDistance(ra[f], rb[f]));
    }
    return worst;
}

} // namespace

TEST_CASE("rotation coordinates do not depend on the Euler branch the take is written on")
{
    const Take take = turningTake();
    const Take jumpy = otherBranches(take);
    CHECK(maxRotationDifference(take, jumpy) < 1e-9); // the same orientations
    const RotationChart chart = meanPartChart({&take});
    REQUIRE(chart.tracks == 4);
    const Eigen::MatrixXd a = rotationCoordinates(take, chart);
    const Eigen::MatrixXd b = rotationCoordinates(jumpy, chart);
    CHECK((a - b).cwiseAbs().maxCoeff() < 1e-7);
    // the coordinates are continuous: the parts turning by up to two turns about their mean pass
    // half a turn without a jump (past half a turn the vectors stretch, but never jump a turn)
    for (Eigen::Index f = 1; f < a.rows(); ++f)
        for (int p = 0; p < 4; ++p) CHECK((a.row(f).segment(p * 6 + 3, 3) - a.row(f - 1).segment(p * 6 + 3, 3)).norm() < 60.0);
    // positions are untouched
    CHECK((a.col(0) - take.values.col(0)).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("rotation coordinates come back as the same orientations on a continuous branch")
{
    const Take take = turningTake();
    for (ChartTime time : {ChartTime::Constant, ChartTime::PerFrame}) {
        const RotationChart chart = meanPartChart({&take}, time);
        const Eigen::MatrixXd coordinates = rotationCoordinates(take, chart);
        Take back = take;
        back.values = eulerFromRotationCoordinates(take, coordinates, chart, Eigen::RowVectorXd(take.values.row(0)));
        CHECK(maxRotationDifference(take, back) < 1e-9);
        // the filtered numbers equal the continuously written ones
        CHECK((back.values - take.values).cwiseAbs().maxCoeff() < 1e-6);
    }
}

TEST_CASE("the Euler filter removes branch jumps, keeps orientations and counts the jumps")
{
    const Take take = turningTake();
    Take jumpy = otherBranches(take);
    const int removed = filterEulerAngles(jumpy);
    CHECK(removed == 4 * int(take.frameCount() - 1)); // every frame changes branch in the jumpy take
    CHECK(maxRotationDifference(take, jumpy) < 1e-9);
    // nearest the previous frame all along: the first frame decides the branch
    Take expected = take;
    const Eigen::RowVectorXd first = jumpy.values.row(0);
    expected.values.row(0) = first;
    CHECK(filterEulerAngles(expected) >= 0);
    CHECK((jumpy.values - expected.values).cwiseAbs().maxCoeff() < 1e-6);
    // a filtered take is left bit for bit
    Take again = jumpy;
    CHECK(filterEulerAngles(again) == 0);
    CHECK(again.values == jumpy.values);
}

TEST_CASE("a part moved onto the reference's branch keeps its orientations and continuity")
{
    const Take reference = turningTake();
    Take take = reference;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        // the whole arm on the mirrored triple, the head one turn up in yaw
        take.values(f, 2 * 6 + 3) += 180.0;
        take.values(f, 2 * 6 + 4) = 180.0 - take.values(f, 2 * 6 + 4);
        take.values(f, 2 * 6 + 5) -= 180.0;
        take.values(f, 3) += 360.0;
    }
    CHECK(matchPartBranches(take, reference) == 3); // one turn for the head; the arm mirrored and turned once
    CHECK((take.values - reference.values).cwiseAbs().maxCoeff() < 1e-9);
}
