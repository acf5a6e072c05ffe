// Every command that writes one take writes it by the output's extension: .bvh, .glb or .csv,
// the same writer as File > Export Take (render/take_export.h).
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/bandai_files.h"
#include "tests/support/test_paths.h"

#include "analysis/io/bvh.h"
#include "analysis/io/take_csv.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>

using bunraku::test::runBunraku;

namespace {

std::string readBytes(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TEST_CASE("emotion, normalise and design write their take as BVH, glTF or CSV by the output's extension", "[cli][export]")
{
    const auto dir = bunraku::test::scratchDir("cli-export");
    const auto demo = dir / "demo";
    REQUIRE(runBunraku({"demo", "-o", demo.string(), "--seed", "5"}).exitCode == 0);
    for (const std::string extension : {"csv", "bvh", "glb"}) {
        INFO(extension);
        const auto weighted = dir / ("weighted." + extension);
        auto run = runBunraku({"emotion", demo.string(), "--pad", "--function", "greeting", "--emotion", "hostile", "--weight", "1.5", "-o",
                               weighted.string()});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        const auto reference = dir / ("average." + extension);
        run = runBunraku({"normalise", demo.string(), "--function", "greeting", "--emotion", "hostile", "--reference", "average", "-o",
                          reference.string()});
        REQUIRE(run.exitCode == 0);
        CHECK(std::filesystem::is_regular_file(reference)); // one file, not a folder
    }
    // The three formats hold the same take: CSV's frames are BVH's frames are glTF's keyframes.
    auto csv = bunraku::analysis::io::readTakeCsv(dir / "weighted.csv");
    REQUIRE(csv.ok());
    auto bvh = bunraku::analysis::io::readBvh(dir / "weighted.bvh");
    REQUIRE(bvh.ok());
    CHECK(bvh->motion.values.rows() == csv->frameCount());
    // A demo take has no skeleton of its own: the weighted take moves the puppet's rig fitted to
    // the corpus (analysis/skeleton/puppet_rig_fit.h), and its BVH is that rig: torso, neck,
    // shoulder_joint, arm_sensor, wrist.
    CHECK(bvh->skeleton.jointCount() == 5);
    CHECK(bvh->skeleton.joints.front().name == "torso");
    const std::string glb = readBytes(dir / "weighted.glb");
    REQUIRE(glb.substr(0, 4) == "glTF");
    CHECK(glb.find("\"right_hand\"") != std::string::npos); // the puppet's parts are its joints
    CHECK(glb.find("\"count\":" + std::to_string(csv->frameCount())) != std::string::npos);
    auto average = bunraku::analysis::io::readBvh(dir / "average.bvh");
    REQUIRE(average.ok());
    CHECK(average->motion.values.rows() > 0);

    // design writes the designed take the same way, and refuses other names before any work.
    const auto take = dir / "weighted.csv";
    REQUIRE(runBunraku({"design", take.string(), "-o", (dir / "designed.glb").string()}).exitCode == 0);
    CHECK(readBytes(dir / "designed.glb").substr(0, 4) == "glTF");
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"design", take.string(), "-o", (dir / "designed.fbx").string()},
          std::vector<std::string>{"emotion", demo.string(), "--pad", "--function", "greeting", "--emotion", "hostile", "--weight", "1",
                                   "-o", (dir / "weighted.txt").string()},
          std::vector<std::string>{"convert", take.string(), "-o", (dir / "converted.obj").string()}}) {
        const auto run = runBunraku(command);
        INFO(command.front() << ": " << run.err);
        CHECK(run.exitCode != 0);
        CHECK(run.err.find("expected a .bvh, .glb or .csv file name") != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(dir / "designed.fbx"));
    CHECK_FALSE(std::filesystem::exists(dir / "weighted.txt"));
    CHECK_FALSE(std::filesystem::exists(dir / "converted.obj"));
}

TEST_CASE("a derived take is written as one body whatever the format, and says how far the per-channel result is", "[cli][export][gap]")
{
    if (bunraku::test::bandaiFilesOrSkip().empty()) return;
    const auto dir = bunraku::test::scratchDir("cli-export-gap");
    auto run = runBunraku({"corpus", bunraku::test::bandaiDir().string(), "-o", (dir / "bandai").string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    // The 3.7 average of the normal waves: positions averaged in the thesis's channels, joint
    // rotations in the skeleton; every file holds the skeleton's motion.
    for (const std::string extension : {"bvh", "glb", "csv"}) {
        INFO(extension);
        const auto average = dir / ("average." + extension);
        run = runBunraku({"normalise", (dir / "bandai").string(), "--function", "wave-right-hand", "--emotion", "normal", "--reference",
                          "average", "-o", average.string(), "--json"});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        CHECK_NOTHROW(nlohmann::json::parse(run.out)); // the note is on stderr
        CHECK(run.err.find("note: average." + extension + " holds the take as one body moves") != std::string::npos);
        CHECK(run.err.find("per-channel result differs from it by up to ") != std::string::npos);
    }
    // An untouched take's channels are its skeleton's parts: nothing to say.
    const auto take = bunraku::test::bandaiDir() / "wave-right-hand_normal_001.bvh";
    run = runBunraku({"convert", take.string(), "-o", (dir / "converted.bvh").string()});
    REQUIRE(run.exitCode == 0);
    CHECK(run.err.find("note:") == std::string::npos);
}
