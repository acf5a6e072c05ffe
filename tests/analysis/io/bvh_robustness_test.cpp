// The BVH reader on hostile shapes: very wide and very deep hierarchies parse (linearly: the
// figures are bench_io's), claims the file cannot back are refused before any allocation of
// their size, and devices or pipes are not read.
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/bvh_joint_map.h"
#include "tests/analysis/io/io_test_support.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;

namespace {

std::string siblings(int count, int frames = 1)
{
    std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 1 Xposition\n";
    for (int k = 0; k < count; ++k) text += "JOINT j" + std::to_string(k) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n}\n";
    text += "}\nMOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: 0.1\n";
    for (int f = 0; f < frames; ++f) text += "0\n";
    return text;
}

std::string chain(int depth)
{
    std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n";
    for (int k = 0; k < depth; ++k) text += "JOINT j" + std::to_string(k) + "\n{\nOFFSET 0 0 1\nCHANNELS 1 Zrotation\n";
    for (int k = 0; k < depth; ++k) text += "}\n";
    text += "}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0";
    for (int k = 0; k < depth; ++k) text += " 0";
    return text + "\n";
}

} // namespace

TEST_CASE("40,000 and 100,000 sibling joints parse, and the part map says what it could not find")
{
    for (const int count : {40000, 100000}) {
        INFO(count);
        auto file = parseBvh(siblings(count), "wide.bvh");
        REQUIRE(file.ok());
        CHECK(file->skeleton.joints.size() == std::size_t(count) + 1);
        CHECK(file->skeleton.joints.back().parent == 0);
        auto map = mapPuppetParts(*file);
        REQUIRE_FALSE(map.ok());
        CHECK_THAT(map.error().message, Contains("wide.bvh: no joint for the puppet part") && Contains(", ..."));
        CHECK(map.error().message.size() < 2000); // the joint list is cut, not 100,000 names long
    }
}

TEST_CASE("a 10,000-deep chain parses and poses without recursion")
{
    auto file = parseBvh(chain(10000), "deep.bvh");
    REQUIRE(file.ok());
    CHECK(file->skeleton.joints.size() == 10001);
    const auto poses = bvhWorldPoses(*file, 0);
    CHECK(poses.back().translation.z() == Approx(10000.0));
    auto motion = bvhToSkeletalMotion(*file);
    REQUIRE(motion.ok());
    CHECK((*motion)->frameCount() == 1);
}

TEST_CASE("a header claiming 10^12 frames is refused at its line without allocating them")
{
    auto file = parseBvh("HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n}\nMOTION\nFrames: 1000000000000\n"
                         "Frame Time: 0.1\n0 0 0\n",
                         "claims.bvh");
    REQUIRE_FALSE(file.ok());
    CHECK_THAT(file.error().message, Contains("claims.bvh:8:") && Contains("'Frames: 1000000000000'") && Contains("hold at most 2 rows of 3 values"));
}

TEST_CASE("many joints without channels cannot make the motion outgrow the file")
{
    auto file = parseBvh(siblings(200000, 2000), "hollow.bvh");
    REQUIRE(file.ok());
    auto motion = bvhToSkeletalMotion(*file);
    REQUIRE_FALSE(motion.ok());
    CHECK_THAT(motion.error().message, Contains("hollow.bvh: 200001 joints for 1 channels over 2000 frames") &&
                                           Contains("expected at most 8 times the channel data"));
}

TEST_CASE("devices, pipes and folders are not read as BVH files")
{
    auto device = readBvh("/dev/zero");
    REQUIRE_FALSE(device.ok());
    CHECK_THAT(device.error().message, Contains("/dev/zero: not a regular file"));
    const auto dir = bunraku::test::scratchDir("bvh_fifo");
    const auto fifo = dir / "pipe.bvh";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    auto pipe = readBvh(fifo); // would block forever if it were opened
    REQUIRE_FALSE(pipe.ok());
    CHECK_THAT(pipe.error().message, Contains("pipe.bvh: not a regular file"));
    auto folder = readBvh(dir);
    REQUIRE_FALSE(folder.ok());
    CHECK_THAT(folder.error().message, Contains("is a folder"));
    auto start = readBvhStart("/dev/zero");
    REQUIRE_FALSE(start.ok());
}

TEST_CASE("the start of a file is read without its remaining rows")
{
    std::string text = chain(3);
    text.replace(text.find("Frames: 1"), 9, "Frames: 3");
    text += "1 2 3 4 5 6\nnot even numbers\n";
    CHECK_FALSE(parseBvh(text, "start.bvh").ok());
    const auto dir = bunraku::test::scratchDir("bvh_start");
    const auto path = bunraku::test::writeText(dir / "start.bvh", text);
    auto start = readBvhStart(path, 2);
    REQUIRE(start.ok());
    CHECK(start->motion.values.rows() == 2);
    CHECK(start->motion.values(1, 5) == 6.0);
}
