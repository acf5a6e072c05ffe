#include "analysis/body/body_pose.h"

#include "tests/analysis/axis/puppet_fixture.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using bunraku::test::livelyTake;

namespace {

/// Mass, world centre and world second moment (about the origin) of one part's mass points.
struct WorldMoments {
    double mass = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};

WorldMoments worldMoments(const MassPoints& points, const RigidTransform& world_T_part)
{
    WorldMoments m;
    for (Eigen::Index k = 0; k < points.masses.size(); ++k) {
        const Eigen::Vector3d p = world_T_part.apply(points.positions.col(k));
        m.mass += points.masses[k];
        m.centre += points.masses[k] * p;
        m.second += points.masses[k] * p * p.transpose();
    }
    m.centre /= m.mass;
    return m;
}

} // namespace

TEST_CASE("mirrored limbs are the reflection of the right limbs across the shoulder's sagittal plane")
{
    const BodyDescription& body = defaultBodyDescription();
    const Take take = livelyTake(40);
    const auto points = sampleMassPoints(body, {2.0});
    const int shoulder = body.partIndex("shoulder");
    for (Eigen::Index frame : {Eigen::Index(0), Eigen::Index(17), Eigen::Index(39)}) {
        const auto poses = worldPartPoses(body, take, frame);
        REQUIRE(poses.size() == body.parts.size());
        const Eigen::Matrix3d shoulderR = poses[std::size_t(shoulder)].rotation.toRotationMatrix();
        const Eigen::Matrix3d reflection = shoulderR * Eigen::Vector3d(1, -1, 1).asDiagonal() * shoulderR.transpose();
        const Eigen::Vector3d origin = poses[std::size_t(shoulder)].translation;
        for (const auto& [left, right] : {std::pair{"left_arm", "right_arm"}, std::pair{"left_hand", "right_hand"}}) {
            const auto l = std::size_t(body.partIndex(left));
            const auto r = std::size_t(body.partIndex(right));
            CHECK(poses[l].rotation.toRotationMatrix().determinant() == Approx(1.0));
            const WorldMoments ml = worldMoments(points[l], poses[l]);
            const WorldMoments mr = worldMoments(points[r], poses[r]);
            CHECK(ml.mass == Approx(mr.mass));
            const Eigen::Vector3d mirroredCentre = origin + reflection * (mr.centre - origin);
            CHECK((ml.centre - mirroredCentre).norm() < 1e-9);
            // second moments about the shoulder origin reflect as M S M^T
            const Eigen::Matrix3d sl = ml.second - ml.mass * (origin * ml.centre.transpose() + ml.centre * origin.transpose()) +
                                       ml.mass * origin * origin.transpose();
            const Eigen::Matrix3d sr = mr.second - mr.mass * (origin * mr.centre.transpose() + mr.centre * origin.transpose()) +
                                       mr.mass * origin * origin.transpose();
            CHECK((sl - reflection * sr * reflection.transpose()).norm() < 1e-6 * sr.norm());
            // and the left limb really is on the puppet's left (+y of the shoulder frame)
            CHECK((shoulderR.transpose() * (ml.centre - origin)).y() > 5.0);
            CHECK((shoulderR.transpose() * (mr.centre - origin)).y() < -5.0);
        }
    }
}

TEST_CASE("a mirrored pose maps reflected local points onto the mirror images")
{
    const RigidTransform source{Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())),
                                Eigen::Vector3d(3, -12, 95)};
    const RigidTransform frame{Eigen::Quaterniond(Eigen::AngleAxisd(-0.4, Eigen::Vector3d(0.2, 0.1, 1).normalized())),
                               Eigen::Vector3d(1, 2, 100)};
    const RigidTransform mirrored = mirroredPose(source, frame);
    const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, 1).asDiagonal();
    const Eigen::Matrix3d frameR = frame.rotation.toRotationMatrix();
    for (const Eigen::Vector3d& q : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-4, 0.5, -20)}) {
        const Eigen::Vector3d world = source.apply(q);
        const Eigen::Vector3d image = frame.translation + frameR * flip * frameR.transpose() * (world - frame.translation);
        CHECK((mirrored.apply(flip * q) - image).norm() < 1e-12);
    }
}

TEST_CASE("sampled mass points carry each primitive's analytic mass and centre")
{
    const auto body = parseBodyDescription(R"({"parts": [{"name": "p", "driven_by": "head", "density": 0.5, "primitives": [
        {"shape": "ellipsoid", "radii": [3, 4, 5], "position": [1, 2, 3]},
        {"shape": "frustum", "radius": 4, "top_radius": 2, "length": 10, "position": [0, 0, -20], "density": 2}]}]})",
                                           "sample.json");
    REQUIRE(body.ok());
    const auto points = sampleMassPoints(*body, {0.5});
    REQUIRE(points.size() == 1);
    CHECK(points[0].masses.sum() == Approx(body->mass()));
    const PartMoments moments = partMoments(points[0]);
    // analytic centre: ellipsoid at (1,2,3); frustum centroid at z = -20 - h (R^2 + 2Rr + 3r^2)/(4(R^2+Rr+r^2)) + h/2 ...
    const double h = 10, big = 4, small = 2;
    const double frustumCentroid = -20 - h / 2 + h * (big * big + 2 * big * small + 3 * small * small) /
                                                     (4 * (big * big + big * small + small * small));
    const double me = body->parts[0].primitives[0].mass();
    const double mf = body->parts[0].primitives[1].mass();
    const Eigen::Vector3d expected = (me * Eigen::Vector3d(1, 2, 3) + mf * Eigen::Vector3d(0, 0, frustumCentroid)) / (me + mf);
    CHECK((moments.centre - expected).norm() < 0.05);
}

TEST_CASE("binding names the missing take part")
{
    Take take = livelyTake(3);
    take.channels[6].part = "torso"; // shoulder.x renamed
    const auto binding = bindBody(defaultBodyDescription(), take);
    REQUIRE_FALSE(binding.ok());
    CHECK(binding.error().code == ErrorCode::NotFound);
    CHECK(binding.error().message.find("shoulder") != std::string::npos);
}
