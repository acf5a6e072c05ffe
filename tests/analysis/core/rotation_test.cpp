#include "analysis/core/rotation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace bunraku::analysis;

namespace {

Eigen::Quaterniond about(double angle, const Eigen::Vector3d& axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

double distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return std::abs(a.angularDistance(b)); }

} // namespace

TEST_CASE("exp undoes log for small, ordinary and near half-turn rotations")
{
    const Eigen::Vector3d axis(0.3, -0.5, 0.8);
    for (double angle : {0.0, 1e-12, 1e-9, 1e-5, 0.3, 1.5, 3.0, std::numbers::pi - 1e-9}) {
        INFO("angle " << angle);
        const Eigen::Quaterniond q = about(angle, axis);
        const Eigen::Vector3d r = logMap(q);
        CHECK(r.norm() == Approx(angle).margin(1e-12));
        if (angle > 1e-9) CHECK((r.normalized() - axis.normalized()).norm() < 1e-6);
        CHECK(distance(expMap(r), q) < 1e-12);
        // -q is the same rotation and has the same vector
        CHECK((logMap(Eigen::Quaterniond(-q.coeffs())) - r).norm() < 1e-12);
    }
}

TEST_CASE("a track of rotations gets rotation vectors continuous past half a turn")
{
    // A steady turn about z by 2.5 turns: the principal vector jumps at pi, the nearest does not.
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (int step = 0; step <= 250; ++step) {
        const double angle = 2.0 * std::numbers::pi * 2.5 * step / 250.0;
        const Eigen::Vector3d r = nearestRotationVector(about(angle, Eigen::Vector3d::UnitZ()), previous);
        CHECK((r - Eigen::Vector3d(0, 0, angle)).norm() < 1e-9);
        previous = r;
    }
    // The identity after a full turn stays at 2 pi along the previous axis.
    const Eigen::Vector3d turned = nearestRotationVector(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, 6.2));
    CHECK((turned - Eigen::Vector3d(0, 0, 2.0 * std::numbers::pi)).norm() < 1e-12);
}

TEST_CASE("the mean rotation is the centre of a symmetric spread and honours weights")
{
    const Eigen::Quaterniond centre = about(1.1, Eigen::Vector3d(1, 2, 3));
    std::vector<Eigen::Quaterniond> spread;
    for (const Eigen::Vector3d& d : {Eigen::Vector3d(0.4, 0, 0), Eigen::Vector3d(-0.4, 0, 0), Eigen::Vector3d(0, 0.3, 0.2),
                                     Eigen::Vector3d(0, -0.3, -0.2)})
        spread.push_back(centre * expMap(d));
    CHECK(distance(meanRotation(spread), centre) < 1e-10);
    // signs of quaternions do not matter
    spread[1].coeffs() = -spread[1].coeffs();
    CHECK(distance(meanRotation(spread), centre) < 1e-10);
    // two rotations weighted 3:1: a quarter of the way along the geodesic
    const Eigen::Quaterniond a = about(0.2, Eigen::Vector3d::UnitX());
    const Eigen::Quaterniond b = about(1.0, Eigen::Vector3d::UnitX());
    const std::vector<Eigen::Quaterniond> pair{a, b};
    const std::vector<double> weights{3.0, 1.0};
    CHECK(distance(meanRotation(pair, weights), about(0.4, Eigen::Vector3d::UnitX())) < 1e-10);
    CHECK(distance(meanRotation(std::vector<Eigen::Quaterniond>{}), Eigen::Quaterniond::Identity()) < 1e-15);
}

TEST_CASE("slerp runs along the shorter arc and rotation distance is the geodesic angle")
{
    const Eigen::Quaterniond a = about(0.3, Eigen::Vector3d::UnitY());
    Eigen::Quaterniond b = about(1.3, Eigen::Vector3d::UnitY());
    b.coeffs() = -b.coeffs(); // the same rotation, the other hemisphere
    CHECK(distance(slerpShortest(a, b, 0.5), about(0.8, Eigen::Vector3d::UnitY())) < 1e-12);
    CHECK(rotationDistance(a, b) == Approx(1.0).margin(1e-12));
    CHECK(distance(slerpShortest(a, b, 0.0), a) < 1e-15);
}
