// workflows/Snakefile run by Debian's snakemake on a subset of the shared Bandai files (two
// functions: bye with one take per emotion, wave-right-hand with two; the default chain, KM2O,
// not estimable on bye and so least squares there, docs/KM2O.md): one corpus and one analysis
// per function, out/summary.csv and
// out/index.html checked against the per-corpus summary.json files; a second run has nothing to
// do, and a deleted table is rebuilt alone, the same.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/peer.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;
using Catch::Matchers::Contains;

namespace {

struct Shell {
    int exitCode = -1;
    std::string log;
};

/// Runs `command` through the shell with its output in `log`, killed after 10 minutes.
Shell runShell(const std::string& command, const fs::path& log)
{
    const int status = std::system(("timeout -k 5 600 " + command + " >'" + log.string() + "' 2>&1 </dev/null").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, bunraku::test::readTextFile(log)};
}

std::vector<std::string> splitLines(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

std::vector<std::string> splitFields(const std::string& line)
{
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

} // namespace

TEST_CASE("the Snakemake workflow analyses a folder of Bandai takes corpus by corpus", "[cli][workflow]")
{
    const bool snakemake = std::system("snakemake --version >/dev/null 2>&1") == 0;
    if (!bunraku::test::requirePeer(snakemake, "snakemake", "apt-get install snakemake (scripts/install-deps.sh)")) return;
    const std::map<std::string, std::vector<std::string>> subset{
        {"bye", {"bye_normal_001", "bye_happy_001", "bye_angry_001"}},
        {"wave-right-hand",
         {"wave-right-hand_normal_001", "wave-right-hand_normal_002", "wave-right-hand_active_001", "wave-right-hand_active_002",
          "wave-right-hand_exhausted_001", "wave-right-hand_exhausted_002"}}};
    bool data = true;
    for (const auto& [function, stems] : subset)
        for (const auto& stem : stems) data = data && fs::is_regular_file(bunraku::test::bandaiDir() / (stem + ".bvh"));
    if (!bunraku::test::requirePeer(data, "the shared Bandai files in " + bunraku::test::bandaiDir().string(),
                                    "see /work/shared/data/bandai/README.md"))
        return;

    // The subset as a folder of links to the shared files (never copied).
    const fs::path dir = bunraku::test::scratchDir("cli_workflow");
    const fs::path in = dir / "in";
    const fs::path out = dir / "out";
    fs::create_directories(in);
    for (const auto& [function, stems] : subset)
        for (const auto& stem : stems) fs::create_symlink(bunraku::test::bandaiDir() / (stem + ".bvh"), in / (stem + ".bvh"));
    const std::string command = "snakemake -s '" + (bunraku::test::sourceDir() / "workflows" / "Snakefile").string() + "' --directory '" +
                                dir.string() + "' --cores 2 --config 'input=" + in.string() + "' 'out=" + out.string() +
                                "' 'pattern={function}_{emotion}_{take}' 'bunraku=" + bunraku::test::bunrakuPath() + "'";
    const Shell first = runShell(command, dir / "first.log");
    INFO(first.log);
    REQUIRE(first.exitCode == 0);

    // The table: one row per function, in name order, each the figures of that corpus's analysis.
    const std::string table = bunraku::test::readTextFile(out / "summary.csv");
    const auto lines = splitLines(table);
    REQUIRE(lines.size() == 1 + subset.size());
    CHECK(lines[0] == "corpus,takes,cells,frames,channels,method,M,mean_P_percent,mean_design_relative_error,report");
    const std::string index = bunraku::test::readTextFile(out / "index.html");
    std::size_t row = 1;
    for (const auto& [function, stems] : subset) {
        CAPTURE(function);
        const json summary = json::parse(bunraku::test::readTextFile(out / "analyses" / function / "summary.json"));
        const json corpus = json::parse(bunraku::test::readTextFile(out / "corpora" / function / "corpus.json"));
        const auto fields = splitFields(lines[row++]);
        REQUIRE(fields.size() == 10);
        CHECK(fields[0] == function);
        CHECK(summary["corpus"] == function);
        CHECK(std::stoul(fields[1]) == stems.size());
        CHECK(summary["takes"].get<std::size_t>() == stems.size());
        CHECK(corpus["takes"].size() == stems.size());
        CHECK(std::stoul(fields[2]) == summary["cells"].size());
        CHECK(summary["cells"].size() == 3); // normal and two emotions
        CHECK(std::stoul(fields[3]) == summary["frames"].get<std::size_t>());
        CHECK(std::stoul(fields[4]) == summary["channels"].get<std::size_t>());
        CHECK(summary["decomposition"]["method"] == "km2o");
        if (function == "bye") {
            // One take per cell: KM2O not estimable, the least-squares components (docs/KM2O.md).
            CHECK(fields[5] == "least-squares (KM2O not estimable)");
            CHECK(summary["decomposition"]["km2o"]["estimable"] == false);
            CHECK(fields[6].empty()); // no KM2O M and P
            CHECK(fields[7].empty());
        } else {
            CHECK(fields[5] == "km2o");
            CHECK(summary["decomposition"]["km2o"]["estimable"] == true);
            CHECK(summary["decomposition"]["km2o"]["notes"].empty()); // two takes in every cell
            CHECK(std::stoi(fields[6]) == summary["decomposition"]["M"].get<int>());
            CHECK(std::stoi(fields[6]) >= 1);
            CHECK(std::stod(fields[7]) == summary["decomposition"]["mean_P_percent"].get<double>());
        }
        double designError = 0.0;
        for (const auto& axis : summary["axes"]) designError += axis["design_relative_error"].get<double>();
        REQUIRE(summary["axes"].size() == 2);
        CHECK(std::stod(fields[8]) == designError / 2.0);
        const std::string report = "analyses/" + function + "/report.html";
        CHECK(fields[9] == report);
        CHECK(fs::is_regular_file(out / report));
        CHECK_THAT(index, Contains("<a href=\"" + report + "\">" + function + "</a>"));
    }

    // Restartable: nothing to do again; a lost table is rebuilt alone, byte for byte.
    const Shell again = runShell(command, dir / "again.log");
    INFO(again.log);
    CHECK(again.exitCode == 0);
    CHECK_THAT(again.log, Contains("Nothing to be done"));
    fs::remove(out / "summary.csv");
    const Shell rebuilt = runShell(command, dir / "rebuilt.log");
    INFO(rebuilt.log);
    CHECK(rebuilt.exitCode == 0);
    CHECK_THAT(rebuilt.log, Contains("rule summary:"));
    CHECK_THAT(rebuilt.log, !Contains("rule analyse:"));
    CHECK(bunraku::test::readTextFile(out / "summary.csv") == table);
}
