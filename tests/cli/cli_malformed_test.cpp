// Malformed inputs through the real executable: every one must give exactly one error line that
// names the file (and the line where there is one), a non-zero exit, and never a crash or hang.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/bvh_fixtures.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

using bunraku::test::isOneLineError;
using bunraku::test::runBunraku;
using bunraku::test::writeText;

namespace {

const std::string kBvh = "HIERARCHY\n"
                         "ROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                         "  JOINT Chest\n  {\n    OFFSET 0 10 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                         "    End Site\n    {\n      OFFSET 0 5 0\n    }\n  }\n}\n"
                         "MOTION\nFrames: 2\nFrame Time: 0.2\n"
                         "0 0 0 0 0 0 0 0 0\n"
                         "1 2 3 10 20 30 5 6 7\n";

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

struct BadInput {
    std::string name;     ///< file name in the scratch folder
    std::string content;
    std::string location; ///< must appear in the message, e.g. "name.bvh:20"
};

} // namespace

TEST_CASE("bunraku info and convert reject malformed take files with one line naming file and line", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-malformed");
    std::string junk;
    for (int i = 0; i < 3000; ++i) junk += char((i * 7919 + 13) % 256);
    const std::vector<BadInput> inputs = {
        {"truncated.bvh", kBvh.substr(0, 200), "truncated.bvh:"},
        {"wrong-count.bvh", replaced(kBvh, "1 2 3 10 20 30 5 6 7", "1 2 3 10 20 30 5 6"), "wrong-count.bvh:20"},
        {"huge-frames.bvh", replaced(kBvh, "Frames: 2", "Frames: 2000000000"), "huge-frames.bvh:17"},
        {"overflow-frames.bvh", replaced(kBvh, "Frames: 2", "Frames: 99999999999999999999999"), "overflow-frames.bvh:17"},
        {"nan.bvh", replaced(kBvh, "1 2 3 10", "1 2 3 nan"), "nan.bvh:20"},
        {"seven-channels.bvh", replaced(kBvh, "CHANNELS 3", "CHANNELS 7"), "seven-channels.bvh:9"},
        {"empty.bvh", "", "empty.bvh"},
        {"junk.bvh", junk, "junk.bvh:1"},
        {"backwards.csv", "time_s,head.x,head.y\n0,1,2\n0.2,1,2\n0.1,1,2\n", "backwards.csv:4"},
        {"nan.csv", "time_s,head.x,head.y\n0,1,2\n0.2,NaN,2\n", "nan.csv:3"},
        {"short-row.csv", "time_s,head.x,head.y\n0,1,2\n0.2,1\n", "short-row.csv:3"},
        {"empty.csv", "", "empty.csv"},
        {"junk.csv", junk, "junk.csv:"},
        {"nan.txt", "1 1 2 3 4 5 nan\n", "nan.txt:1"},
        // lengths beyond +-1e7 cm and angles beyond +-1e9 deg (docs/FORMATS.md, Value limits)
        {"offset-1e308.bvh", replaced(kBvh, "OFFSET 0 10 0", "OFFSET 0 1e308 0"), "offset-1e308.bvh:8"},
        {"position-1e308.bvh", replaced(kBvh, "1 2 3 10 20 30", "1e308 2 3 10 20 30"), "position-1e308.bvh:20"},
        {"angle-minus-1e308.bvh", replaced(kBvh, "1 2 3 10 20 30", "1 2 3 -1e308 20 30"), "angle-minus-1e308.bvh:20"},
        {"angle-1e12.bvh", replaced(kBvh, "1 2 3 10 20 30 5", "1 2 3 10 20 30 1e12"), "angle-1e12.bvh:20"},
        {"angle-1e9-plus-1.bvh", replaced(kBvh, "1 2 3 10 20 30", "1 2 3 10 1000000001 30"), "angle-1e9-plus-1.bvh:20"},
    };
    for (const auto& input : inputs) {
        const auto file = writeText(dir / input.name, input.content);
        for (const std::vector<std::string>& command :
             {std::vector<std::string>{"info", file.string(), "--json"},
              std::vector<std::string>{"convert", file.string(), "-o", (dir / "out.csv").string()}}) {
            const auto run = runBunraku(command);
            INFO(command.front() << " " << input.name << ": " << run.err);
            CHECK(isOneLineError(run.exitCode, run.err));
            CHECK(run.err.find(input.location) != std::string::npos);
        }
    }
    CHECK_FALSE(std::filesystem::exists(dir / "out.csv")); // nothing written on failure
}

TEST_CASE("corpus commands reject a manifest pointing to missing or inconsistent take files", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-malformed-corpus");
    const auto corpus = dir / "corpus";
    REQUIRE(runBunraku({"demo", "-o", corpus.string()}).exitCode == 0);
    const auto manifestFile = corpus / "corpus.json";
    const auto manifest = nlohmann::json::parse(bunraku::test::readTextFile(manifestFile));
    const std::string firstFile = manifest["takes"][0]["file"];

    SECTION("a missing take file")
    {
        auto changed = manifest;
        changed["takes"][3]["file"] = "no-such-take.csv";
        writeText(manifestFile, changed.dump(1));
    }
    SECTION("a take with fewer frames than the manifest says")
    {
        auto text = bunraku::test::readTextFile(corpus / firstFile);
        text.erase(text.rfind('\n', text.size() - 2) + 1); // drop the last row
        writeText(corpus / firstFile, text);
    }
    SECTION("a take whose header lists other channels")
    {
        auto text = bunraku::test::readTextFile(corpus / firstFile);
        writeText(corpus / firstFile, replaced(text, "head.x", "head.q"));
    }
    SECTION("a NaN inside a take file")
    {
        auto text = bunraku::test::readTextFile(corpus / firstFile);
        const auto secondRow = text.find('\n', text.find('\n') + 1) + 1;
        text.replace(text.find(',', secondRow) + 1, 0, "nan");
        writeText(corpus / firstFile, text);
    }
    SECTION("invalid JSON")
    {
        writeText(manifestFile, "{\n  \"format\": \"bunraku-corpus\",\n  oops\n}\n");
    }
    const auto out = dir / "out";
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"info", corpus.string()},
          std::vector<std::string>{"preprocess", corpus.string(), "-o", out.string()},
          std::vector<std::string>{"decompose", corpus.string(), "--pad", "--method", "ls", "-o", out.string()},
          std::vector<std::string>{"emotion", corpus.string(), "--pad", "--function", "greeting", "--emotion", "friendly", "--weight",
                                   "1", "-o", (dir / "e.csv").string()}}) {
        const auto run = runBunraku(command);
        INFO(command.front() << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK(run.err.find(corpus.string()) != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(out));
    CHECK_FALSE(std::filesystem::exists(dir / "e.csv"));
}

TEST_CASE("a JSON input holding 1e400 or ill-formed UTF-8 is one error line naming the file and line", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-json-numbers");
    // A corpus whose takes keep their skeletons (read from BVH).
    std::filesystem::create_directories(dir / "in");
    const auto families = bunraku::test::bvhFamilies();
    for (const std::string name : {"wave_calm_1", "wave_calm_2"})
        writeText(dir / "in" / (name + ".bvh"), bunraku::test::fixtureBvh(families[4]));
    const auto corpus = dir / "c";
    REQUIRE(runBunraku({"corpus", (dir / "in").string(), "-o", corpus.string()}).exitCode == 0);
    const auto skeleton = corpus / "wave_calm_1.skeleton.json";
    const std::string original = bunraku::test::readTextFile(skeleton);
    const auto offset = original.find("\"offset\": [\n    ");
    REQUIRE(offset != std::string::npos);
    const long offsetLine = 2 + long(std::count(original.begin(), original.begin() + std::ptrdiff_t(offset), '\n'));
    const auto name = original.find("\"name\": \"");
    REQUIRE(name != std::string::npos);
    const long nameLine = 1 + long(std::count(original.begin(), original.begin() + std::ptrdiff_t(name), '\n'));
    const auto take = corpus / "wave_calm_1.csv";
    const std::vector<std::pair<std::string, std::string>> skeletons = {
        {std::string(original).insert(offset + 16, "1e400,\n    "), "wave_calm_1.skeleton.json:" + std::to_string(offsetLine)},
        {std::string(original).insert(name + 9, "\xff"), "wave_calm_1.skeleton.json:" + std::to_string(nameLine)},
    };
    for (const auto& [text, location] : skeletons) {
        writeText(skeleton, text);
        const auto run = runBunraku({"info", corpus.string()});
        INFO(run.err);
        CHECK(isOneLineError(run.exitCode, run.err)); // not an abort
        CHECK(run.err.find(location) != std::string::npos);
        CHECK(run.err.find('\xff') == std::string::npos);
    }
    writeText(skeleton, original);
    // parameters, a body description, a BVH joint map
    const auto parameters = writeText(dir / "p.json", "{\"normalise\":\n {\"tau\": 1e400}}");
    const auto body = writeText(dir / "b.json", "{\"parts\": [\n{\"x\": 1e400}]}");
    const auto map = writeText(dir / "jm.json", "{\"head\":\n \"\xff\"}");
    const std::vector<std::pair<std::vector<std::string>, std::string>> commands = {
        {{"decompose", corpus.string(), "--parameters", parameters.string(), "-o", (dir / "out").string()}, "p.json:2"},
        {{"analyse", corpus.string(), "--parameters", parameters.string(), "-o", (dir / "out").string()}, "p.json:2"},
        {{"axis", take.string(), "--body", body.string(), "-o", (dir / "a.csv").string()}, "b.json:2"},
        {{"info", (dir / "in" / "wave_calm_1.bvh").string(), "--joint-map", map.string()}, "jm.json:2"},
    };
    for (const auto& [command, location] : commands) {
        const auto run = runBunraku(command);
        INFO(command.front() << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK(run.err.find(location) != std::string::npos);
        CHECK(run.err.find("json.exception") == std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(dir / "out"));
}

TEST_CASE("parameters in their range that fail at run time name the parameters file", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-parameters-run-time");
    const auto corpus = dir / "corpus";
    REQUIRE(runBunraku({"demo", "-o", corpus.string()}).exitCode == 0);
    const std::vector<std::pair<std::string, std::string>> files = {
        {"band.json", "{\"normalise\": {\"searchBand\": 100000}}"}, // beyond the analysis's limit: refused as it is read
        {"scale.json", "{\"normalise\": {\"maxScale\": 256}}"},
        {"m.json", "{\"decompose\": {\"M\": 1000}}"},
    };
    for (const auto& [name, text] : files) {
        const auto parameters = writeText(dir / name, text);
        for (const std::string command : {"decompose", "analyse"}) {
            const auto run = runBunraku({command, corpus.string(), "--parameters", parameters.string(), "-o", (dir / "out").string()});
            INFO(command << " " << name << ": " << run.err);
            CHECK(isOneLineError(run.exitCode, run.err));
            if (name != "band.json") CHECK(run.err.find(corpus.string()) != std::string::npos);
            CHECK(run.err.find(parameters.string()) != std::string::npos);
        }
    }
    CHECK_FALSE(std::filesystem::exists(dir / "out"));
}

TEST_CASE("a 1 MB label or file name gives an error line of at most a few hundred characters", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-long-label");
    const auto corpus = dir / "corpus";
    REQUIRE(runBunraku({"demo", "-o", corpus.string()}).exitCode == 0);
    std::filesystem::remove_all(corpus / "truth");
    auto manifest = nlohmann::json::parse(bunraku::test::readTextFile(corpus / "corpus.json"));
    const std::string label(1'000'000, 'g');
    for (auto& take : manifest["takes"])
        if (take["function"] == "greeting") take["function"] = label;
    writeText(corpus / "corpus.json", manifest.dump(1));
    const std::vector<std::vector<std::string>> commands = {
        {"normalise", corpus.string(), "--function", "greeting", "--emotion", "none", "-o", (dir / "n").string()},
        {"emotion", corpus.string(), "--pad", "--method", "ls", "--function", "greeting", "--emotion", "none", "--weight", "1", "-o",
         (dir / "e.csv").string()},
        {"preprocess", corpus.string(), "-o", (dir / "p").string()}, // a take file named after the label: too long a name
    };
    for (const auto& command : commands) {
        const auto run = runBunraku(command);
        INFO(command.front() << ": " << run.err.substr(0, 400));
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK(run.err.size() < 1000);
        CHECK(run.err.find("...") != std::string::npos);
    }
}

TEST_CASE("decompose and emotion reject bad options with one line and write nothing", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-bad-options");
    const auto corpus = dir / "corpus";
    REQUIRE(runBunraku({"demo", "-o", corpus.string()}).exitCode == 0);
    const auto out = dir / "out";
    const auto badOrder = runBunraku({"decompose", corpus.string(), "--pad", "--method", "ls", "--arma-table", "-1", "2", "-o",
                                      out.string()});
    CHECK(isOneLineError(badOrder.exitCode, badOrder.err));
    CHECK(badOrder.err.find("--arma-table") != std::string::npos);
    // Values outside an option's range (the analysis's limits, stated by --help) name the option.
    for (const auto& [option, command] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"--M", {"decompose", corpus.string(), "--pad", "--method", "km2o", "--M", "-3", "-o", out.string()}},
             {"--weight", {"emotion", corpus.string(), "--pad", "--function", "greeting", "--emotion", "friendly", "--weight", "4",
                           "-o", out.string() + ".csv"}}}) {
        const auto run = runBunraku(command);
        INFO(run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK(run.err.find(option) != std::string::npos);
    }
    // The remaining errors all name the corpus folder they are about.
    const std::vector<std::vector<std::string>> commands = {
        {"decompose", corpus.string(), "--no-preprocess", "--method", "ls", "-o", out.string()}, // unequal lengths without --pad
        {"decompose", corpus.string(), "--pad", "--method", "km2o", "--M", "1000", "-o", out.string()},
        {"emotion", corpus.string(), "--pad", "--function", "greeting", "--emotion", "furious", "--weight", "1", "-o", out.string() + ".csv"},
    };
    for (const auto& command : commands) {
        const auto run = runBunraku(command);
        INFO(run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK(run.err.find(corpus.string()) != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(out));
    CHECK_FALSE(std::filesystem::exists(out.string() + ".csv"));
    // A range with trailing garbage is refused, not read as its leading number.
    for (const std::string range : {"3x:20", "3:20y", "x", "3:"}) {
        const auto run = runBunraku({"experiment", "km2o", "--T", "300", "--seeds", "1", "--M", range});
        INFO(range << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK(run.err.find("--M expects FIRST:LAST") != std::string::npos);
    }
}

TEST_CASE("decompose of a corpus too short for spectra fails before writing anything", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-one-frame");
    const auto corpus = dir / "corpus";
    REQUIRE(runBunraku({"demo", "-o", corpus.string()}).exitCode == 0);
    std::filesystem::remove_all(corpus / "truth");
    auto manifest = nlohmann::json::parse(bunraku::test::readTextFile(corpus / "corpus.json"));
    for (auto& take : manifest["takes"]) { // keep the header and the first frame of every take
        const auto file = corpus / take["file"].get<std::string>();
        const auto text = bunraku::test::readTextFile(file);
        writeText(file, text.substr(0, text.find('\n', text.find('\n') + 1) + 1));
        take["frames"] = 1;
    }
    writeText(corpus / "corpus.json", manifest.dump(1));
    const auto out = dir / "out";
    const auto run = runBunraku({"decompose", corpus.string(), "--method", "ls", "-o", out.string()});
    INFO(run.err);
    CHECK(isOneLineError(run.exitCode, run.err));
    CHECK(run.err.find(corpus.string()) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
}
