// The command line end to end: BVH conversion round trips, demo -> preprocess -> decompose ->
// emotion, and the atomic replacement of output files.
#include "tests/support/shared_data.h"
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"

#include "analysis/io/bvh.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/take_csv.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

using bunraku::test::readNumericCsv;
using bunraku::test::runBunraku;
using nlohmann::json;

namespace {

/// Largest difference of two numeric CSVs of equal shape; angle columns (`.yaw`, `.pitch`,
/// `.roll`) compared modulo 360 degrees.
double largestDifference(const bunraku::test::NumericCsv& a, const bunraku::test::NumericCsv& b)
{
    REQUIRE(a.header == b.header);
    REQUIRE(a.rows.size() == b.rows.size());
    double largest = 0.0;
    for (std::size_t r = 0; r < a.rows.size(); ++r) {
        REQUIRE(a.rows[r].size() == b.rows[r].size());
        for (std::size_t c = 0; c < a.rows[r].size(); ++c) {
            const std::string& name = a.header[c];
            const bool angle = name.size() > 4 && (name.ends_with(".yaw") || name.ends_with(".pitch") || name.ends_with(".roll"));
            double d = a.rows[r][c] - b.rows[r][c];
            if (angle) d = std::remainder(d, 360.0);
            largest = std::max(largest, std::fabs(d));
        }
    }
    return largest;
}

json runJson(const std::vector<std::string>& arguments)
{
    const auto run = runBunraku(arguments);
    INFO(arguments.front() << ": " << run.err);
    REQUIRE(run.exitCode == 0);
    return json::parse(run.out);
}

} // namespace

TEST_CASE("bunraku convert takes a bandai BVH to CSV and back to BVH without changing the take", "[cli]")
{
    const auto source = bunraku::test::bandaiDir() / "bye_normal_001.bvh";
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(source))) return;
    const auto dir = bunraku::test::scratchDir("cli-convert");
    const auto info = runJson({"info", source.string(), "--json"});
    CHECK(info.at("format") == "bvh");
    CHECK(info.at("joint_count").get<int>() > 4);

    const auto csv = dir / "bye.csv";
    const auto converted = runJson({"convert", source.string(), "-o", csv.string(), "--json"});
    CHECK(converted.at("output_format") == "csv");
    CHECK(converted.at("channels") == 24);
    CHECK(converted.at("frames") == info.at("frames"));

    const auto csvInfo = runJson({"info", csv.string(), "--json"});
    CHECK(csvInfo.at("frames") == info.at("frames"));
    CHECK(csvInfo.at("channels") == 24);
    CHECK(csvInfo.at("rate_hz").get<double>() == Approx(info.at("rate_hz").get<double>()).epsilon(1e-6));

    const auto bvh = dir / "bye-puppet.bvh";
    runJson({"convert", csv.string(), "-o", bvh.string(), "--json"});
    const auto back = dir / "bye-back.csv";
    runJson({"convert", bvh.string(), "-o", back.string(), "--json"});
    // 1e-6 cm / 1e-6 deg (issue 2), relative to the shortest-round-trip numbers written.
    CHECK(largestDifference(readNumericCsv(csv), readNumericCsv(back)) < 1e-6);
}

