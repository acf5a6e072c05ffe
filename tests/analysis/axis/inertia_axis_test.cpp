#include "analysis/axis/inertia_axis.h"
#include "analysis/body/puppet_mass.h"

#include "tests/analysis/axis/puppet_fixture.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using bunraku::test::puppetTake;
using bunraku::test::rotationAbout;

namespace {

/// One solid driven by the take's shoulder, whose x is the forward reference.
BodyDescription singleSolid(const std::string& primitive)
{
    auto body = parseBodyDescription(R"({"parts": [{"name": "solid", "driven_by": "shoulder", "density": 1, "primitives": [)" +
                                         primitive + "]}]}",
                                     "solid.json");
    REQUIRE(body.ok());
    return std::move(body).value();
}

/// A take whose shoulder follows `pose(frame)`; the other parts stay at rest.
Take shoulderTake(Eigen::Index frames, const std::function<RigidTransform(Eigen::Index)>& pose)
{
    Take take = puppetTake(frames, [](Eigen::Index) { return RigidTransform{}; });
    for (Eigen::Index f = 0; f < frames; ++f) setPartPose(take, f, 6, pose(f));
    return take;
}

} // namespace

TEST_CASE("a long box rotated by a known rotation gives that rotation as its axis")
{
    // edges 4 (x) < 6 (y) < 40 (z): least moment about z, largest about x
    const AxisModel model = makeAxisModel(singleSolid(R"({"shape": "box", "size": [4, 6, 40]})"), {{0.5}});
    const auto [yaw, pitch, roll] = GENERATE(std::tuple{30.0, 20.0, 10.0}, std::tuple{-50.0, 5.0, -25.0}, std::tuple{0.0, 0.0, 0.0});
    const Eigen::Quaterniond rotation = rotationFromYawPitchRoll({yaw, pitch, roll});
    const Eigen::Vector3d position(10, -20, 90);
    const Take take = shoulderTake(2, [&](Eigen::Index) { return RigidTransform{rotation, position}; });
    AxisOptions principal;
    principal.frontBack = FrontBackAxis::Principal;
    const auto axis = computeMotionAxis(model, take, principal);
    REQUIRE(axis.ok());
    const RigidTransform& pose = axis->world_T_axis[1];
    CHECK((pose.rotation.toRotationMatrix() - rotation.toRotationMatrix()).norm() < 1e-6);
    CHECK((pose.translation - position).norm() < 1e-9);
    CHECK(axis->moments(1, 2) < axis->moments(1, 1));
    CHECK(axis->moments(1, 1) < axis->moments(1, 0));
    // the box's analytic moments (mass 960 g): m (b^2 + c^2) / 12 about each axis, the lattice's within 0.2 %
    CHECK(axis->moments(1, 2) == Approx(960.0 * (16 + 36) / 12.0).epsilon(0.01));
    CHECK(axis->moments(1, 0) == Approx(960.0 * (36 + 1600) / 12.0).epsilon(0.002));
    CHECK(axis->degenerateFrames.empty());
}

TEST_CASE("the inertia from part moments equals the brute-force inertia of the posed mass points")
{
    const AxisModel model = makeAxisModel(defaultBodyDescription(), {{2.0}});
    const Take take = bunraku::test::livelyTake(20);
    REQUIRE(model.massSource == MassSource::Model);
    const auto points = bodyMassPoints(model.body, {2.0});
    const auto poses = worldPartPoses(model.body, take, 13);
    const auto [centre, inertia] = inertiaAboutCentre(model.parts, poses);
    double mass = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t p = 0; p < points.size(); ++p)
        for (Eigen::Index k = 0; k < points[p].masses.size(); ++k) {
            mass += points[p].masses[k];
            sum += points[p].masses[k] * poses[p].apply(points[p].positions.col(k));
        }
    const Eigen::Vector3d expectedCentre = sum / mass;
    Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
    for (std::size_t p = 0; p < points.size(); ++p)
        for (Eigen::Index k = 0; k < points[p].masses.size(); ++k) {
            const Eigen::Vector3d r = poses[p].apply(points[p].positions.col(k)) - expectedCentre;
            expected += points[p].masses[k] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
        }
    CHECK((centre - expectedCentre).norm() < 1e-9);
    CHECK((inertia - expected).norm() < 1e-9 * expected.norm());
}

