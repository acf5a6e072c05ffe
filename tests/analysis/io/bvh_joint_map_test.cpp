// The automatic part map and the calibrated, upright part frames, on every fixture family
// (tests/support/bvh_fixtures.h) and on every shared Bandai file.
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_anatomy.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/bvh_joint_map.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using bunraku::test::BvhFamily;
using Catch::Matchers::Contains;

namespace {

double degreesBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

BvhFile parsedFixture(const BvhFamily& family, bool leftWave = false)
{
    auto file = parseBvh(bunraku::test::fixtureBvh(family, 12, leftWave), family.id + ".bvh");
    INFO(family.id << ": " << (file.ok() ? std::string() : file.error().message));
    REQUIRE(file.ok());
    return std::move(file).value();
}

BvhImportOptions importOptions(BodySide side = BodySide::Right)
{
    BvhImportOptions options;
    options.guessUnits = true;
    options.side = side;
    return options;
}

/// The invariants of an upright, attached puppet at every frame of `take`: head above shoulder
/// above hips, the shoulder's and head's z within `tiltDeg` of vertical at the first frame, the
/// arm's x along the forearm and the hand's x along the hand, each part at its joint.
void checkUprightAndAttached(const Take& take, double tiltDeg)
{
    REQUIRE(take.skeleton);
    const SkeletalMotion& motion = *take.skeleton;
    const Skeleton& skeleton = *motion.skeleton;
    PartJoints joints{};
    for (std::size_t p = 0; p < 4; ++p) joints[p] = skeleton.binding(kPuppetParts[p])->joint;
    const int hips = pelvisJoint(skeleton, joints[1]);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        INFO("frame " << f);
        const auto poses = motion.worldPoses(f);
        const double head = take.values(f, puppetChannel(0, Dof::Z));
        const double shoulder = take.values(f, puppetChannel(1, Dof::Z));
        CHECK(head > shoulder);
        CHECK(shoulder > poses[std::size_t(hips)].translation.z());
        for (int p = 0; p < 4; ++p)
            CHECK((partPose(take, f, p * kDofCount).translation - poses[std::size_t(joints[std::size_t(p)])].translation).norm() < 1e-6);
        auto landmarks = findLandmarks(motion, joints, f);
        REQUIRE(landmarks.ok());
        const Eigen::Vector3d armX = partPose(take, f, 2 * kDofCount).rotation * Eigen::Vector3d::UnitX();
        const Eigen::Vector3d handX = partPose(take, f, 3 * kDofCount).rotation * Eigen::Vector3d::UnitX();
        CHECK(degreesBetween(armX, landmarks->wrist - landmarks->elbow) < 1e-4);
        // An estimated finger tip continues the forearm, which bends against the hand: only
        // at the calibration frame is it the hand's direction.
        const bool tipEstimated = std::count(landmarks->estimated.begin(), landmarks->estimated.end(), "finger tip") > 0;
        if (f == 0 || !tipEstimated) CHECK(degreesBetween(handX, landmarks->fingerTip - landmarks->wrist) < 1e-4);
    }
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    CHECK(degreesBetween(partPose(take, 0, kDofCount).rotation * up, up) < tiltDeg);
    CHECK(degreesBetween(partPose(take, 0, 0).rotation * up, up) < tiltDeg);
    // y to the performer's left: the shoulder frame's y points from the right arm to the left.
    const Eigen::Quaterniond shoulder = partPose(take, 0, kDofCount).rotation;
    CHECK(degreesBetween(shoulder * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()) > 60.0);
}

} // namespace