TEST_CASE("demo, preprocess and least-squares decompose run end to end against the ground truth", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-pipeline");
    const auto demo = dir / "demo", pre = dir / "pre", out = dir / "ls";
    runJson({"demo", "-o", demo.string(), "--seed", "3", "--json"});
    const auto report = runJson({"preprocess", demo.string(), "-o", pre.string(), "--json"});
    CHECK(report.at("takes") == 30);
    CHECK(report.at("channels") == 24);
    int shifted = 0, turned = 0;
    for (const auto& take : report.at("report")) {
        shifted += take.at("shift_frames").get<int>() != 0 ? 1 : 0;
        turned += std::fabs(take.at("heading_offset_deg").get<double>()) > 90.0 ? 1 : 0;
    }
    CHECK(shifted > 0);
    CHECK(turned > 0); // one take per cell has its yaw offset by about 180 deg

    CHECK(report.at("truth_copied") == true); // the preprocessed corpus keeps the demo's ground truth
    const auto summary = runJson({"decompose", pre.string(), "--method", "ls", "-o", out.string(), "--json"});
    REQUIRE(summary.contains("truth"));
    CHECK(summary.at("functions").size() == 2);
    CHECK(summary.at("cells").size() == 6);
    CHECK(summary.at("frames") == report.at("frames"));
    for (const auto& file : summary.at("files")) CHECK(std::filesystem::exists(out / file.get<std::string>()));
    // Preprocessing aligned the takes: the function estimate is close to the true y^i.
    for (const auto& [function, error] : summary.at("truth").at("y").items()) {
        INFO(function);
        CHECK(error.at("relative_error_percent").get<double>() < 5.0);
    }
    // z^{i,none} = 0 by hypothesis 4; the other cells' z is close to the truth.
    for (const auto& [cell, error] : summary.at("truth").at("z").items()) {
        INFO(cell);
        CHECK(error.at("rms").get<double>() < 10.0);
    }
}

TEST_CASE("bunraku emotion --per-channel with weight 0 gives y and with weight 1 gives y + z", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-emotion");
    const auto demo = dir / "demo", out = dir / "ls";
    runJson({"demo", "-o", demo.string(), "--seed", "5", "--json"});
    runJson({"decompose", demo.string(), "--pad", "--method", "ls", "-o", out.string(), "--json"});
    const auto zero = dir / "a0.csv", one = dir / "a1.csv";
    for (const auto& [weight, file] : {std::pair{"0", zero}, std::pair{"1", one}}) {
        const auto run = runBunraku({"emotion", demo.string(), "--pad", "--method", "ls", "--function", "serving-tea", "--emotion", "hostile",
                                     "--weight", weight, "--per-channel", "-o", file.string()});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
    }
    const auto y = readNumericCsv(out / "y_serving-tea.csv");
    const auto z = readNumericCsv(out / "z_serving-tea_hostile.csv");
    CHECK(largestDifference(readNumericCsv(zero), y) == 0.0);
    // Positions add as numbers; orientations add as rotation coordinates (z's angle columns are
    // the rotation vector in degrees), so the weighted angles are not y's plus z's.
    auto sum = y;
    const auto weighted = readNumericCsv(one);
    for (std::size_t r = 0; r < sum.rows.size(); ++r)
        for (std::size_t c = 1; c < sum.rows[r].size(); ++c) {
            const std::string& name = y.header[c];
            const bool angle = name.ends_with(".yaw") || name.ends_with(".pitch") || name.ends_with(".roll");
            if (angle) sum.rows[r][c] = weighted.rows[r][c];
            else sum.rows[r][c] += z.rows[r][c];
        }
    CHECK(largestDifference(weighted, sum) < 1e-9);
}