TEST_CASE("the puppet's axis stands up and faces forward at rest")
{
    const AxisModel model = makeAxisModel(defaultBodyDescription());
    const Take take = puppetTake(3, [](Eigen::Index) { return RigidTransform{}; });
    const auto axis = computeMotionAxis(model, take);
    REQUIRE(axis.ok());
    const Eigen::Matrix3d r = axis->world_T_axis[0].rotation.toRotationMatrix();
    CHECK(r.col(2).z() > 0.99);
    CHECK(r.col(0).x() > 0.99);
    // The modelled puppet is symmetric about the sagittal plane but for its hair ornaments: the
    // centre of mass lies within 0.05 cm of the plane; the description's primitives are exactly
    // symmetric.
    CHECK(std::abs(axis->world_T_axis[0].translation.y()) < 0.05);
    AxisOptions primitives;
    primitives.massPoints.source = MassSource::Primitives;
    const auto exact = computeMotionAxis(makeAxisModel(defaultBodyDescription(), primitives), take);
    REQUIRE(exact.ok());
    CHECK(std::abs(exact->world_T_axis[0].translation.y()) < 1e-9);
}

TEST_CASE("the axis never flips sign over a full turn")
{
    const AxisModel model = makeAxisModel(defaultBodyDescription(), {{2.0}});
    // An index, not the vectors: Catch2's GENERATE keeps Eigen temporaries past their scope.
    static const Eigen::Vector3d turnAxes[] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY(),
                                               Eigen::Vector3d(1, 1, 0.5).normalized()};
    const Eigen::Vector3d turnAxis = turnAxes[GENERATE(0, 1, 2)];
    const int frames = 73; // 5 degrees per frame
    const Take take = puppetTake(frames, [&](Eigen::Index f) { return rotationAbout(turnAxis, 5.0 * double(f)); });
    const auto axis = computeMotionAxis(model, take);
    REQUIRE(axis.ok());
    const Eigen::Matrix3d first = axis->world_T_axis[0].rotation.toRotationMatrix();
    for (int f = 1; f < frames; ++f) {
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(5.0 * f * M_PI / 180.0, turnAxis).toRotationMatrix();
        const Eigen::Matrix3d now = axis->world_T_axis[std::size_t(f)].rotation.toRotationMatrix();
        const Eigen::Matrix3d before = axis->world_T_axis[std::size_t(f - 1)].rotation.toRotationMatrix();
        INFO("frame " << f);
        CHECK((now - turn * first).norm() < 1e-6);
        CHECK(now.col(0).dot(before.col(0)) > 0.99);
        CHECK(now.col(2).dot(before.col(2)) > 0.99);
    }
}

TEST_CASE("degenerate inertia is detected and reported, the undetermined axes carried over")
{
    SECTION("a cylinder: middle = largest moment")
    {
        const AxisModel model = makeAxisModel(singleSolid(R"({"shape": "cylinder", "radius": 3, "length": 30})"), {{0.5}});
        const Take take = shoulderTake(5, [](Eigen::Index f) { return rotationAbout(Eigen::Vector3d::UnitZ(), 10.0 * double(f)); });
        AxisOptions principal;
        principal.frontBack = FrontBackAxis::Principal;
        const auto axis = computeMotionAxis(model, take, principal);
        REQUIRE(axis.ok());
        // the lattice breaks the symmetry only slightly; the tolerance makes it "equal"
        REQUIRE(axis->degenerateFrames.size() == 5);
        CHECK(axis->degenerateFrames[0].degeneracy == Degeneracy::CrossAxes);
        CHECK(axis->degeneracyReport().find("x, y undetermined") != std::string::npos);
        for (const RigidTransform& pose : axis->world_T_axis) {
            CHECK(pose.rotation.toRotationMatrix().col(2).z() == Approx(1.0));
            CHECK(pose.rotation.toRotationMatrix().col(0).x() == Approx(1.0)); // kept from the first frame's forward
        }
        // by default x is the shoulder's facing, which turns 10 degrees a frame
        const auto facing = computeMotionAxis(model, take);
        REQUIRE(facing.ok());
        CHECK(facing->degenerateFrames.size() == 5);
        CHECK_FALSE(facing->degenerateFrames[0].affectsAxis);
        CHECK(facing->degeneracyReport().empty()); // equal x/y moments do not matter when x is the shoulder's facing
        for (int f = 0; f < 5; ++f)
            CHECK(facing->world_T_axis[std::size_t(f)].rotation.toRotationMatrix().col(0).x() == Approx(std::cos(10.0 * f * M_PI / 180.0)));
    }
    SECTION("a sphere: all moments equal")
    {
        const AxisModel model = makeAxisModel(singleSolid(R"({"shape": "ellipsoid", "radii": [5, 5, 5]})"), {{0.5}});
        const Take take = shoulderTake(3, [](Eigen::Index) { return RigidTransform{}; });
        const auto axis = computeMotionAxis(model, take);
        REQUIRE(axis.ok());
        REQUIRE(axis->degenerateFrames.size() == 3);
        CHECK(axis->degenerateFrames[0].degeneracy == Degeneracy::Spherical);
        CHECK(axis->world_T_axis[2].rotation.isApprox(Eigen::Quaterniond::Identity(), 1e-12));
    }
    SECTION("the puppet is not degenerate")
    {
        const auto axis = computeMotionAxis(makeAxisModel(defaultBodyDescription(), {{2.0}}), bunraku::test::livelyTake(30));
        REQUIRE(axis.ok());
        CHECK(axis->degenerateFrames.empty());
        CHECK(axis->degeneracyReport().empty());
    }
}

