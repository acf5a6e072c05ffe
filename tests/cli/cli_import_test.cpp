// `bunraku info` and `bunraku axis` on real and fixture BVH files: any valid BVH is described
// without a joint map, the part map is printed, and the motion axis of the first frame stands
// within 15 degrees of vertical.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <map>
#include <string>

using bunraku::test::runBunraku;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

std::filesystem::path writeFixture(const std::filesystem::path& dir, const bunraku::test::BvhFamily& family)
{
    return bunraku::test::writeText(dir / (family.id + ".bvh"), bunraku::test::fixtureBvh(family));
}

/// Degrees between the first frame's motion axis z and the vertical, from `axis --coordinates`.
double firstAxisTilt(const std::filesystem::path& take, const std::filesystem::path& output)
{
    const auto run = runBunraku({"axis", take.string(), "--coordinates", "-o", output.string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const auto csv = bunraku::test::readNumericCsv(output);
    REQUIRE(csv.header.size() == 7); // time_s, centre x y z, rotation vector x y z (deg)
    REQUIRE(!csv.rows.empty());
    const Eigen::Vector3d rotationVector(csv.rows[0][4], csv.rows[0][5], csv.rows[0][6]);
    const double angle = rotationVector.norm() * M_PI / 180.0;
    const Eigen::Matrix3d world_R_axis =
        angle > 0.0 ? Eigen::AngleAxisd(angle, rotationVector.normalized()).toRotationMatrix() : Eigen::Matrix3d::Identity();
    return std::acos(std::clamp(world_R_axis.col(2).dot(Eigen::Vector3d::UnitZ()), -1.0, 1.0)) * 180.0 / M_PI;
}

} // namespace

TEST_CASE("info describes every fixture family without a joint map and prints the part map")
{
    const auto dir = bunraku::test::scratchDir("cli_info_families");
    for (const auto& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        const auto file = writeFixture(dir, family);
        const auto run = runBunraku({"info", file.string(), "--json"});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        const json info = json::parse(run.out);
        CHECK(info["format"] == "bvh");
        CHECK(info["bvh_frames"] == 12);
        CHECK(info["rate_hz"] == 30.0);
        CHECK(info["up_axis"] == (family.zUp ? "z" : "y"));
        CHECK(info["units"]["guess"] == (family.unitsPerCm == 1.0 ? "cm" : "m"));
        CHECK(info["joints"][1]["rotation_order"].get<std::string>().size() == 3);
        for (std::size_t p = 0; p < 4; ++p) {
            static const char* parts[] = {"head", "shoulder", "arm", "hand"};
            CHECK(info["part_map"][parts[p]]["joint"] == family.expected[p]);
        }
        CHECK(info["channels"] == 24);
        // The text form prints the hierarchy with each joint's channels, and the map.
        const auto text = runBunraku({"info", file.string()});
        REQUIRE(text.exitCode == 0);
        CHECK_THAT(text.out, Contains("part map: head=" + family.expected[0]) && Contains("hierarchy (joint [channels])") &&
                                 Contains("up axis: " + std::string(family.zUp ? "z" : "y")));
    }
}

TEST_CASE("info --side left maps the left arm and hand")
{
    const auto dir = bunraku::test::scratchDir("cli_info_left");
    const auto families = bunraku::test::bvhFamilies();
    const auto file = writeFixture(dir, families[3]); // mixamo
    const auto run = runBunraku({"info", file.string(), "--side", "left", "--json"});
    REQUIRE(run.exitCode == 0);
    const json info = json::parse(run.out);
    CHECK(info["part_map"]["arm"]["joint"] == families[3].expectedLeft[0]);
    CHECK(info["part_map"]["hand"]["joint"] == families[3].expectedLeft[1]);
    CHECK(info["part_map"]["side"] == "left");
}

TEST_CASE("info describes a valid BVH whose parts cannot be mapped, and says why")
{
    const auto dir = bunraku::test::scratchDir("cli_info_unmapped");
    const auto file = bunraku::test::writeText(dir / "stick.bvh", "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n"
                                                                   "JOINT b\n{\nOFFSET 0 1 0\nCHANNELS 1 Zrotation\n}\n}\n"
                                                                   "MOTION\nFrames: 2\nFrame Time: 0.01\n0 0 0 5\n0 0 1 6\n");
    const auto run = runBunraku({"info", file.string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK_THAT(run.out, Contains("2 joints + 0 End Sites, 4 channels, 2 frames") && Contains("100 Hz") &&
                            Contains("part map: none") && Contains("no joint for the puppet part 'head'") && Contains("b  [Zrotation]"));
    const auto asJson = runBunraku({"info", file.string(), "--json"});
    REQUIRE(asJson.exitCode == 0);
    const json info = json::parse(asJson.out);
    CHECK(info["takes"] == 0);
    CHECK(info["joint_count"] == 2);
    CHECK_THAT(info["part_map_error"].get<std::string>(), Contains("stick.bvh"));
    // convert needs the puppet parts: a one-line error.
    const auto convert = runBunraku({"convert", file.string(), "-o", (dir / "stick.csv").string()});
    CHECK(bunraku::test::isOneLineError(convert.exitCode, convert.err));
    CHECK_THAT(convert.err, Contains("stick.bvh") && Contains("--joints"));
}

TEST_CASE("the motion axis of the first frame stands within 15 degrees of vertical for every fixture family")
{
    const auto dir = bunraku::test::scratchDir("cli_axis_families");
    for (const auto& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        CHECK(firstAxisTilt(writeFixture(dir, family), dir / (family.id + "_axis.csv")) < 15.0);
    }
}

TEST_CASE("the motion axis of the first frame stands within 15 degrees of vertical for every bandai file")
{
    const auto dir = bunraku::test::scratchDir("cli_axis_bandai");
    for (const auto& path : bunraku::test::bandaiFilesOrSkip()) {
        INFO(path.filename().string());
        CHECK(firstAxisTilt(path, dir / (path.stem().string() + "_axis.csv")) < 15.0);
    }
}

TEST_CASE("bad BVH files get one-line errors naming the file and the line")
{
    const auto dir = bunraku::test::scratchDir("cli_bad_bvh");
    const std::string head = "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 1 Xposition\n}\nMOTION\n";
    struct Case {
        std::string name, text, where, what;
    };
    const Case cases[] = {
        {"claims.bvh", head + "Frames: 1000000000000\nFrame Time: 0.1\n1\n", "claims.bvh:8:", "hold at most"},
        {"slow.bvh", head + "Frames: 1\nFrame Time: 1e308\n1\n", "slow.bvh:9:", "at most 3600 s per frame"},
        {"nan.bvh", head + "Frames: 2\nFrame Time: 0.1\n1\nnan\n", "nan.bvh:11:", "non-finite"},
        {"short.bvh", "HIERARCHY\nROOT a\n{\nOFFSET 0 0\n", "short.bvh:4:", "OFFSET expects 3 numbers"},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        const auto file = bunraku::test::writeText(dir / c.name, c.text);
        const auto run = runBunraku({"info", file.string()});
        CHECK(bunraku::test::isOneLineError(run.exitCode, run.err));
        CHECK_THAT(run.err, Contains(c.where) && Contains(c.what));
    }
}

TEST_CASE("corpus makes a corpus folder from files, reporting each file's map and any resampling")
{
    const auto dir = bunraku::test::scratchDir("cli_corpus");
    const auto families = bunraku::test::bvhFamilies();
    std::filesystem::create_directories(dir / "in");
    for (const std::string name : {"dataset-2_wave_happy_001", "dataset-2_wave_happy_002", "dataset-2_wave_calm_001"})
        bunraku::test::writeText(dir / "in" / (name + ".bvh"), bunraku::test::fixtureBvh(families[4])); // classic naming
    std::string fast = bunraku::test::fixtureBvh(families[4]);
    fast.replace(fast.find("Frame Time: 0.0333333"), 21, "Frame Time: 0.0166667");
    bunraku::test::writeText(dir / "in" / "dataset-2_wave_calm_002.bvh", fast);

    // The default pattern reads "dataset-2" as the function: a pattern says what the names mean.
    const auto run = runBunraku({"corpus", (dir / "in").string(), "-o", (dir / "out").string(), "--pattern",
                                 "{any}_{function}_{emotion}_{take}", "--neutral", "calm", "--json"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const json report = json::parse(run.out);
    CHECK(report["rate_hz"] == 30.0);
    CHECK(report["neutral_emotion"] == "calm");
    CHECK(report["functions"] == json::array({"wave"}));
    REQUIRE(report["takes"].size() == 4);
    for (const auto& take : report["takes"]) CHECK_THAT(take["part_map"].get<std::string>(), Contains("arm=RightElbow (name)"));
    CHECK(report["takes"][1]["rate_hz"] == 60.0);
    CHECK(report["takes"][1]["resampled"] == true);
    CHECK_THAT(report["notes"][0].get<std::string>(), Contains("resampled to it: dataset-2_wave_calm_002.bvh (60 Hz)"));

    const auto info = runBunraku({"info", (dir / "out").string()});
    REQUIRE(info.exitCode == 0);
    CHECK_THAT(info.out, Contains("wave/calm/2") && Contains("(with its skeleton)"));

    const auto text = runBunraku({"corpus", (dir / "in").string(), "-o", (dir / "out2").string(), "--pattern", "{any}_{function}_{emotion}_{take}"});
    REQUIRE(text.exitCode == 0);
    CHECK_THAT(text.out, Contains("note: corpus rate 30 Hz (the rate most files have); resampled to it") &&
                             Contains("note: neutral emotion 'calm' (the first; give --neutral to choose)"));

    const auto bad = runBunraku({"corpus", (dir / "in").string(), "-o", (dir / "out3").string(), "--pattern", "{function}.{emotion}"});
    CHECK(bunraku::test::isOneLineError(bad.exitCode, bad.err));
    CHECK_THAT(bad.err, Contains("dataset-2_wave_calm_001.bvh: the file name does not match the pattern '{function}.{emotion}'"));
}

TEST_CASE("corpus of the bandai files: every take mapped, the neutral emotion found")
{
    const auto files = bunraku::test::bandaiFilesOrSkip();
    if (files.empty()) return;
    const auto dir = bunraku::test::scratchDir("cli_corpus_bandai");
    const auto run = runBunraku({"corpus", bunraku::test::bandaiDir().string(), "-o", (dir / "bandai").string(), "--json"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const json report = json::parse(run.out);
    CHECK(report["takes"].size() == files.size());
    CHECK(report["neutral_emotion"] == "normal");
    CHECK(report["emotions"].size() == 5);
    for (const auto& take : report["takes"]) CHECK_THAT(take["part_map"].get<std::string>(), Contains("hand=Hand_R (name)"));
}

TEST_CASE("axis --json says where the masses come from: the modelled puppet fitted to the skeleton or the primitives")
{
    const auto dir = bunraku::test::scratchDir("cli_axis_masses");
    const auto family = bunraku::test::bvhFamilies().front();
    const auto file = writeFixture(dir, family);
    std::map<std::string, json> answers;
    for (const std::string masses : {"model", "primitives"}) {
        const auto run = runBunraku({"axis", file.string(), "--masses", masses, "--json", "-o", (dir / (masses + ".csv")).string()});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        answers[masses] = json::parse(run.out);
        CHECK(answers[masses]["mass_source"] == masses);
        double sum = 0.0;
        for (const auto& [part, grams] : answers[masses]["part_masses_g"].items()) sum += grams.get<double>();
        CHECK(sum == Approx(answers[masses]["mass_g"].get<double>()));
        // The mirrored left arm weighs what the right one does.
        CHECK(answers[masses]["part_masses_g"]["left_arm"].get<double>() ==
              Approx(answers[masses]["part_masses_g"]["right_arm"].get<double>()).epsilon(1e-9));
    }
    // The model's solid is lighter than the overlapping primitives (its skirt and sleeves thinner).
    CHECK(answers["model"]["mass_g"].get<double>() < 0.8 * answers["primitives"]["mass_g"].get<double>());
    // Both stand the first frame's axis up.
    CHECK(firstAxisTilt(file, dir / "tilt.csv") < 15.0);
    const auto bad = runBunraku({"axis", file.string(), "--masses", "clay", "-o", (dir / "clay.csv").string()});
    CHECK(bad.exitCode != 0);
    CHECK_THAT(bad.err, Contains("--masses"));
}
