// `bunraku convert TAKE --kimono -o FILE.csv`: the kimono simulated as cloth over the take, its
// measured points appended as 18 channels (analysis/cloth/kimono_cloth.h); `--kimono -o FILE.glb`
// of the commands that write a take: the cloth as a mesh moving by morph targets.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/shared_data.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
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

namespace {

/// The JSON chunk of a .glb (a 12-byte header, then the JSON chunk).
nlohmann::json glbJson(const std::filesystem::path& file)
{
    const std::string bytes = bunraku::test::readTextFile(file);
    REQUIRE(bytes.size() > 20);
    REQUIRE(bytes.compare(0, 4, "glTF") == 0);
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.substr(20, length));
}

/// The frames of the kimono's weights animation in a .glb (0 when there is none).
std::size_t kimonoKeys(const nlohmann::json& gltf)
{
    int node = -1;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n)
        if (gltf["nodes"][n].value("name", std::string()) == "kimono_cloth") node = int(n);
    if (node < 0) return 0;
    for (const auto& animation : gltf["animations"])
        for (const auto& channel : animation["channels"])
            if (channel["target"]["node"] == node && channel["target"]["path"] == "weights")
                return gltf["accessors"][animation["samplers"][channel["sampler"].get<std::size_t>()]["input"].get<std::size_t>()]["count"];
    return 0;
}

} // namespace

TEST_CASE("the commands that write a take put the simulated kimono into a glb with --kimono", "[cli][kimono][export]")
{
    const auto dir = bunraku::test::scratchDir("cli_kimono_glb");
    const auto demo = dir / "demo";
    REQUIRE(runBunraku({"demo", "-o", demo.string()}).exitCode == 0);
    const auto take = demo / "greeting_hostile_1.csv";
    const std::size_t frames = bunraku::test::readNumericCsv(take).rows.size();
    const std::vector<std::pair<std::string, std::vector<std::string>>> commands{
        {"convert", {"convert", take.string(), "--kimono", "-o", (dir / "converted.glb").string()}},
        {"design", {"design", take.string(), "--kimono", "--cloth-drag", "1", "-o", (dir / "designed.glb").string()}},
        {"normalise", {"normalise", demo.string(), "--function", "greeting", "--emotion", "hostile", "--kimono", "-o", (dir / "reference.glb").string()}},
        {"emotion", {"emotion", demo.string(), "--pad", "--function", "greeting", "--emotion", "hostile", "--weight", "1.5", "--kimono", "-o",
                     (dir / "weighted.glb").string()}}};
    for (const auto& [name, arguments] : commands) {
        const auto run = runBunraku(arguments);
        INFO(name << ": " << run.err);
        REQUIRE(run.exitCode == 0);
        const nlohmann::json gltf = glbJson(arguments.back());
        CHECK(gltf["meshes"].size() == 2); // the figure and the kimono
        CHECK(kimonoKeys(gltf) > 1);
        if (name == "convert" || name == "design") CHECK(kimonoKeys(gltf) == frames);
    }
    // Without --kimono: the figure alone.
    REQUIRE(runBunraku({"convert", take.string(), "-o", (dir / "plain.glb").string()}).exitCode == 0);
    CHECK(glbJson(dir / "plain.glb")["meshes"].size() == 1);
    CHECK(kimonoKeys(glbJson(dir / "plain.glb")) == 0);

    // Outputs that cannot hold the kimono are refused before any work, naming the file.
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"design", take.string(), "--kimono", "-o", (dir / "designed.bvh").string()},
          std::vector<std::string>{"normalise", demo.string(), "--function", "greeting", "--emotion", "hostile", "--kimono", "-o",
                                   (dir / "folder").string()}}) {
        const auto run = runBunraku(command);
        INFO(command.front() << ": " << run.err);
        CHECK(run.exitCode != 0);
        CHECK(run.err.find("--kimono writes the simulated cloth into") != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(dir / "designed.bvh"));
    CHECK_FALSE(std::filesystem::exists(dir / "folder"));
}