TEST_CASE("the motion axis reports takes it cannot pose")
{
    Take take = bunraku::test::livelyTake(4);
    take.channels[3].dof = "heading";
    const auto axis = computeMotionAxis(makeAxisModel(defaultBodyDescription(), {{2.0}}), take);
    REQUIRE_FALSE(axis.ok());
    CHECK(axis.error().message.find("head") != std::string::npos);
    std::stop_source stop;
    stop.request_stop();
    const auto cancelled = computeMotionAxis(makeAxisModel(defaultBodyDescription(), {{2.0}}), bunraku::test::livelyTake(4), {},
                                             RunControl{stop.get_token(), {}});
    REQUIRE_FALSE(cancelled.ok());
    CHECK(cancelled.error().code == ErrorCode::Cancelled);
}

TEST_CASE("when the arms swing forward the x and y moments cross, and axis x stays on the shoulder's facing")
{
    const AxisModel model = makeAxisModel(defaultBodyDescription(), {{2.0}});
    // the arm and hand swing about the right shoulder joint from hanging to pointing forward;
    // the head leans forward and to the left, which breaks the left-right symmetry slightly
    const Take take = puppetTake(
        41, [](Eigen::Index) { return RigidTransform{}; },
        [](Eigen::Index f, int p) {
            if (p == 0) return RigidTransform{Eigen::Quaterniond::Identity(), Eigen::Vector3d(4, 4, 0)};
            if (p == 1) return RigidTransform{};
            // the bone (local x) turns from straight down (pitch 90) to forward (pitch 0); the arm
            // sensor is 10 cm and the hand sensor 24 cm along it from the shoulder joint
            const Eigen::Quaterniond bone(Eigen::AngleAxisd(M_PI / 2.0 * (1.0 - double(f) / 40.0), Eigen::Vector3d::UnitY()));
            const Eigen::Vector3d shoulderJoint(0, -9, 99);
            const double along = p == 2 ? 10.0 : 24.0;
            const RigidTransform world{bone, shoulderJoint + bone * Eigen::Vector3d(along, 0, 0)};
            return bunraku::test::restPose(p).inverse() * world;
        });
    AxisOptions principal;
    principal.frontBack = FrontBackAxis::Principal;
    const auto literal = computeMotionAxis(model, take, principal);
    const auto facing = computeMotionAxis(model, take);
    REQUIRE(literal.ok());
    REQUIRE(facing.ok());
    // the moments about the shoulder's x and y swap order over the swing
    const auto aboutWorld = [&](Eigen::Index f, const Eigen::Vector3d& direction) {
        const Eigen::Matrix3d r = literal->world_T_axis[std::size_t(f)].rotation.toRotationMatrix();
        const Eigen::Matrix3d inertia = r * literal->moments.row(f).transpose().asDiagonal() * r.transpose();
        return direction.dot(inertia * direction);
    };
    CHECK((aboutWorld(0, Eigen::Vector3d::UnitX()) > aboutWorld(0, Eigen::Vector3d::UnitY())) !=
          (aboutWorld(40, Eigen::Vector3d::UnitX()) > aboutWorld(40, Eigen::Vector3d::UnitY())));
    double largestTurn = 0.0;
    for (Eigen::Index f = 1; f <= 40; ++f) {
        const Eigen::Vector3d before = literal->world_T_axis[std::size_t(f - 1)].rotation * Eigen::Vector3d::UnitX();
        const Eigen::Vector3d now = literal->world_T_axis[std::size_t(f)].rotation * Eigen::Vector3d::UnitX();
        largestTurn = std::max(largestTurn, std::acos(std::clamp(before.dot(now), -1.0, 1.0)) * 180.0 / M_PI);
        CHECK((facing->world_T_axis[std::size_t(f)].rotation * Eigen::Vector3d::UnitX()).x() > 0.98); // z leans a little
    }
    // the principal x swings across to the old y within a few frames of the crossing
    CHECK(largestTurn > 10.0);
    const Eigen::Vector3d first = literal->world_T_axis.front().rotation * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d last = literal->world_T_axis.back().rotation * Eigen::Vector3d::UnitX();
    CHECK(std::abs(first.dot(last)) < 0.5);
}