TEST_CASE("joint names are read through prefixes, side marks and separators")
{
    struct Case {
        std::string name;
        std::optional<BodySide> side;
        std::string term;
    };
    const Case cases[] = {
        {"mixamorig:RightForeArm", BodySide::Right, "forearm"}, {"Bip01 R Forearm", BodySide::Right, "forearm"},
        {"Bip001_L_Hand", BodySide::Left, "hand"},             {"R_Forearm", BodySide::Right, "forearm"},
        {"forearm.R", BodySide::Right, "forearm"},             {"hand.l", BodySide::Left, "hand"},
        {"LowerArm_R", BodySide::Right, "lowerarm"},           {"rShldr", BodySide::Right, "shldr"},
        {"rradius", BodySide::Right, "radius"},                {"lhand", BodySide::Left, "hand"},
        {"relbow", BodySide::Right, "elbow"},                  {"LeftLowArm", BodySide::Left, "lowarm"},
        {"RightWrist", BodySide::Right, "wrist"},              {"Character1:Head", std::nullopt, "head"},
        {"lowerback", std::nullopt, "lowerback"},              {"root", std::nullopt, "root"},
        {"ring1", std::nullopt, "ring1"},                      {"Spine2", std::nullopt, "spine2"},
        {"HeadTop_End", std::nullopt, "headtopend"},           {"Hand_Left", BodySide::Left, "hand"},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        const auto info = jointNameInfo(c.name);
        CHECK(info.side == c.side);
        CHECK(info.term == c.term);
    }
}

TEST_CASE("every fixture family maps head, shoulder, arm and hand without a joint map")
{
    for (const BvhFamily& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        const BvhFile file = parsedFixture(family);
        auto map = mapPuppetParts(file, std::nullopt, {}, importOptions());
        INFO((map.ok() ? map->describe() : map.error().message));
        REQUIRE(map.ok());
        for (std::size_t p = 0; p < 4; ++p) CHECK(map->names.joints[p] == family.expected[p]);
        const MapMethod expected = family.id == "unnamed" ? MapMethod::Topology : MapMethod::Name;
        CHECK(map->methods[0] == expected);
        CHECK(map->methods[1] == MapMethod::Topology); // where the arm chains branch
        CHECK(map->methods[2] == expected);
        CHECK(map->methods[3] == expected);
        PartMapOptions left;
        left.side = BodySide::Left;
        auto leftMap = mapPuppetParts(file, std::nullopt, left, importOptions());
        REQUIRE(leftMap.ok());
        CHECK(leftMap->names.joints[2] == family.expectedLeft[0]);
        CHECK(leftMap->names.joints[3] == family.expectedLeft[1]);
        CHECK(leftMap->names.joints[1] == family.expected[1]);
    }
}

TEST_CASE("given joints win over the automatic map and one joint for two parts is refused")
{
    const auto families = bunraku::test::bvhFamilies();
    const BvhFile file = parsedFixture(families.front()); // bandai
    auto map = mapPuppetParts(file, parseJointMap("shoulder=Spine").value(), {}, importOptions());
    REQUIRE(map.ok());
    CHECK(map->names.joints[1] == "Spine");
    CHECK(map->methods[1] == MapMethod::Given);
    CHECK(map->names.joints[0] == "Head");
    CHECK(map->describe() == "head=Head (name), shoulder=Spine (given), arm=LowerArm_R (name), hand=Hand_R (name), right side");
    CHECK(map->text() == "head=Head,shoulder=Spine,arm=LowerArm_R,hand=Hand_R");
    auto twice = mapPuppetParts(file, parseJointMap("head=Chest").value(), {}, importOptions());
    REQUIRE_FALSE(twice.ok());
    CHECK_THAT(twice.error().message, Contains("bandai.bvh") && Contains("'Chest' is mapped to two parts (head and shoulder)"));
    auto missing = mapPuppetParts(file, parseJointMap("hand=Paw").value(), {}, importOptions());
    REQUIRE_FALSE(missing.ok());
    CHECK_THAT(missing.error().message, Contains("'Paw'") && Contains("Hips, Spine, Chest"));
}

TEST_CASE("a skeleton with nothing to go by says which part found no joint")
{
    auto file = parseBvh("HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\nJOINT b\n{\nOFFSET 0 1 0\n"
                         "CHANNELS 0\n}\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0\n",
                         "stick.bvh");
    REQUIRE(file.ok());
    auto map = mapPuppetParts(*file);
    REQUIRE_FALSE(map.ok());
    CHECK_THAT(map.error().message, Contains("stick.bvh") && Contains("no joint for the puppet part 'head'") && Contains("--joints") &&
                                        Contains("joints: a, b"));
}

