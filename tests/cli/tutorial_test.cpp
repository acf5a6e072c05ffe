// docs/TUTORIAL.md, run as written: its ```sh tutorial commands in order on the Bandai waves
// (../shared/data/bandai, read in place), in a scratch folder, then every output checked
// against what the page says of it. A missing Bandai file fails under CI=true and is reported
// as skipped otherwise.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/cli/tutorial_script.h"
#include "tests/support/peer.h"
#include "tests/support/test_paths.h"

#include "analysis/core/corpus.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/bvh.h"
#include "analysis/io/corpus_io.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

using namespace bunraku;
using bunraku::test::readTextFile;

namespace {

namespace fs = std::filesystem;

/// Width and height of a PNG file (0, 0 when it is not one).
std::pair<int, int> pngSize(const fs::path& file)
{
    const std::string bytes = readTextFile(file);
    if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || bytes.compare(12, 4, "IHDR") != 0) return {0, 0};
    auto big = [&](std::size_t at) {
        return int((std::uint32_t(std::uint8_t(bytes[at])) << 24) | (std::uint32_t(std::uint8_t(bytes[at + 1])) << 16)
                   | (std::uint32_t(std::uint8_t(bytes[at + 2])) << 8) | std::uint32_t(std::uint8_t(bytes[at + 3])));
    };
    return {big(16), big(20)};
}

/// A BVH written by a tutorial step: its joints (not End Sites) and frames.
void checkBvh(const fs::path& file, int joints, Eigen::Index frames)
{
    INFO(file.string());
    auto bvh = analysis::io::readBvh(file);
    REQUIRE(bvh);
    CHECK(bvh->skeleton.jointCount() == joints);
    CHECK(bvh->motion.values.rows() == frames);
    CHECK(bvh->motion.frameTime == Approx(1.0 / 30.0).epsilon(1e-5));
}

/// A .glb written by a tutorial step: the header, the JSON chunk, one skin of `joints` joints and
/// one animation whose time accessor has `frames` keys.
void checkGlb(const fs::path& file, int joints, int frames)
{
    INFO(file.string());
    const std::string bytes = readTextFile(file);
    REQUIRE(bytes.size() > 20);
    auto little = [&](std::size_t at) {
        std::uint32_t value = 0;
        std::memcpy(&value, bytes.data() + at, 4);
        return value;
    };
    REQUIRE(bytes.compare(0, 4, "glTF") == 0);
    CHECK(little(4) == 2);
    CHECK(little(8) == bytes.size());
    const std::uint32_t jsonLength = little(12);
    REQUIRE(bytes.compare(16, 4, "JSON") == 0);
    REQUIRE(20 + std::size_t(jsonLength) <= bytes.size());
    const auto gltf = nlohmann::json::parse(bytes.substr(20, jsonLength));
    REQUIRE(gltf["skins"].size() == 1);
    CHECK(gltf["skins"][0]["joints"].size() == std::size_t(joints));
    REQUIRE(gltf["animations"].size() == 1);
    const auto& sampler = gltf["animations"][0]["samplers"][0];
    CHECK(gltf["accessors"][sampler["input"].get<int>()]["count"] == frames);
}

/// Position (cm^2) and rotation (deg^2) sums of a variance.csv row (take, stage, total, 24 channels).
struct FamilySums {
    double position = 0.0, rotation = 0.0;
};

std::map<std::pair<int, std::string>, FamilySums> varianceFamilies(const fs::path& file)
{
    std::map<std::pair<int, std::string>, FamilySums> sums;
    std::istringstream in(readTextFile(file));
    std::string line;
    std::vector<std::string> header;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::istringstream row(line);
        for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
        if (header.empty()) {
            header = fields;
            continue;
        }
        REQUIRE(fields.size() == header.size());
        FamilySums& sum = sums[{std::stoi(fields[0]), fields[1]}];
        for (std::size_t c = 3; c < fields.size(); ++c) {
            const char axis = header[c].back();
            const bool position = header[c].size() > 2 && header[c][header[c].size() - 2] == '.' && (axis == 'x' || axis == 'y' || axis == 'z');
            (position ? sum.position : sum.rotation) += std::stod(fields[c]);
        }
    }
    return sums;
}

} // namespace

