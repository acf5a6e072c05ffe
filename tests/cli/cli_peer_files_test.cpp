// One writer per file (issue 28): `bunraku decompose` and `bunraku normalise` write the files of
// their stages with the writers of `bunraku analyse` (analysis/report/analysis_files.h), so the
// three give the same bytes for every file they share, on the demo corpus and on real takes.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

using bunraku::test::readTextFile;
using bunraku::test::runBunraku;
namespace fs = std::filesystem;

namespace {

void run(const std::vector<std::string>& arguments)
{
    const auto result = runBunraku(arguments);
    INFO(arguments.front() << ": " << result.err);
    REQUIRE(result.exitCode == 0);
}

std::set<std::string> fileNames(const fs::path& folder)
{
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().filename().string().front() != '.') names.insert(entry.path().filename().string());
    return names;
}

/// Analyses, decomposes and normalises (one cell) `corpus` with every command's defaults and
/// compares what they share byte for byte. Returns the names of the files compared.
std::set<std::string> requireSameFiles(const fs::path& dir, const fs::path& corpus, const std::string& function, const std::string& emotion)
{
    const fs::path analysed = dir / "analysed", decomposed = dir / "decomposed", normalised = dir / "normalised";
    run({"analyse", corpus.string(), "-o", analysed.string()});
    run({"decompose", corpus.string(), "-o", decomposed.string()});
    run({"normalise", corpus.string(), "--function", function, "--emotion", emotion, "-o", normalised.string()});
    const std::set<std::string> analyseFiles = fileNames(analysed);
    std::set<std::string> compared;
    for (const std::string& name : fileNames(decomposed)) {
        if (name == "summary.json" || !analyseFiles.count(name)) continue; // each command's own summary
        INFO(name);
        CHECK(readTextFile(decomposed / name) == readTextFile(analysed / name));
        compared.insert(name);
    }
    // normalise's names for the same tables: K_correspondence.csv, K_normalised.csv, variance.csv
    // and reference.csv against correspondence_K.csv, normalised_K.csv, variance_F_E.csv and
    // reference_F_E.csv (K = F_E_k).
    const std::string cell = function + "_" + emotion;
    int takes = 0;
    for (const std::string& name : fileNames(normalised)) {
        const auto suffix = [&](const std::string& end) {
            return name.size() > end.size() && name.compare(name.size() - end.size(), end.size(), end) == 0;
        };
        std::string peer;
        if (suffix("_correspondence.csv")) peer = "correspondence_" + name.substr(0, name.size() - 19) + ".csv";
        else if (suffix("_normalised.csv")) peer = "normalised_" + name.substr(0, name.size() - 15) + ".csv";
        else if (name == "variance.csv") peer = "variance_" + cell + ".csv";
        else if (name == "reference.csv") peer = "reference_" + cell + ".csv";
        else continue;
        INFO(name << " against " << peer);
        REQUIRE(analyseFiles.count(peer));
        CHECK(readTextFile(normalised / name) == readTextFile(analysed / peer));
        compared.insert("normalise:" + name);
        takes += suffix("_normalised.csv") ? 1 : 0;
    }
    CHECK(takes >= 3);
    CHECK(compared.count("normalise:variance.csv"));
    return compared;
}

/// The files `decompose` and `analyse` both write for a corpus of these functions and cells.
void requireDecompositionCompared(const std::set<std::string>& compared, const std::vector<std::string>& functions,
                                  const std::vector<std::string>& cells)
{
    for (const char* name : {"km2o_by_M.csv", "km2o_errors.csv", "spectra.csv", "arma_table.csv"}) CHECK(compared.count(name));
    for (const auto& function : functions) CHECK(compared.count("y_" + function + ".csv"));
    for (const auto& cell : cells) CHECK(compared.count("z_" + cell + ".csv"));
}

} // namespace

