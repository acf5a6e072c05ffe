// `bunraku convert TAKE --kimono -o FILE.csv`: the kimono simulated as cloth over the take, its
// measured points appended as 18 channels (analysis/cloth/kimono_cloth.h).
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/shared_data.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

using bunraku::test::runBunraku;

namespace {

/// The column of `name` in a CSV header, or -1.
int column(const std::vector<std::string>& header, const std::string& name)
{
    const auto found = std::find(header.begin(), header.end(), name);
    return found == header.end() ? -1 : int(found - header.begin());
}

void checkKimonoCsv(const std::filesystem::path& csvFile, std::size_t takeChannels)
{
    const auto csv = bunraku::test::readNumericCsv(csvFile);
    REQUIRE(csv.header.size() == 1 + takeChannels + 18);
    CHECK(csv.header[1 + takeChannels] == "sleeve_right_tip.x");
    CHECK(csv.header.back() == "hem_right.z");
    const int shoulderZ = column(csv.header, "shoulder.z");
    REQUIRE(shoulderZ > 0);
    for (const char* point : {"hem_front", "hem_back", "hem_left", "hem_right"}) {
        const int z = column(csv.header, std::string(point) + ".z");
        REQUIRE(z > 0);
        for (const auto& row : csv.rows) {
            INFO(point << " at " << row[0] << " s");
            // The hem hangs well below the shoulder sensor (the dō-wa is 24 cm below it).
            CHECK(row[std::size_t(z)] < row[std::size_t(shoulderZ)] - 24.0);
            CHECK(std::isfinite(row[std::size_t(z)]));
        }
    }
}

} // namespace

TEST_CASE("convert --kimono appends the kimono's 18 channels to a demo take and refuses a .bvh output", "[cli][kimono]")
{
    const auto dir = bunraku::test::scratchDir("cli_kimono");
    auto run = runBunraku({"demo", "-o", (dir / "demo").string()});
    REQUIRE(run.exitCode == 0);
    const auto take = dir / "demo" / "greeting_hostile_1.csv";
    run = runBunraku({"convert", take.string(), "--kimono", "-o", (dir / "kimono.csv").string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(run.out.find("42 channels, the kimono's 18 among them") != std::string::npos);
    checkKimonoCsv(dir / "kimono.csv", 24);

    run = runBunraku({"convert", take.string(), "--kimono", "-o", (dir / "kimono.bvh").string()});
    CHECK(run.exitCode != 0);
    CHECK(run.err.find("--kimono writes a .csv take") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "kimono.bvh"));
    run = runBunraku({"convert", take.string(), "--kimono", "--cloth-mass", "0", "-o", (dir / "bad.csv").string()});
    CHECK(run.exitCode == 2); // outside the option's range
}

TEST_CASE("convert --kimono on a Bandai wave dresses the puppet fitted to the performer", "[cli][kimono][bandai]")
{
    const auto bvh = bunraku::test::bandaiDir() / "wave-right-hand_active_001.bvh";
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(bvh))) return;
    const auto dir = bunraku::test::scratchDir("cli_kimono_bandai");
    const auto run = runBunraku({"convert", bvh.string(), "--kimono", "-o", (dir / "wave.csv").string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    checkKimonoCsv(dir / "wave.csv", 24);
}

TEST_CASE("experiment kimono measures every take of a corpus and the means per cell", "[cli][kimono]")
{
    const auto dir = bunraku::test::scratchDir("cli_kimono_experiment");
    auto run = runBunraku({"demo", "-o", (dir / "demo").string()});
    REQUIRE(run.exitCode == 0);
    // Two cells of two takes (the whole demo corpus takes some 15 s).
    run = runBunraku({"corpus", (dir / "demo" / "greeting_none_1.csv").string(), (dir / "demo" / "greeting_none_2.csv").string(),
                      (dir / "demo" / "greeting_hostile_1.csv").string(), (dir / "demo" / "greeting_hostile_2.csv").string(), "-o",
                      (dir / "small").string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    run = runBunraku({"experiment", "kimono", (dir / "small").string(), "--json", "--figure", (dir / "kimono.svg").string()});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    const auto report = nlohmann::json::parse(run.out);
    // The figure: one dot per take in each of its two plots, one per cell in each legend, and
    // the takes' values where the dots are (the first plot's y axis reaches the largest swing).
    std::ifstream svgFile(dir / "kimono.svg");
    std::stringstream svg;
    svg << svgFile.rdbuf();
    std::size_t dots = 0;
    for (std::size_t at = svg.str().find("<circle"); at != std::string::npos; at = svg.str().find("<circle", at + 1)) ++dots;
    CHECK(dots == 2 * 4 + 2 * 2);
    CHECK(svg.str().find("greeting") == std::string::npos); // one function: the legend names the emotions
    CHECK(svg.str().find(">hostile</text>") != std::string::npos);
    CHECK(svg.str().rfind("</svg>") != std::string::npos);
    run = runBunraku({"experiment", "kimono", (dir / "small").string(), "--figure", (dir / "small" / "corpus.json").string()});
    CHECK(run.exitCode != 0); // never over the corpus it reads
    CHECK(run.err.find("--figure") != std::string::npos);
    REQUIRE(report["takes"].size() == 4);
    REQUIRE(report["cells"].size() == 2);
    for (const auto& take : report["takes"]) {
        CHECK(take["sleeve_swing_right_cm"].get<double>() > 0.0);
        CHECK(take["sleeve_swing_right_cm"].get<double>() < 20.0);
        CHECK(std::abs(take["sleeve_lag_s"].get<double>()) <= 0.5 + 1e-9);
        CHECK(take["hem_swing_cm"].get<double>() > 0.0);
        // The left sleeve mirrors the right one's arm: a swing of the same size.
        CHECK(take["sleeve_swing_left_cm"].get<double>() == Approx(take["sleeve_swing_right_cm"].get<double>()).epsilon(0.5));
    }
    for (const auto& cell : report["cells"]) CHECK(cell["takes"] == 2);
}