TEST_CASE("the tutorial's commands run in order on the Bandai waves and write what the tutorial says", "[cli][tutorial][bandai]")
{
    const fs::path bandai = test::bandaiDir();
    if (!test::requirePeer(fs::exists(bandai / "wave-right-hand_normal_001.bvh") && fs::exists(bandai / "wave-right-hand_exhausted_005.bvh"),
                           "the Bandai Namco waves in " + bandai.string(), "see ../shared/data/bandai/README.md"))
        return;

    const auto steps = test::parseTutorial(readTextFile(test::sourceDir() / "docs" / "TUTORIAL.md"));
    // The checks below follow these steps: a step added, removed or moved in the page must be
    // reflected here.
    std::vector<std::string> subcommands;
    for (const auto& step : steps) subcommands.push_back(step.fileName.empty() ? step.words[1] : "(file " + step.fileName + ")");
    REQUIRE(subcommands == std::vector<std::string>{"info", "corpus", "render", "normalise", "(file optimal.json)", "analyse", "emotion",
                                                     "normalise", "normalise", "phase", "gains", "design", "design", "design", "render",
                                                     "convert", "info"});

    const fs::path dir = test::scratchDir("tutorial");
    // One run of the commands, then every output checked in blocks of its own (not SECTIONs:
    // each SECTION would run the whole tutorial again).
    std::vector<test::CliRun> runs;
    for (const auto& step : steps) {
        if (!step.fileName.empty()) {
            test::writeText(dir / step.fileName, step.fileText);
            runs.push_back({0, "", ""});
            continue;
        }
        const auto arguments = test::expandTutorialWords(step, bandai, dir);
        const auto run = test::runBunrakuWith("env -C '" + dir.string() + "'", arguments);
        INFO("docs/TUTORIAL.md:" << step.line << ": bunraku " << step.words[1] << "\n" << run.out << run.err);
        REQUIRE(run.exitCode == 0);
        runs.push_back(run);
    }

    {
        INFO("info describes the 22-joint file");
        CHECK(runs[0].out.find("BVH: 22 joints + 5 End Sites, 132 channels, 187 frames") != std::string::npos);
        CHECK(runs[0].out.find("part map: head=Head (name), shoulder=Chest (topology), arm=LowerArm_R (name), hand=Hand_R (name)")
              != std::string::npos);
    }
    {
        INFO("the corpus reads back with the 15 waves, neutral 'normal', each on its 22-joint skeleton");
        auto corpus = analysis::io::readCorpus(dir / "waves");
        REQUIRE(corpus);
        CHECK(corpus->takes.size() == 15);
        CHECK(corpus->neutralEmotion == "normal");
        CHECK(corpus->rateHz == Approx(30.0));
        for (const char* emotion : {"normal", "active", "exhausted"}) CHECK(corpus->cell("wave-right-hand", emotion).size() == 5);
        Eigen::Index shortest = 1 << 30, longest = 0;
        for (const auto& take : corpus->takes) {
            REQUIRE(take.skeleton);
            CHECK(take.skeleton->skeleton->jointCount() == 22);
            shortest = std::min(shortest, take.frameCount());
            longest = std::max(longest, take.frameCount());
        }
        CHECK(shortest == 180); // "180 (active 1) to 216 frames (exhausted 2)"
        CHECK(longest == 216);
    }
    {
        INFO("the renders are PNGs of the sizes asked for");
        CHECK(pngSize(dir / "compare.png") == std::pair{1280, 720});
        CHECK(pngSize(dir / "designed.png") == std::pair{960, 540});
    }
    {
        INFO("normalising the active cell with the optimal path brings every take at least halfway to take 3");
        const fs::path out = dir / "active-normalised";
        const auto summary = nlohmann::json::parse(readTextFile(out / "summary.json"));
        CHECK(summary["suggested_reference"] == 3);
        CHECK(summary["files"].size() == 17); // 5 takes as CSV and on the performer's skeleton (.bvh), 5 correspondences...
        for (const auto& file : summary["files"]) CHECK(fs::is_regular_file(out / file.get<std::string>()));
        const auto families = varianceFamilies(out / "variance.csv");
        // The tutorial's table: take 1 426,829.2 -> 176,689.4 cm^2, 2,692,186.9 -> 1,022,209.8 deg^2.
        CHECK(families.at({1, "raw"}).position == Approx(426829.2).epsilon(0.01));
        CHECK(families.at({1, "normalised"}).position == Approx(176689.4).epsilon(0.05));
        CHECK(families.at({1, "raw"}).rotation == Approx(2692186.9).epsilon(0.01));
        CHECK(families.at({1, "normalised"}).rotation == Approx(1022209.8).epsilon(0.05));
        for (int take : {1, 2, 4, 5}) {
            INFO("take " << take);
            CHECK(families.at({take, "normalised"}).position < 0.5 * families.at({take, "raw"}).position);
            CHECK(families.at({take, "normalised"}).rotation < 0.5 * families.at({take, "raw"}).rotation);
        }
        CHECK(families.at({3, "normalised"}).position + families.at({3, "normalised"}).rotation < 1e-6);
    }
    {
        INFO("the analysis: KM2O with M = 1 and P near 0.07 %, the references, the phrases and the design's error");
        const fs::path out = dir / "analysis";
        CHECK(runs[5].out.find("analysed 15 takes in 3 cells (KM2O M = 1") != std::string::npos);
        const auto summary = nlohmann::json::parse(readTextFile(out / "summary.json"));
        CHECK(summary["takes"] == 15);
        CHECK(summary["decomposition"]["M"] == 1);
        CHECK(summary["decomposition"]["input"] == "normalised");
        const double p = summary["decomposition"]["mean_P_percent"].get<double>();
        CHECK(p > 0.05);
        CHECK(p < 0.09);
        CHECK(summary["decomposition"]["mean_P_percent_by_M"][1].get<double>() > p); // P rises with M
        std::map<std::string, int> references;
        for (const auto& cell : summary["cells"]) references[cell["emotion"].get<std::string>()] = cell["suggested_reference"].get<int>();
        CHECK(references == std::map<std::string, int>{{"normal", 5}, {"active", 3}, {"exhausted", 2}});
        for (const auto& axes : summary["axes"]) {
            INFO(axes["emotion"]);
            CHECK(axes["phrase_boundaries"] == nlohmann::json::array({0, 45, 69, 113, 125, 146, 168, 203, 215}));
            CHECK(axes["design_relative_error"].get<double>() < 0.5 * axes["undesigned_relative_error"].get<double>());
            if (axes["emotion"] == "exhausted") {
                CHECK(axes["undesigned_relative_error"].get<double>() == Approx(0.096).margin(0.005));
                CHECK(axes["design_relative_error"].get<double>() == Approx(0.024).margin(0.005));
            }
        }
        for (const char* file : {"report.html", "warp_wave-right-hand_exhausted.csv", "gains_wave-right-hand_exhausted.csv",
                                 "y_wave-right-hand.csv", "z_wave-right-hand_exhausted.csv", "variance_wave-right-hand_active.csv"})
            CHECK(fs::file_size(out / file) > 100);
    }
    {
        INFO("the weighted take and the average takes keep the performer's skeleton");
        checkBvh(dir / "exhausted-x2.bvh", 22, 216);
        checkBvh(dir / "functional.bvh", 22, 216);
        checkBvh(dir / "exhausted.bvh", 22, 216);
    }
    {
        INFO("the warp curve: 28 monotone control points, a mean shift of about 16 frames");
        const auto warp = test::readNumericCsv(dir / "warp.csv");
        REQUIRE(warp.header == std::vector<std::string>{"output_frame", "source_frame"});
        REQUIRE(warp.rows.size() == 28);
        CHECK(warp.rows.front() == std::vector<double>{0.0, 0.0});
        double shift = 0.0;
        for (std::size_t i = 0; i < warp.rows.size(); ++i) {
            shift += std::abs(warp.rows[i][0] - warp.rows[i][1]) / double(warp.rows.size());
            if (i == 0) continue;
            CHECK(warp.rows[i][0] > warp.rows[i - 1][0]);
            CHECK(warp.rows[i][1] >= warp.rows[i - 1][1]);
        }
        CHECK(shift == Approx(15.70).margin(0.5));
    }
    {
        INFO("the gains: 8 phrases from frame 0 to 215, a g0 and a g1 per phrase and axis DOF");
        CHECK(runs[10].out.find("8 phrases (boundaries 0 68 79 91 114 138 149 160 215") != std::string::npos);
        const auto gains = nlohmann::json::parse(readTextFile(dir / "gains.json"));
        REQUIRE(gains["phrases"].size() == 8);
        CHECK(gains["phrases"].front()["begin"] == 0);
        CHECK(gains["phrases"].back()["end"] == 215);
        for (const auto& phrase : gains["phrases"]) {
            REQUIRE(phrase["gains"].size() == 6);
            for (const auto& gain : phrase["gains"]) CHECK((std::isfinite(gain["g0"].get<double>()) && std::isfinite(gain["g1"].get<double>())));
        }
    }
    {
        INFO("the designed takes re-import with the source's 22 joints; the glTF files parse");
        checkBvh(dir / "timing-only.bvh", 22, 216);
        checkBvh(dir / "designed.bvh", 22, 216);
        auto source = analysis::io::readBvh(bandai / "wave-right-hand_normal_001.bvh");
        auto designed = analysis::io::readBvh(dir / "designed.bvh");
        auto functional = analysis::io::readBvh(dir / "functional.bvh");
        REQUIRE(source);
        REQUIRE(designed);
        REQUIRE(functional);
        REQUIRE(designed->skeleton.joints.size() == source->skeleton.joints.size());
        for (std::size_t j = 0; j < source->skeleton.joints.size(); ++j)
            CHECK(designed->skeleton.joints[j].name == source->skeleton.joints[j].name);
        // The design changed the motion: the functional take's frame 100 is not the designed one's.
        CHECK((designed->motion.values.row(100) - functional->motion.values.row(100)).cwiseAbs().maxCoeff() > 1.0);
        checkGlb(dir / "designed.glb", 22, 216);
        checkGlb(dir / "designed-again.glb", 22, 216);
        CHECK(runs.back().out.find("BVH: 22 joints + 5 End Sites, 132 channels, 216 frames") != std::string::npos);
    }
}