TEST_CASE("phase, gains and design run on a 138-frame reference and a 90-frame sample", "[cli]")
{
    const auto happy = bunraku::test::bandaiDir() / "bye_happy_001.bvh";
    const auto angry = bunraku::test::bandaiDir() / "bye_angry_001.bvh";
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(happy) && std::filesystem::exists(angry))) return;
    const auto dir = bunraku::test::scratchDir("cli-lengths");
    runJson({"convert", happy.string(), "-o", (dir / "happy.csv").string(), "--json"});
    runJson({"convert", angry.string(), "-o", (dir / "angry.csv").string(), "--json"});
    // The first 138 frames of the happy wave, and the angry one hurried from 110 into 90 frames
    // (the nearest frame at 109/89 of the time), as CSV takes at 30 Hz.
    auto rewrite = [&](const std::filesystem::path& in, const std::filesystem::path& out, int frames, double step) {
        const auto csv = readNumericCsv(in);
        std::ostringstream text;
        text.precision(17);
        for (std::size_t c = 0; c < csv.header.size(); ++c) text << (c ? "," : "") << csv.header[c];
        text << "\n";
        for (int t = 0; t < frames; ++t) {
            const auto& row = csv.rows[std::size_t(std::lround(step * t))];
            text << double(t) / 30.0;
            for (std::size_t c = 1; c < row.size(); ++c) text << "," << row[c];
            text << "\n";
        }
        bunraku::test::writeText(out, text.str());
    };
    const auto reference = dir / "bye_reference_138.csv", sample = dir / "bye_angry_90.csv";
    rewrite(dir / "happy.csv", reference, 138, 1.0);
    rewrite(dir / "angry.csv", sample, 90, 109.0 / 89.0);
    CHECK(runJson({"info", reference.string(), "--json"}).at("frames") == 138);
    CHECK(runJson({"info", sample.string(), "--json"}).at("frames") == 90);

    const auto warp = dir / "warp.csv", gains = dir / "gains.json", designed = dir / "designed.csv";
    const auto bandOnly = runBunraku({"phase", "--reference", reference.string(), "--sample", sample.string(), "-o",
                                      (dir / "none.csv").string(), "--time-scale", "none"});
    CHECK(bandOnly.exitCode != 0); // the thesis's band alone has no path
    CHECK(bandOnly.err.find("138") != std::string::npos);
    const auto phase = runJson({"phase", "--reference", reference.string(), "--sample", sample.string(), "-o", warp.string(), "--json"});
    CHECK(phase.at("correspondence").size() == 138);
    CHECK(phase.at("control_points").back().at(0).get<double>() == Approx(89.0));
    CHECK(phase.at("control_points").back().at(1).get<double>() > 100.0);
    runJson({"gains", "--reference", reference.string(), "--sample", sample.string(), "--warp", warp.string(), "-o",
             gains.string(), "--json"});
    const auto design = runJson({"design", reference.string(), "--warp", warp.string(), "--gains", gains.string(), "-o",
                                 designed.string(), "--json"});
    CHECK(design.at("frames") == 90);
    CHECK(readNumericCsv(designed).rows.size() == 90);
}

TEST_CASE("decompose replaces its output files instead of rewriting them in place", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-atomic");
    const auto demo = dir / "demo", out = dir / "ls";
    runJson({"demo", "-o", demo.string(), "--json"});
    runJson({"decompose", demo.string(), "--pad", "--method", "ls", "-o", out.string(), "--json"});
    // The earlier summary.json shared with another name (a hard link): replacing the output
    // (built beside it and swapped in) leaves the other name's content alone; writing in place
    // would change it.
    const std::string old = bunraku::test::readTextFile(out / "summary.json");
    std::filesystem::create_hard_link(out / "summary.json", dir / "kept.json");
    runJson({"decompose", demo.string(), "--pad", "--method", "km2o", "-o", out.string(), "--json"});
    CHECK(bunraku::test::readTextFile(dir / "kept.json") == old);
    CHECK(json::parse(bunraku::test::readTextFile(dir / "kept.json")).at("method") == "ls");
    CHECK(json::parse(bunraku::test::readTextFile(out / "summary.json")).at("method") == "km2o");
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        CHECK(entry.path().filename().string().rfind(".", 0) != 0); // no temporary folders left
    for (const auto& entry : std::filesystem::directory_iterator(out)) // only the manifest is hidden
        CHECK((entry.path().filename().string().rfind(".", 0) != 0 || entry.path().filename() == ".bunraku-files.json"));
}

TEST_CASE("preprocessing a demo corpus keeps its ground truth and leaves no temporary folders", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-preprocess-truth");
    const auto demo = dir / "demo", preprocessed = dir / "preprocessed";
    runJson({"demo", "-o", demo.string(), "--json"});
    const auto report = runJson({"preprocess", demo.string(), "-o", preprocessed.string(), "--json"});
    CHECK(report.at("truth_copied") == true);
    CHECK(std::filesystem::is_regular_file(preprocessed / "truth" / "truth.json"));
    CHECK(bunraku::test::readTextFile(preprocessed / "truth" / "truth.json") == bunraku::test::readTextFile(demo / "truth" / "truth.json"));
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        CHECK(entry.path().filename().string().rfind(".", 0) != 0);
    const auto summary = runJson({"decompose", preprocessed.string(), "--method", "ls", "-o", (dir / "ls").string(), "--json"});
    CHECK(summary.contains("truth"));
}

