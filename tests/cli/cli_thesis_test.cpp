// The command line's thesis comparisons of issue "closer to the thesis": the noise experiment's
// two sets of bands, the per-scale approximation error, Table 4.4's readings, the start-position
// step and Table 4.1's MA convention in the decomposition's ARMA table.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using bunraku::test::runBunraku;

TEST_CASE("experiment noise reports the thesis's bands beside the workbench's", "[cli][thesis]")
{
    const auto run = runBunraku({"experiment", "noise", "--json"});
    REQUIRE(run.exitCode == 0);
    const auto json = nlohmann::json::parse(run.out);
    const auto& thesis = json["thesis_bands"]["methods"];
    REQUIRE(thesis.size() == 3);
    CHECK(thesis[1]["name"] == "wavelet-below-noise");
    CHECK(thesis[1]["scales"].front() == 28.0);
    CHECK(thesis[1]["scales"].back() == 35.0);
    CHECK(thesis[2]["scales"].back() == 35.0);
    CHECK(thesis[0]["shape_rms"].get<double>() > thesis[1]["shape_rms"].get<double>());
    CHECK(json["thesis_bands"]["with_time_constraint"]["methods"].size() == 3);
    // the workbench's variant, as before: below the noise ranks first
    const auto& ours = json["methods"];
    REQUIRE(ours.size() == 3);
    CHECK(ours[1]["mean_abs_error_frames"].get<double>() < ours[2]["mean_abs_error_frames"].get<double>());
    CHECK(ours[1]["mean_abs_error_frames"].get<double>() < ours[0]["mean_abs_error_frames"].get<double>());
    const auto text = runBunraku({"experiment", "noise"});
    CHECK(text.out.find("thesis bands") != std::string::npos);
    CHECK(text.out.find("28..35") != std::string::npos);
}

TEST_CASE("experiment approximation writes eq. 5.18 per scale and DOF as JSON and CSV", "[cli][thesis]")
{
    const auto dir = bunraku::test::scratchDir("cli-approximation");
    const auto csv = dir / "approximation.csv";
    const auto run = runBunraku({"experiment", "approximation", "demo", "--max-scale", "12", "--csv", csv.string(), "--json"});
    REQUIRE(run.exitCode == 0);
    const auto json = nlohmann::json::parse(run.out);
    REQUIRE(json["cells"].size() == 4);
    const auto& cell = json["cells"][0];
    CHECK(cell["scales"].size() == 12);
    CHECK(cell["relative_error"].size() == 6);
    CHECK(cell["relative_error"]["axis.x"].size() == 12);
    CHECK(cell["thesis"].is_null());
    CHECK(json["thesis_figure"].get<std::string>().find("Fig. 5.16") != std::string::npos);
    const auto& mean = cell["mean_relative_error"];
    CHECK(mean.back().get<double>() < mean.front().get<double>());
    const std::string text = bunraku::test::readTextFile(csv);
    CHECK(text.rfind("function,emotion,scale,dof,relative_error,thesis\n", 0) == 0);
    std::size_t lines = 0;
    for (char c : text) lines += c == '\n' ? 1 : 0;
    CHECK(lines == 1 + 4 * 12 * 7); // 4 cells x 12 scales x (6 DOF + mean)
    CHECK(runBunraku({"experiment", "approximation", "demo", "--max-scale", "0"}).exitCode != 0);
}

TEST_CASE("experiment km2o shares the noise over the cells and takes K' takes on request", "[cli][thesis]")
{
    const auto run = runBunraku({"experiment", "km2o", "--T", "1000", "--M", "5:6", "--seeds", "1", "--noise-sharing",
                                 "shared", "--takes", "8", "--json"});
    REQUIRE(run.exitCode == 0);
    const auto json = nlohmann::json::parse(run.out);
    CHECK(json["noise_sharing"] == "shared");
    CHECK(json["takes"] == 8);
    CHECK(json["thesis_printed"][0].get<double>() == Approx(0.25));
    CHECK(json["thesis_P_percent"][0].get<double>() == Approx(0.025));
    CHECK(runBunraku({"experiment", "km2o", "--noise-sharing", "some"}).exitCode != 0);
    CHECK(runBunraku({"experiment", "km2o", "--takes", "1"}).exitCode != 0);
}

