// The whole-body motion axis (issue 25): de Leva's segments found on every fixture family and on
// the shared Bandai takes, checked against the published table, against the segments' own
// inertia summed by the parallel-axis theorem, and on the performer standing and waving.
#include "analysis/axis/axis_channels.h"
#include "analysis/axis/segment_inertia.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/body/body_pose.h"
#include "analysis/design/motion_design.h"
#include "analysis/design/warp_curve.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/bvh.h"
#include "analysis/io/take_reader.h"

#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"
#include "tests/support/fixture_joint_take.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace bunraku::analysis;
using bunraku::test::BvhFamily;

namespace {

constexpr double kPi = 3.14159265358979323846;

double degreesFromVertical(const RigidTransform& world_T_axis)
{
    const Eigen::Vector3d z = world_T_axis.rotation * Eigen::Vector3d::UnitZ();
    return std::acos(std::clamp(z.z(), -1.0, 1.0)) * 180.0 / kPi;
}

/// The body's inertia about its centre from the segments alone (each its own moments plus the
/// parallel-axis term): the peer of the joints' reduced moments.
std::pair<Eigen::Vector3d, Eigen::Matrix3d> segmentsInertia(const std::vector<BodySegment>& segments)
{
    double mass = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    for (const auto& s : segments) {
        mass += s.mass;
        first += s.mass * s.centre;
    }
    const Eigen::Vector3d centre = first / mass;
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (const auto& s : segments) {
        const Eigen::Vector3d d = s.centre - centre;
        inertia += s.inertia + s.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
    return {centre, inertia};
}

} // namespace

TEST_CASE("de Leva's segment tables add up to the whole body", "[axis][segments]")
{
    for (const SegmentTable table : {SegmentTable::DeLevaMale, SegmentTable::DeLevaFemale}) {
        INFO(segmentTableName(table));
        double sum = 0.0;
        for (const SegmentKind kind : {SegmentKind::Head, SegmentKind::Trunk}) sum += segmentParameters(table, kind).massFraction;
        for (const SegmentKind kind : {SegmentKind::UpperArm, SegmentKind::Forearm, SegmentKind::Hand, SegmentKind::Thigh,
                                       SegmentKind::Shank, SegmentKind::Foot})
            sum += 2.0 * segmentParameters(table, kind).massFraction;
        CHECK(sum == Approx(1.0).margin(2e-4));
        CHECK(segmentTableFromName(segmentTableName(table)) == table);
    }
    // Spot values of Table 4 (males): the trunk 43.46 %, its centre 51.38 % from C7; the thigh's radii.
    CHECK(segmentParameters(SegmentTable::DeLevaMale, SegmentKind::Trunk).massFraction == 0.4346);
    CHECK(segmentParameters(SegmentTable::DeLevaMale, SegmentKind::Trunk).centreFraction == 0.5138);
    CHECK(segmentParameters(SegmentTable::DeLevaMale, SegmentKind::Thigh).radiusLongitudinal == 0.149);
    CHECK(segmentTableBodyMassKg(SegmentTable::DeLevaFemale) == 61.9);
}

TEST_CASE("the whole-body segments are found on every fixture family", "[axis][segments]")
{
    const auto& points = bunraku::test::canonicalPoints();
    for (const BvhFamily& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        const Take take = bunraku::test::fixtureJointTake(family);
        REQUIRE(usesSegmentModel(take));
        auto body = segmentBody(take);
        INFO((body.ok() ? std::string() : body.error().message));
        REQUIRE(body.ok());
        std::map<std::string, int> kinds;
        for (const auto& s : body->segments) ++kinds[segmentKindName(s.kind)];
        CHECK(kinds == std::map<std::string, int>{{"head", 1}, {"trunk", 1}, {"upper_arm", 2}, {"forearm", 2}, {"hand", 2},
                                                  {"thigh", 2}, {"shank", 2}, {"foot", 2}});
        // The limbs' ends are the canonical performer's joint centres (frame 0 stands on them);
        // the cmu-asf arm's wrist and hand joints, the collars and the fingers are told apart.
        const auto near = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() < 0.5; };
        for (const auto& s : body->segments) {
            INFO(segmentKindName(s.kind) << " of " << s.chain << ": " << s.proximal.transpose() << " -> " << s.distal.transpose());
            const std::string side = s.chain.starts_with("left") ? "L" : "R";
            switch (s.kind) {
            case SegmentKind::UpperArm:
                CHECK(near(s.proximal, points.at("shoulder" + side)));
                CHECK(near(s.distal, points.at("elbow" + side)));
                break;
            case SegmentKind::Forearm: CHECK(near(s.distal, points.at("wrist" + side))); break;
            case SegmentKind::Thigh:
                CHECK(near(s.proximal, points.at("hip" + side)));
                CHECK(near(s.distal, points.at("knee" + side)));
                break;
            case SegmentKind::Shank: CHECK(near(s.distal, points.at("ankle" + side))); break;
            case SegmentKind::Foot: CHECK(s.distal.x() > s.proximal.x() + 10.0); break; // forward to the toes
            case SegmentKind::Trunk:
                CHECK(near(s.distal, 0.5 * (points.at("hipL") + points.at("hipR"))));
                CHECK(s.proximal.z() > 135.0); // C7, about the shoulders' height
                CHECK(s.proximal.z() < 145.0);
                break;
            case SegmentKind::Head: CHECK(s.proximal.z() > 155.0); break; // the vertex above the head joint
            case SegmentKind::Hand: CHECK(s.distal.z() < s.proximal.z()); break; // hanging
            }
        }
        const AxisModel& model = body->model;
        CHECK(model.massSource == MassSource::Segments);
        CHECK(model.totalMass == Approx(73000.0).epsilon(1e-9));
        // The joints' moments, posed at frame 0, give the segments' inertia (parallel axes): the
        // six points of each segment carry its mass, centre and principal moments exactly, and
        // each joint's frame takes them there and back.
        const auto poses = worldPartPoses(model.body, take, 0);
        const auto [centre, inertia] = inertiaAboutCentre(model.parts, poses);
        const auto [peerCentre, peerInertia] = segmentsInertia(body->segments);
        CHECK((centre - peerCentre).norm() < 1e-6);
        CHECK((inertia - peerInertia).norm() < 1e-6 * peerInertia.norm());
        // A standing adult: the centre of mass at 53-58 % of the 172 cm height, the long axis
        // vertical, moments of the order measured on standing men (Santschi et al. 1963: about
        // 1.2 kg m^2 about the long axis, 11-13 kg m^2 across it).
        CHECK(centre.z() > 0.53 * 172.0);
        CHECK(centre.z() < 0.58 * 172.0);
        auto axis = computeMotionAxis(model, take);
        REQUIRE(axis.ok());
        CHECK(degreesFromVertical(axis->world_T_axis[0]) < 5.0);
        const Eigen::Vector3d moments = axis->moments.row(0).transpose() * 1e-7; // kg m^2
        INFO("moments (kg m^2): " << moments.transpose());
        CHECK(moments.z() > 0.6);
        CHECK(moments.z() < 2.5);
        CHECK(moments.x() > 8.0);
        CHECK(moments.x() < 16.0);
        CHECK(moments.y() > 8.0);
        CHECK(moments.y() < 16.0);
        // Axis x is the performer's front (+x of the canonical performer).
        CHECK((axis->world_T_axis[0].rotation * Eigen::Vector3d::UnitX()).x() > 0.95);
    }
}