TEST_CASE("normalise writes each normalised take of a BVH corpus on the performer's skeleton, listed in the manifest", "[cli][bandai]")
{
    std::vector<std::string> files;
    for (int k = 1; k <= 3; ++k) files.push_back((bunraku::test::bandaiDir() / ("wave-right-hand_active_00" + std::to_string(k) + ".bvh")).string());
    bool present = true;
    for (const auto& file : files) present = present && std::filesystem::exists(file);
    if (!bunraku::test::requireBandaiData(present)) return;
    const auto dir = bunraku::test::scratchDir("cli-normalise-bvh");
    std::vector<std::string> corpus{"corpus"};
    corpus.insert(corpus.end(), files.begin(), files.end());
    corpus.insert(corpus.end(), {"-o", (dir / "waves").string()});
    REQUIRE(runBunraku(corpus).exitCode == 0);
    const auto out = dir / "out";
    const auto run = runBunraku({"normalise", (dir / "waves").string(), "--function", "wave-right-hand", "--emotion", "active", "-o",
                                 out.string(), "--json"});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const auto summary = json::parse(run.out);
    const auto reference = bunraku::analysis::io::readTakeCsv(out / "reference.csv");
    REQUIRE(reference.ok());
    const auto source = bunraku::analysis::io::readBvh(files.front());
    REQUIRE(source.ok());
    REQUIRE(source->skeleton.jointCount() == 22);
    const json manifest = json::parse(bunraku::test::readTextFile(out / bunraku::analysis::io::kWrittenFilesManifest));
    const std::string manifestText = manifest.dump();
    std::vector<std::string> listed;
    for (const auto& file : summary.at("files")) listed.push_back(file.get<std::string>());
    for (int k = 1; k <= 3; ++k) {
        const std::string name = "wave-right-hand_active_" + std::to_string(k) + "_normalised.bvh";
        INFO(name);
        CHECK(std::find(listed.begin(), listed.end(), name) != listed.end());
        CHECK(manifestText.find("\"" + name + "\"") != std::string::npos);
        const auto bvh = bunraku::analysis::io::readBvh(out / name);
        REQUIRE(bvh.ok());
        CHECK(bvh->skeleton.jointCount() == source->skeleton.jointCount());
        CHECK(bvh->motion.values.rows() == reference->frameCount());
        CHECK(bvh->motion.frameTime == Approx(source->motion.frameTime));
    }
    // Nothing in the folder the manifest does not list: it may be replaced by the next run.
    CHECK(bunraku::analysis::io::foreignFiles(out).empty());
}