TEST_CASE("preprocess moves each take rigidly by default and per part on request", "[cli][thesis]")
{
    const auto dir = bunraku::test::scratchDir("cli-start-position");
    REQUIRE(runBunraku({"demo", "-o", (dir / "demo").string()}).exitCode == 0);
    for (const std::string mode : {"rigid", "per-part"}) {
        const auto run = runBunraku({"preprocess", (dir / "demo").string(), "-o", (dir / mode).string(), "--position", mode, "--json"});
        REQUIRE(run.exitCode == 0);
        const auto json = nlohmann::json::parse(run.out);
        CHECK(json["position_alignment"] == mode);
        bool allEqual = true, someDiffer = false;
        for (const auto& take : json["report"]) {
            const auto& offsets = take["position_offsets"];
            for (const auto& offset : offsets) {
                const bool same = offset["offset_cm"] == offsets[0]["offset_cm"];
                allEqual = allEqual && same;
                someDiffer = someDiffer || !same;
            }
        }
        if (mode == "rigid") CHECK(allEqual);
        else CHECK(someDiffer);
    }
    CHECK(runBunraku({"preprocess", (dir / "demo").string(), "-o", (dir / "x").string(), "--position", "affine"}).exitCode != 0);
}

TEST_CASE("the ARMA table carries Table 4.1's MA convention beside the invertible one", "[cli][thesis]")
{
    const auto dir = bunraku::test::scratchDir("cli-arma-convention");
    REQUIRE(runBunraku({"demo", "-o", (dir / "demo").string()}).exitCode == 0);
    REQUIRE(runBunraku({"decompose", (dir / "demo").string(), "--pad", "-o", (dir / "out").string()}).exitCode == 0);
    const std::string table = bunraku::test::readTextFile(dir / "out" / "arma_table.csv");
    CHECK(table.rfind("channel,function,emotion,takes,a1,a2,b0,b1,b2,b0_thesis,b1_thesis,b2_thesis,innovation_variance,fpe\n", 0) == 0);
}

TEST_CASE("the thesis's greedy scan, one option away, keeps the demo corpus's numbers of before the default changed", "[cli][thesis]")
{
    // Thesis 3.8 variance (24 channels, summed over the cell's takes) of every demo cell
    // normalised to its suggested take with --path greedy, as the default gave them until the
    // optimal path became the default (2026-11-28); the optimal path's beside them.
    struct Cell {
        const char* function;
        const char* emotion;
        double raw, greedy, optimal;
    };
    const Cell cells[] = {
        {"greeting", "none", 16721.22595236933, 3530.154017408794, 3530.154017408794},
        {"greeting", "friendly", 67527.54477767594, 6160.001630269756, 6160.038775091585},
        {"greeting", "hostile", 6956.61880610132, 1882.1064540262673, 1757.6393099947072},
        {"serving-tea", "none", 17421.86427537705, 6417.415714980331, 6149.094911637249},
        {"serving-tea", "friendly", 61501.84725489264, 9655.872034894594, 9379.095450496323},
        {"serving-tea", "hostile", 12621.868785337647, 3018.0105813713485, 3008.345798388381},
    };
    const auto dir = bunraku::test::scratchDir("cli-greedy-demo");
    REQUIRE(runBunraku({"demo", "-o", (dir / "demo").string(), "--json"}).exitCode == 0);
    for (const Cell& cell : cells) {
        for (const std::string path : {"greedy", "optimal", ""}) {
            INFO(cell.function << "/" << cell.emotion << " --path " << (path.empty() ? "(default)" : path));
            std::vector<std::string> arguments{"normalise", (dir / "demo").string(), "--function", cell.function, "--emotion", cell.emotion,
                                               "-o", (dir / (std::string(cell.function) + cell.emotion + path)).string(), "--json"};
            if (!path.empty()) arguments.insert(arguments.end(), {"--path", path});
            const auto run = runBunraku(arguments);
            INFO(run.err);
            REQUIRE(run.exitCode == 0);
            const auto summary = nlohmann::json::parse(run.out);
            const double expected = path == "greedy" ? cell.greedy : cell.optimal; // the default: optimal
            CHECK(summary.at("path") == (path.empty() ? "optimal" : path));
            CHECK(summary.at("variance_raw_total").get<double>() == Approx(cell.raw).epsilon(1e-12));
            CHECK(summary.at("variance_normalised_total").get<double>() == Approx(expected).epsilon(1e-12));
        }
    }
}