TEST_CASE("the female table weighs 61.9 kg and moves the centre of mass by its own fractions", "[axis][segments]")
{
    const Take take = bunraku::test::fixtureJointTake(bunraku::test::bvhFamilies().front());
    auto male = segmentBody(take);
    auto female = segmentBody(take, {SegmentTable::DeLevaFemale});
    REQUIRE(male.ok());
    REQUIRE(female.ok());
    CHECK(female->model.totalMass == Approx(61900.0).epsilon(1e-9));
    // The women's thighs are 14.78 % of the body (men's 14.16 %) with their centre at 36.12 %
    // of the thigh (40.95 %): the segments' masses follow the table, part by part.
    for (std::size_t k = 0; k < female->segments.size(); ++k) {
        const auto& s = female->segments[k];
        // (The published fractions add up to 99.99 %: scaled by 1 / 0.9999 to the whole body.)
        CHECK(s.mass == Approx(segmentParameters(SegmentTable::DeLevaFemale, s.kind).massFraction * 61900.0 / 0.9999));
        CHECK(male->segments[k].kind == s.kind);
    }
    const auto poses = worldPartPoses(female->model.body, take, 0);
    const auto [centre, inertia] = inertiaAboutCentre(female->model.parts, poses);
    const auto [peerCentre, peerInertia] = segmentsInertia(female->segments);
    CHECK((centre - peerCentre).norm() < 1e-6);
    CHECK((inertia - peerInertia).norm() < 1e-6 * peerInertia.norm());
}

TEST_CASE("a take without a skeleton or without its joints has no whole-body axis, and says why", "[axis][segments]")
{
    Take take;
    take.channels = sixDofChannels("thing");
    take.values = Eigen::MatrixXd::Zero(3, 6);
    take.rateHz = 30.0;
    CHECK_FALSE(usesSegmentModel(take));
    auto none = segmentBody(take);
    REQUIRE_FALSE(none.ok());
    CHECK(none.error().message.find("no skeleton") != std::string::npos);

    // The skeleton of a family whose take kept only some joints: the missing joint is named.
    BvhFamily family = bunraku::test::bvhFamilies().front();
    Take joints = bunraku::test::fixtureJointTake(family);
    const std::string thigh = bunraku::test::fixtureJointAt(family, "hipL");
    const auto first = std::find_if(joints.channels.begin(), joints.channels.end(), [&](const Channel& c) { return c.part == thigh; });
    REQUIRE(first != joints.channels.end());
    const Eigen::Index column = first - joints.channels.begin();
    joints.channels.erase(first, first + 6);
    Eigen::MatrixXd kept(joints.values.rows(), joints.values.cols() - 6);
    kept << joints.values.leftCols(column), joints.values.rightCols(joints.values.cols() - column - 6);
    joints.values = kept;
    auto missing = segmentBody(joints);
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error().message.find(thigh + ".x..roll") != std::string::npos);
}