TEST_CASE("normalise prints and writes the variance per DOF family and marks the takes it moved away", "[cli]")
{
    std::vector<std::string> files;
    for (int k = 1; k <= 5; ++k) files.push_back((bunraku::test::bandaiDir() / ("wave-right-hand_active_00" + std::to_string(k) + ".bvh")).string());
    bool present = true;
    for (const auto& file : files) present = present && std::filesystem::exists(file);
    if (!bunraku::test::requireBandaiData(present)) return;
    const auto dir = bunraku::test::scratchDir("cli-normalise-families");
    std::vector<std::string> corpus{"corpus"};
    corpus.insert(corpus.end(), files.begin(), files.end());
    corpus.insert(corpus.end(), {"-o", (dir / "waves").string()});
    REQUIRE(runBunraku(corpus).exitCode == 0);
    for (const std::string path : {"greedy", "optimal", ""}) {
        INFO("--path " << (path.empty() ? "(default)" : path));
        std::vector<std::string> arguments{"normalise", (dir / "waves").string(), "--function", "wave-right-hand", "--emotion", "active",
                                           "-o", (dir / (path.empty() ? "default" : path)).string()};
        if (!path.empty()) arguments.insert(arguments.end(), {"--path", path});
        auto withJson = arguments;
        withJson.push_back("--json");
        const json summary = runJson(withJson);
        CHECK(summary.at("path") == (path.empty() ? "optimal" : path)); // the default is the optimal path
        std::vector<int> worse;
        for (const auto& take : summary.at("takes")) {
            REQUIRE(take.at("families").size() == 2);
            const auto& position = take.at("families")[0];
            const auto& rotation = take.at("families")[1];
            CHECK(position.at("family") == "position");
            CHECK(position.at("unit") == "cm\u00b2");
            CHECK(rotation.at("family") == "rotation");
            CHECK(rotation.at("unit") == "deg\u00b2");
            // The families split the thesis's total over the 24 channels.
            CHECK(position.at("raw").get<double>() + rotation.at("raw").get<double>() ==
                  Approx(take.at("variance_raw").get<double>()).epsilon(1e-12));
            CHECK(position.at("normalised").get<double>() + rotation.at("normalised").get<double>() ==
                  Approx(take.at("variance_normalised").get<double>()).epsilon(1e-12));
            if (take.at("take") == 3) CHECK(take.at("variance_normalised") == 0.0); // the reference
            for (const auto& family : take.at("families"))
                if (family.at("normalised").get<double>() > family.at("raw").get<double>()) {
                    worse.push_back(take.at("take").get<int>());
                    break;
                }
        }
        const auto printed = runBunraku(arguments);
        REQUIRE(printed.exitCode == 0);
        CHECK(printed.out.find("position cm\u00b2") != std::string::npos);
        std::size_t marked = 0;
        for (std::size_t at = printed.out.find("  worse"); at != std::string::npos; at = printed.out.find("  worse", at + 1)) ++marked;
        if (path == "greedy") {
            // The greedy scan moves takes 2 and 4 away from the reference, in both families.
            CHECK(worse == std::vector<int>{2, 4});
            CHECK(marked == 4);
            CHECK(printed.out.find("take(s) 2 4: normalised further from the reference than raw") != std::string::npos);
            CHECK(printed.out.find("--path optimal") != std::string::npos);
        } else {
            CHECK(worse.empty());
            CHECK(marked == 0);
        }
    }
}

TEST_CASE("normalise with its defaults lowers the variance of at least 4 of 5 takes in every Bandai wave cell", "[cli]")
{
    std::vector<std::string> files;
    for (const std::string style : {"normal", "active", "exhausted"})
        for (int k = 1; k <= 5; ++k)
            files.push_back((bunraku::test::bandaiDir() / ("wave-right-hand_" + style + "_00" + std::to_string(k) + ".bvh")).string());
    bool present = true;
    for (const auto& file : files) present = present && std::filesystem::exists(file);
    if (!bunraku::test::requireBandaiData(present)) return;
    const auto dir = bunraku::test::scratchDir("cli-normalise-defaults");
    std::vector<std::string> corpus{"corpus"};
    corpus.insert(corpus.end(), files.begin(), files.end());
    corpus.insert(corpus.end(), {"-o", (dir / "waves").string(), "--pattern", "{function}_{emotion}_{take}"});
    REQUIRE(runBunraku(corpus).exitCode == 0);
    // The suggested take (the default reference: it stays at 0, the other four fall) and the
    // average take of all five (all five fall); no option but the reference given.
    for (const std::string reference : {"", "average"})
        for (const std::string style : {"normal", "active", "exhausted"}) {
            std::vector<std::string> arguments{"normalise", (dir / "waves").string(), "--function", "wave-right-hand", "--emotion", style,
                                               "-o", (dir / ("out-" + style + reference)).string(), "--json"};
            if (!reference.empty()) arguments.insert(arguments.end(), {"--reference", reference});
            const json summary = runJson(arguments);
            INFO(style << " " << (reference.empty() ? "suggested" : reference) << ": " << summary.at("takes").dump());
            CHECK(summary.at("path") == "optimal");
            REQUIRE(summary.at("takes").size() == 5);
            int lowered = 0;
            for (const auto& take : summary.at("takes")) {
                const double raw = take.at("variance_raw").get<double>(), normalised = take.at("variance_normalised").get<double>();
                lowered += normalised < raw ? 1 : 0;
                CHECK(normalised <= raw); // none rises (the reference take stays at 0)
            }
            CHECK(lowered >= 4);
            if (!reference.empty()) CHECK(lowered == 5);
        }
}
