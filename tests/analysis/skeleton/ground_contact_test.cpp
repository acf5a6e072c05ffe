// A body put on the floor (analysis/skeleton/ground_contact.h), checked against geometry worked
// out by hand: a pelvis on two legs of 40 + 40 cm, each ending in a 10 cm foot.
#include "analysis/core/rotation.h"
#include "analysis/skeleton/ground_contact.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

using namespace bunraku::analysis;

namespace {

/// pelvis (root) -> hip_L / hip_R (+-10 cm across) -> knee (40 cm down) -> ankle (40 cm down)
/// -> toe (10 cm forward) -> End Site; a spine going up from the pelvis.
std::shared_ptr<const Skeleton> legs()
{
    auto s = std::make_shared<Skeleton>();
    s->name = "legs";
    auto add = [&](const std::string& name, int parent, Eigen::Vector3d offset, bool end = false) {
        SkeletonJoint j;
        j.name = name;
        j.parent = parent;
        j.offset = offset;
        j.endSite = end;
        s->joints.push_back(j);
        return int(s->joints.size()) - 1;
    };
    const int pelvis = add("pelvis", -1, {0, 0, 0});
    add("spine_End", add("spine", pelvis, {0, 0, 10}), {0, 0, 40}, true);
    for (const double side : {1.0, -1.0}) {
        const int hip = add(side > 0 ? "hip_L" : "hip_R", pelvis, {0, 10 * side, 0});
        const int knee = add(side > 0 ? "knee_L" : "knee_R", hip, {0, 0, -40});
        const int ankle = add(side > 0 ? "ankle_L" : "ankle_R", knee, {0, 0, -40});
        add(side > 0 ? "toe_L_End" : "toe_R_End", ankle, {10, 0, 0}, true);
    }
    return s;
}

/// Knees bent by `bend` (thighs forward, shins back) with the pelvis at `height`.
SkeletalMotion crouch(double bend, double height)
{
    SkeletalMotion m = makeRestMotion(legs(), 1);
    m.movingJoints = {0};
    m.movingTranslations = Eigen::RowVector3d(0, 0, height);
    for (const char* side : {"_L", "_R"}) {
        m.rotation(0, m.skeleton->find(std::string("hip") + side)) = Eigen::Quaterniond(Eigen::AngleAxisd(-bend / 2, Eigen::Vector3d::UnitY()));
        m.rotation(0, m.skeleton->find(std::string("knee") + side)) = Eigen::Quaterniond(Eigen::AngleAxisd(bend, Eigen::Vector3d::UnitY()));
        m.rotation(0, m.skeleton->find(std::string("ankle") + side)) = Eigen::Quaterniond(Eigen::AngleAxisd(-bend / 2, Eigen::Vector3d::UnitY()));
    }
    return m;
}

double boneLengthChange(const SkeletalMotion& a, const SkeletalMotion& b)
{
    const auto pa = a.worldPoses(0), pb = b.worldPoses(0);
    double worst = 0.0;
    for (std::size_t j = 0; j < pa.size(); ++j) {
        const int parent = a.skeleton->joints[j].parent;
        if (parent < 0) continue;
        const double la = (pa[j].translation - pa[std::size_t(parent)].translation).norm();
        const double lb = (pb[j].translation - pb[std::size_t(parent)].translation).norm();
        worst = std::max(worst, std::abs(la - lb));
    }
    return worst;
}

} // namespace

TEST_CASE("the legs of a body on two legs are found from its skeleton", "[ground]")
{
    const SkeletalMotion m = crouch(0.6, 80.0);
    const LegLayout layout = findLegs(m);
    REQUIRE(layout.pelvis == m.skeleton->find("pelvis"));
    REQUIRE(layout.legs.size() == 2);
    CHECK(layout.legs[0].hip == m.skeleton->find("hip_L"));
    CHECK(layout.legs[0].knee == m.skeleton->find("knee_L"));
    CHECK(layout.legs[0].ankle == m.skeleton->find("ankle_L"));
    CHECK(layout.legs[1].ankle == m.skeleton->find("ankle_R"));
}

TEST_CASE("a crouch held higher straightens its legs and keeps its feet flat on the floor", "[ground]")
{
    // Knees bent 60 deg: the ankles 2 x 40 cos 30 deg = 69.28 cm below the hips. The toes on the
    // floor (z = 0) with the pelvis at 69.28 cm.
    const double bend = std::numbers::pi / 3;
    const double drop = 80.0 * std::cos(bend / 2);
    const SkeletalMotion m = crouch(bend, drop);
    REQUIRE(lowestPoints(m)(0) == Approx(0.0).margin(1e-9));
    // Held 5 cm higher with the feet on the floor: the legs straighten to reach 74.28 cm.
    const Eigen::VectorXd pelvis = Eigen::VectorXd::Constant(1, drop + 5.0);
    const Eigen::VectorXd floor = Eigen::VectorXd::Zero(1);
    const auto grounded = groundBody(m, pelvis, floor);
    REQUIRE(grounded);
    const auto poses = grounded->worldPoses(0);
    CHECK(poses[std::size_t(m.skeleton->find("pelvis"))].translation.z() == Approx(drop + 5.0).margin(1e-9));
    CHECK(lowestPoints(*grounded)(0) == Approx(0.0).margin(1e-9));
    CHECK(boneLengthChange(m, *grounded) < 1e-9);
    const auto before = m.worldPoses(0);
    for (const char* side : {"_L", "_R"}) {
        const auto ankle = std::size_t(m.skeleton->find(std::string("ankle") + side));
        const auto hip = std::size_t(m.skeleton->find(std::string("hip") + side));
        // The foot keeps its orientation (flat), the ankle stays under the same point across.
        CHECK(rotationDistance(poses[ankle].rotation, before[ankle].rotation) < 1e-9);
        CHECK(poses[ankle].translation.y() == Approx(before[ankle].translation.y()).margin(1e-9));
        CHECK(poses[ankle].translation.z() == Approx(0.0).margin(1e-9));
        // The knee's bend from the law of cosines: |hip - ankle| = 74.28 cm.
        CHECK((poses[ankle].translation - poses[hip].translation).norm() == Approx(drop + 5.0).margin(1e-9));
    }
}

TEST_CASE("a body held higher than its stretched legs reach is lowered until its feet touch", "[ground]")
{
    const SkeletalMotion m = crouch(0.4, 75.0);
    const Eigen::VectorXd pelvis = Eigen::VectorXd::Constant(1, 95.0); // legs reach 80 cm
    const Eigen::VectorXd floor = Eigen::VectorXd::Zero(1);
    const auto grounded = groundBody(m, pelvis, floor);
    REQUIRE(grounded);
    CHECK(lowestPoints(*grounded)(0) == Approx(0.0).margin(1e-9)); // no foot above or below the floor
    const double height = grounded->worldPoses(0)[0].translation.z();
    CHECK(height == Approx(80.0).margin(1e-6)); // stretched straight down
    CHECK(boneLengthChange(m, *grounded) < 1e-9);
}