TEST_CASE("decompose, normalise and analyse write the same bytes for every file they share on the demo corpus", "[cli][peer]")
{
    const auto dir = bunraku::test::scratchDir("cli-peer-demo");
    run({"demo", "-o", (dir / "demo").string()});
    const auto compared = requireSameFiles(dir, dir / "demo", "greeting", "hostile");
    requireDecompositionCompared(compared, {"greeting", "serving-tea"},
                                 {"greeting_friendly", "greeting_hostile", "greeting_none", "serving-tea_friendly",
                                  "serving-tea_hostile", "serving-tea_none"});
}

TEST_CASE("decompose, normalise and analyse write the same bytes for every file they share on the Bandai waves", "[cli][peer][bandai]")
{
    std::vector<std::string> files;
    for (const std::string style : {"normal", "active", "exhausted"})
        for (int k = 1; k <= 5; ++k)
            files.push_back((bunraku::test::bandaiDir() / ("wave-right-hand_" + style + "_00" + std::to_string(k) + ".bvh")).string());
    bool present = true;
    for (const auto& file : files) present = present && fs::exists(file);
    if (!bunraku::test::requireBandaiData(present)) return;
    const auto dir = bunraku::test::scratchDir("cli-peer-bandai");
    std::vector<std::string> corpus{"corpus"};
    corpus.insert(corpus.end(), files.begin(), files.end());
    corpus.insert(corpus.end(), {"-o", (dir / "waves").string(), "--pattern", "{function}_{emotion}_{take}"});
    run(corpus);
    const auto compared = requireSameFiles(dir, dir / "waves", "wave-right-hand", "active");
    requireDecompositionCompared(compared, {"wave-right-hand"},
                                 {"wave-right-hand_normal", "wave-right-hand_active", "wave-right-hand_exhausted"});
}

TEST_CASE("decompose --method takes the parameter files' name least-squares and the short ls alike", "[cli][peer]")
{
    const auto dir = bunraku::test::scratchDir("cli-peer-method-names");
    run({"demo", "-o", (dir / "demo").string()});
    run({"decompose", (dir / "demo").string(), "--method", "least-squares", "-o", (dir / "long").string()});
    run({"decompose", (dir / "demo").string(), "--method", "ls", "-o", (dir / "short").string()});
    for (const char* name : {"y_greeting.csv", "z_greeting_hostile.csv", "arma_table.csv"}) {
        INFO(name);
        CHECK(readTextFile(dir / "long" / name) == readTextFile(dir / "short" / name));
        CHECK_FALSE(readTextFile(dir / "long" / name).empty());
    }
    CHECK_FALSE(fs::exists(dir / "long" / "km2o_by_M.csv")); // least squares: no KM2O table
}

TEST_CASE("phase spells the approximation weight as normalise and the parameter files do, its old --weight kept", "[cli][peer]")
{
    const auto normal = bunraku::test::bandaiDir() / "bye_normal_001.bvh";
    const auto angry = bunraku::test::bandaiDir() / "bye_angry_001.bvh";
    if (!bunraku::test::requireBandaiData(fs::exists(normal) && fs::exists(angry))) return;
    const auto dir = bunraku::test::scratchDir("cli-peer-phase-names");
    const auto phase = [&](const std::string& option, const std::string& value, const fs::path& out) {
        run({"phase", "--reference", normal.string(), "--sample", angry.string(), option, value, "-o", out.string()});
        return readTextFile(out);
    };
    const std::string spelled = phase("--approximation-weight", "2", dir / "spelled.csv");
    CHECK(phase("--weight", "2", dir / "old.csv") == spelled);
    CHECK(phase("--approximation-weight", "8", dir / "default.csv") != spelled); // the option is read
    const auto help = runBunraku({"phase", "--help"});
    CHECK(help.out.find("--approximation-weight") != std::string::npos);
    CHECK(help.out.find("  --weight ") == std::string::npos); // the old name is not offered (--weighting is another)
}
