#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "tests/analysis/io/io_test_support.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;

namespace {

bool near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance = 1e-9) { return (a - b).norm() <= tolerance; }

/// A 3-joint chain whose root carries rotation channels in the order given.
std::string orderChain(const std::string& order, const std::string& values)
{
    return "HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 2 " + order + "\n JOINT B\n {\n  OFFSET 1 0 0\n  CHANNELS 0\n  End Site\n  {\n   OFFSET 0 0 0\n  }\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n" +
           values + "\n";
}

} // namespace

TEST_CASE("bvh parser reads the hand-written two-joint chain")
{
    auto file = readBvh(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    REQUIRE(file.ok());
    const auto& skeleton = file->skeleton;
    REQUIRE(skeleton.joints.size() == 3);
    CHECK(skeleton.jointCount() == 2);
    CHECK(skeleton.endSiteCount() == 1);
    CHECK(skeleton.channelCount == 9);
    CHECK(skeleton.joints[1].name == "Elbow");
    CHECK(skeleton.joints[1].parent == 0);
    CHECK(skeleton.joints[1].firstChannel == 6);
    CHECK(skeleton.joints[2].endSite);
    CHECK(skeleton.joints[2].parent == 1);
    CHECK(skeleton.joints[1].channels == std::vector<BvhChannel>{BvhChannel::Zrotation, BvhChannel::Yrotation, BvhChannel::Xrotation});
    CHECK(file->motion.frameTime == 0.2);
    CHECK(file->motion.values(1, 0) == 10.0);
}

TEST_CASE("forward kinematics of a two-joint chain matches the hand computation")
{
    auto file = readBvh(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    REQUIRE(file.ok());
    // frame 0: rest pose along x
    auto rest = bvhWorldPoses(*file, 0);
    CHECK(near(rest[1].translation, {10, 0, 0}));
    CHECK(near(rest[2].translation, {15, 0, 0}));
    // frame 1: root at (10,0,0) turned 90 deg about z; elbow turned another 90 deg about z.
    // elbow = (10,0,0) + Rz(90)(10,0,0) = (10,10,0); end = elbow + Rz(180)(5,0,0) = (5,10,0)
    auto moved = bvhWorldPoses(*file, 1);
    CHECK(near(moved[0].translation, {10, 0, 0}));
    CHECK(near(moved[1].translation, {10, 10, 0}));
    CHECK(near(moved[2].translation, {5, 10, 0}));
    CHECK(near(moved[1].rotation * Eigen::Vector3d::UnitX(), {-1, 0, 0}));
}

TEST_CASE("rotation channels apply in the order listed, intrinsically")
{
    // R = Rx(90) Ry(90): the child offset (1,0,0) -> Ry -> (0,0,-1) -> Rx -> (0,1,0)
    auto xy = parseBvh(orderChain("Xrotation Yrotation", "90 90"), "xy.bvh");
    REQUIRE(xy.ok());
    CHECK(near(bvhWorldPoses(*xy, 0)[1].translation, {0, 1, 0}));
    // R = Ry(90) Rx(90): (1,0,0) -> Rx -> (1,0,0) -> Ry -> (0,0,-1)
    auto yx = parseBvh(orderChain("Yrotation Xrotation", "90 90"), "yx.bvh");
    REQUIRE(yx.ok());
    CHECK(near(bvhWorldPoses(*yx, 0)[1].translation, {0, 0, -1}));
}

TEST_CASE("a three-joint chain at depth with mixed channel counts")
{
    const std::string text = "HIERARCHY\r\nROOT Hips\r\n{\r\n\tOFFSET 1 2 3\r\n\tCHANNELS 3 Xposition Yposition Zposition\r\n"
                             "\tJOINT Spine\r\n\t{\r\n\t\tOFFSET 0 10 0\t \r\n\t\tCHANNELS 3 Xrotation Yrotation Zrotation\r\n"
                             "\t\tJOINT Neck\r\n\t\t{\r\n\t\t\tOFFSET 0 0 4\r\n\t\t\tCHANNELS 3 Yrotation Xrotation Zrotation\r\n"
                             "\t\t\tEnd Site\r\n\t\t\t{\r\n\t\t\t\tOFFSET 2.0E0 0 0\r\n\t\t\t}\r\n\t\t}\r\n\t}\r\n}\r\n"
                             "MOTION\r\nFrames:\t1\r\nFrame Time:\t3.3333e-02\r\n5 0 0   90 0 0   0 -90 0  \r\n";
    auto file = parseBvh(text, "depth.bvh");
    REQUIRE(file.ok());
    auto poses = bvhWorldPoses(*file, 0);
    // Hips: position channels replace the offset -> (5,0,0)
    CHECK(near(poses[0].translation, {5, 0, 0}));
    // Spine: (5,0,0) + (0,10,0); rotation Rx(90)
    CHECK(near(poses[1].translation, {5, 10, 0}));
    // Neck: Spine + Rx(90)(0,0,4) = (5,10,0) + (0,-4,0)
    CHECK(near(poses[2].translation, {5, 6, 0}));
    // End: Neck + Rx(90) Rx(-90) (2,0,0) = (7,6,0)
    CHECK(near(poses[3].translation, {7, 6, 0}));
    // with AddToOffset the root translation is offset + channels
    BvhKinematicsOptions add;
    add.positionMode = BvhPositionMode::AddToOffset;
    CHECK(near(bvhWorldPoses(*file, 0, add)[0].translation, {6, 2, 3}));
}

TEST_CASE("bvh round-trips through its own text")
{
    auto file = readBvh(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    REQUIRE(file.ok());
    auto again = parseBvh(formatBvh(*file), "again.bvh");
    REQUIRE(again.ok());
    CHECK(again->skeleton.joints.size() == file->skeleton.joints.size());
    CHECK(again->motion.values == file->motion.values);
    for (std::size_t j = 0; j < file->skeleton.joints.size(); ++j) {
        CHECK(again->skeleton.joints[j].name == file->skeleton.joints[j].name);
        CHECK(again->skeleton.joints[j].parent == file->skeleton.joints[j].parent);
        CHECK(again->skeleton.joints[j].channels == file->skeleton.joints[j].channels);
    }
}

TEST_CASE("malformed bvh files give errors naming the file and line")
{
    const std::string good = orderChain("Xrotation Yrotation", "1 2");
    struct Case {
        std::string text;
        std::string where;
        std::string what;
    };
    const auto replace = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    const Case cases[] = {
        {"", "bad.bvh", "HIERARCHY"},
        {replace("HIERARCHY", "HIERARCH"), "bad.bvh:1", "HIERARCHY"},
        {replace("CHANNELS 2 Xrotation", "CHANNELS 2 Wrotation"), "bad.bvh:5", "Wrotation"},
        {replace("CHANNELS 2", "CHANNELS 3"), "bad.bvh:5", "lists 2"},
        {replace("OFFSET 1 0 0", "OFFSET 1 0"), "bad.bvh:8", "OFFSET expects 3"},
        {replace("OFFSET 1 0 0", "OFFSET 1 nan 0"), "bad.bvh:8", "non-finite"},
        {replace(" }\n}\nMOTION", " }\nMOTION"), "bad.bvh:15", "braces"},
        {replace("Frames: 1", "Frames: x"), "bad.bvh:17", "Frames"},
        {replace("Frames: 1", "Frames: 2"), "bad.bvh:19", "expected 2 motion rows (Frames), found 1"},
        {replace("Frames: 1", "Frames: 3"), "bad.bvh:17", "hold at most 2 rows of 2 values"},
        {replace("Frames: 1", "Frames: 99999999999999"), "bad.bvh:17", "hold at most 2 rows"},
        {replace("Frames: 1", "Frames: 2") + "\n\n\n\n\n", "bad.bvh:24", "expected 2 motion rows"},
        {replace("Frame Time: 0.1", "Frame Time: 1e308"), "bad.bvh:18", "expected at most 3600 s per frame"},
        {replace("Frame Time: 0.1", "Frame Time: 0"), "bad.bvh:18", "Frame Time"},
        {replace("Frame Time: 0.1", "Frame Time: 1e-300"), "bad.bvh:18", "(0, 1000000] Hz"},
        {replace("\n1 2\n", "\n1\n"), "bad.bvh:19", "expected 2 channel values"},
        {replace("\n1 2\n", "\n1 inf\n"), "bad.bvh:19", "non-finite"},
        {replace("\n1 2\n", "\n1 2x\n"), "bad.bvh:19", "expected a number"},
        {replace("\n1 2\n", "\n1 2\n3 4\n"), "bad.bvh:20", "more motion rows"},
        {replace("MOTION\n", ""), "bad.bvh", "Frames"},
        {replace("JOINT B", "JOINT A"), "bad.bvh:6", "named twice"},
    };
    for (const auto& c : cases) {
        auto file = parseBvh(c.text, "bad.bvh");
        INFO(c.text);
        REQUIRE_FALSE(file.ok());
        CHECK(file.error().code == ErrorCode::Parse);
        CHECK_THAT(file.error().message, Contains(c.where) && Contains(c.what));
    }
}

TEST_CASE("bvh parser never crashes on truncated files")
{
    auto full = readBvh(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    REQUIRE(full.ok());
    const std::string text = formatBvh(*full);
    for (std::size_t cut = 0; cut < text.size(); cut += 7) {
        auto file = parseBvh(text.substr(0, cut), "cut.bvh");
        if (!file.ok()) CHECK_THAT(file.error().message, Contains("cut.bvh"));
    }
}

TEST_CASE("joint maps parse from the command-line form and from JSON")
{
    auto map = parseJointMap("head=Kopf, arm = ForeArm_R");
    REQUIRE(map.ok());
    CHECK(map->joints[0] == "Kopf");
    CHECK(map->joints[1].empty());
    CHECK(map->joints[2] == "ForeArm_R");
    CHECK_THAT(parseJointMap("knee=Knee").error().message, Contains("knee=Knee") && Contains("unknown part"));
    CHECK_THAT(parseJointMap("head").error().message, Contains("part=Joint"));

    const auto dir = bunraku::test::scratchDir("joint_map_json");
    bunraku::test::writeText(dir / "map.json", R"({"head": "H", "shoulder": "S", "arm": "A", "hand": "W"})");
    auto json = readJointMapJson(dir / "map.json");
    REQUIRE(json.ok());
    CHECK(json->joints == std::array<std::string, 4>{"H", "S", "A", "W"});
    bunraku::test::writeText(dir / "bad.json", "{\n\"head\": 3\n}");
    CHECK_THAT(readJointMapJson(dir / "bad.json").error().message, Contains("bad.json") && Contains("head"));
    bunraku::test::writeText(dir / "broken.json", "{\n\"head\": \n");
    CHECK_THAT(readJointMapJson(dir / "broken.json").error().message, Contains("broken.json:"));
}

TEST_CASE("the Y-up axis change sends file forward to x and file up to z")
{
    const Eigen::Quaterniond world_R_file = bvhAxisChange(BvhUpAxis::Y);
    CHECK(near(world_R_file * Eigen::Vector3d(0, 0, 1), {1, 0, 0}));
    CHECK(near(world_R_file * Eigen::Vector3d(1, 0, 0), {0, 1, 0}));
    CHECK(near(world_R_file * Eigen::Vector3d(0, 1, 0), {0, 0, 1}));
    CHECK(near(world_R_file * Eigen::Vector3d(1, 2, 3), {3, 1, 2}));
    CHECK(bvhAxisChange(BvhUpAxis::Z).isApprox(Eigen::Quaterniond::Identity()));
}

TEST_CASE("an unknown joint in the map is a clear error listing the joints")
{
    auto file = readBvh(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    REQUIRE(file.ok());
    BvhImportOptions options;
    CHECK_THAT(bvhToPuppetTake(*file, options).error().message, Contains("two_joint_chain.bvh") && Contains("--joints"));
    options.jointMap = JointMap{{"Base", "Base", "Elbow", "Wrist"}};
    CHECK_THAT(bvhToPuppetTake(*file, options).error().message, Contains("'Wrist'") && Contains("Base, Elbow"));
    // One joint for two parts would collapse the puppet: refused, naming the joint and the parts.
    options.jointMap = JointMap{{"Base", "Base", "Elbow", "Elbow"}};
    CHECK_THAT(bvhToPuppetTake(*file, options).error().message,
               Contains("two_joint_chain.bvh") && Contains("'Base' is mapped to two parts (head and shoulder)"));
}