TEST_CASE("the whole-body axis of the Bandai performers stays within 10 degrees of vertical", "[axis][segments][bandai]")
{
    const auto files = bunraku::test::bandaiFilesOrSkip();
    io::ImportOptions options;
    options.bvhLayout = io::BvhTakeLayout::AllJoints;
    for (const auto& file : files) {
        INFO(file.filename().string());
        auto take = io::readTakeFile(file, options);
        REQUIRE(take.ok());
        auto body = segmentBody(*take);
        INFO((body.ok() ? std::string() : body.error().message));
        REQUIRE(body.ok());
        CHECK(body->segments.size() == 14);
        auto axis = computeMotionAxis(body->model, *take);
        REQUIRE(axis.ok());
        double worst = 0.0;
        for (const auto& pose : axis->world_T_axis) worst = std::max(worst, degreesFromVertical(pose));
        CHECK(worst < 10.0);
        // The centre of mass of a standing adult lies a little above the hip joints, whatever the
        // knees do (hip joint centres at about 0.50-0.53 of the stature, the centre of mass at
        // about 0.55-0.57): within 0-12 cm above their midpoint at every frame.
        std::optional<Eigen::Index> hips, hipsR;
        for (const SixDofPart& part : sixDofParts(*take)) {
            if (part.part == "UpperLeg_L") hips = part.firstChannel;
            if (part.part == "UpperLeg_R") hipsR = part.firstChannel;
        }
        REQUIRE(hips);
        REQUIRE(hipsR);
        double low = 1e9, high = -1e9;
        for (Eigen::Index f = 0; f < take->frameCount(); ++f) {
            const double midHip = 0.5 * (partPose(*take, f, *hips).translation.z() + partPose(*take, f, *hipsR).translation.z());
            low = std::min(low, axis->world_T_axis[std::size_t(f)].translation.z() - midHip);
            high = std::max(high, axis->world_T_axis[std::size_t(f)].translation.z() - midHip);
        }
        INFO("centre of mass above the hips: " << low << " .. " << high << " cm");
        CHECK(low > 0.0);
        CHECK(high < 12.0);
    }
}

TEST_CASE("a design on a Bandai performer's whole-body axis moves every joint as the designed axis", "[axis][segments][bandai]")
{
    const auto files = bunraku::test::bandaiFilesOrSkip();
    if (files.empty()) return;
    io::ImportOptions options;
    options.bvhLayout = io::BvhTakeLayout::AllJoints;
    auto functional = io::readTakeFile(bunraku::test::bandaiDir() / "wave-right-hand_normal_001.bvh", options);
    auto emotional = io::readTakeFile(bunraku::test::bandaiDir() / "wave-right-hand_active_001.bvh", options);
    REQUIRE(functional.ok());
    REQUIRE(emotional.ok());
    auto model = segmentBody(*functional);
    REQUIRE(model.ok());
    auto basis = prepareDesign(model->model, *functional);
    REQUIRE(basis.ok());
    auto emotionalModel = segmentBody(*emotional);
    REQUIRE(emotionalModel.ok());
    auto emotionalAxis = computeMotionAxis(emotionalModel->model, *emotional);
    REQUIRE(emotionalAxis.ok());
    auto extracted = extractDesign(basis->coordinates, axisCoordinates(emotionalAxis->world_T_axis));
    REQUIRE(extracted.ok());
    const DesignedMotion designed = designMotion(*basis, extracted->phase.curve, extracted->gains);
    // Every joint of the skeleton is a channel of the designed take, and the designed take's own
    // whole-body axis (its joints integrated again) is the designed axis.
    REQUIRE(designed.take.channels.size() == functional->channels.size());
    REQUIRE(designed.take.skeleton);
    auto again = segmentBody(designed.take);
    REQUIRE(again.ok());
    auto axis = computeMotionAxis(again->model, designed.take);
    REQUIRE(axis.ok());
    REQUIRE(axis->frameCount() == Eigen::Index(designed.world_T_axis.size()));
    double centre = 0.0, angle = 0.0;
    for (std::size_t u = 0; u < designed.world_T_axis.size(); ++u) {
        centre = std::max(centre, (axis->world_T_axis[u].translation - designed.world_T_axis[u].translation).norm());
        angle = std::max(angle, axis->world_T_axis[u].rotation.angularDistance(designed.world_T_axis[u].rotation) * 180.0 / kPi);
    }
    INFO("centre " << centre << " cm, angle " << angle << " deg");
    // (The designed joints are slerped between source frames one by one, the axis as a whole.)
    CHECK(centre < 0.5);
    CHECK(angle < 2.0);
    // Designing with the extracted phase and gains comes near the emotional take's axis (5.5).
    const Eigen::MatrixXd measured = axisCoordinates(emotionalAxis->world_T_axis);
    REQUIRE(designed.axisCoordinates.rows() == measured.rows());
    const double designError = relativeError(designed.axisCoordinates, measured);
    INFO("design error " << designError);
    CHECK(designError < 0.2);
}