TEST_CASE("every fixture family imports as an upright puppet attached to its bones")
{
    for (const BvhFamily& family : bunraku::test::bvhFamilies()) {
        for (const BodySide side : {BodySide::Right, BodySide::Left}) {
            INFO(family.id << ", " << bodySideName(side) << " side");
            const BvhFile file = parsedFixture(family, side == BodySide::Left);
            auto imported = importBvhPuppet(file, importOptions(side));
            INFO((imported.ok() ? std::string() : imported.error().message));
            REQUIRE(imported.ok());
            CHECK(imported->upAxis == (family.zUp ? BvhUpAxis::Z : BvhUpAxis::Y));
            CHECK(imported->cmPerUnit == (family.unitsPerCm == 1.0 ? 1.0 : 100.0));
            checkUprightAndAttached(imported->take, 5.0);
            // The canonical performer: head joint at 155 cm, chest at 130 cm when standing.
            CHECK(imported->take.values(0, puppetChannel(0, Dof::Z)) == Approx(155.0).margin(1e-6));
            // The waving hand rises: higher at the last frame than at the first.
            CHECK(imported->take.values(11, puppetChannel(3, Dof::Z)) > imported->take.values(0, puppetChannel(3, Dof::Z)) + 10.0);
        }
    }
}

TEST_CASE("the units of a skeleton are guessed from its height")
{
    for (const BvhFamily& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        const BvhFile file = parsedFixture(family);
        const BvhUnitsGuess guess = guessBvhUnits(file);
        CHECK(guess.unit == (family.unitsPerCm == 1.0 ? "cm" : "m"));
        // From the toes (1 cm) to the head top (172 cm), or to the head joint (155 cm) without it.
        const double cm = guess.height * (family.unitsPerCm == 1.0 ? 1.0 : 100.0);
        CHECK(cm > 150.0);
        CHECK(cm < 175.0);
    }
}

namespace {

/// The Mixamo-style fixture in `unitsPerCm`, 3 s at 30 Hz, its root walking `cmPerSecond` along
/// the file's forward axis (+Z, y up).
BvhFile walkingFixture(double unitsPerCm, double cmPerSecond)
{
    BvhFamily family = bunraku::test::bvhFamilies()[3];
    family.unitsPerCm = unitsPerCm;
    auto file = parseBvh(bunraku::test::fixtureBvh(family, 91), "walk.bvh");
    REQUIRE(file.ok());
    for (Eigen::Index f = 0; f < file->motion.values.rows(); ++f) file->motion.values(f, 2) += cmPerSecond * unitsPerCm * double(f) / 30.0;
    return std::move(file).value();
}

} // namespace

TEST_CASE("a skeleton 40 to 100 units tall is guessed in inches when it walks at a person's pace")
{
    // A 172 cm performer written in inches (68 units) walking 130 cm/s: inches.
    const BvhUnitsGuess walking = guessBvhUnits(walkingFixture(1.0 / 2.54, 130.0));
    INFO(walking.note);
    CHECK(walking.unit == "in");
    CHECK(walking.cmPerUnit == 2.54);
    CHECK(walking.height * walking.cmPerUnit == Approx(172.0).margin(8.0));
    // Standing in place, the same file says nothing more: centimetres, with the hint.
    const BvhUnitsGuess standing = guessBvhUnits(walkingFixture(1.0 / 2.54, 0.0));
    CHECK(standing.unit == "cm");
    CHECK(standing.note.find("or inches") != std::string::npos);
    // A 69 cm figure (a puppet, a child) in centimetres toddling 70 cm/s (the performer scaled
    // by 0.4, walking 175 cm/s before scaling): centimetres.
    const BvhUnitsGuess small = guessBvhUnits(walkingFixture(0.4, 175.0));
    INFO(small.note);
    CHECK(small.unit == "cm");
}

TEST_CASE("every bandai file maps by name and imports as an upright, attached puppet")
{
    for (const auto& path : bunraku::test::bandaiFilesOrSkip()) {
        INFO(path.filename().string());
        auto file = readBvh(path);
        REQUIRE(file.ok());
        auto imported = importBvhPuppet(*file, importOptions());
        REQUIRE(imported.ok());
        CHECK(imported->map->text() == "head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R");
        CHECK(imported->cmPerUnit == 1.0);
        checkUprightAndAttached(imported->take, 15.0);
        auto left = importBvhPuppet(*file, importOptions(BodySide::Left));
        REQUIRE(left.ok());
        CHECK(left->map->text() == "head=Head,shoulder=Chest,arm=LowerArm_L,hand=Hand_L");
        checkUprightAndAttached(left->take, 15.0);
    }
}
