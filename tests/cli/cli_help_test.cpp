// `bunraku help SUBCOMMAND` and `bunraku --version`, run as a user would.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/test_paths.h"

#include "app/build_info.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/pipeline/stage_parameters.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

using bunraku::test::runBunraku;

namespace {

/// The subcommands a help text lists under "Subcommands:".
std::vector<std::string> listedSubcommands(const std::string& help)
{
    std::vector<std::string> names;
    const auto start = help.find("Subcommands:");
    if (start == std::string::npos) return names;
    const std::string tail = help.substr(start);
    static const std::regex listed(R"(\n  ([a-z][a-z0-9-]*)( |\n|$))");
    for (std::sregex_iterator it(tail.begin(), tail.end(), listed), end; it != end; ++it) names.push_back((*it)[1].str());
    return names;
}

} // namespace

TEST_CASE("bunraku help SUBCOMMAND prints what SUBCOMMAND --help prints, for every subcommand", "[cli][help]")
{
    const auto root = runBunraku({"--help"});
    REQUIRE(root.exitCode == 0);
    CHECK(runBunraku({"help"}).out == root.out);
    const auto names = listedSubcommands(root.out);
    REQUIRE(std::find(names.begin(), names.end(), "help") != names.end());
    REQUIRE(names.size() >= 10);
    int compared = 0;
    for (const std::string& name : names) {
        if (name == "help") continue;
        const auto direct = runBunraku({name, "--help"});
        const auto help = runBunraku({"help", name});
        INFO(name << "\n" << help.err);
        CHECK(help.exitCode == 0);
        CHECK(help.out == direct.out);
        ++compared;
        for (const std::string& child : listedSubcommands(direct.out)) {
            const auto nested = runBunraku({"help", name, child});
            INFO(name << " " << child);
            CHECK(nested.exitCode == 0);
            CHECK(nested.out == runBunraku({name, child, "--help"}).out);
            ++compared;
        }
    }
    CHECK(compared >= 16);
}

TEST_CASE("every numeric option of the analysis states its range in --help: the analysis's own limits, enforced", "[cli][help][limits]")
{
    namespace pl = bunraku::analysis::pipeline;
    struct Option {
        std::vector<std::string> command;
        std::string option;
        std::string range; ///< as --help states it
        std::string beyond; ///< a value just past the range
    };
    const auto in = [](auto low, auto high) {
        std::ostringstream text;
        text << "in [" << low << " - " << high << "]";
        return text.str();
    };
    // An existing folder for the commands whose corpus must exist (the option is refused first).
    const std::string folder = bunraku::test::scratchDir("cli-help-ranges").string();
    const std::vector<Option> options = {
        {{"normalise"}, "--tau", in(0, pl::kMaxTau), std::to_string(pl::kMaxTau + 1)},
        {{"normalise"}, "--tcmp", in(0, pl::kMaxSearchBand), std::to_string(pl::kMaxSearchBand + 1)},
        {{"phase"}, "--tau", in(0, pl::kMaxTau), std::to_string(pl::kMaxTau + 1)},
        {{"phase"}, "--tcmp", in(0, pl::kMaxSearchBand), std::to_string(pl::kMaxSearchBand + 1)},
        {{"phase"}, "--max-scale", in(1, pl::kMaxScale), std::to_string(pl::kMaxScale + 1)},
        {{"experiment", "approximation"}, "--max-scale", in(1, pl::kMaxScale), std::to_string(pl::kMaxScale + 1)},
        {{"phase"}, "--control-spacing", in(1, pl::kMaxControlSpacing), std::to_string(pl::kMaxControlSpacing + 1)},
        {{"decompose"}, "--M", in(0, pl::kMaxCorrelationLength), std::to_string(pl::kMaxCorrelationLength + 1)},
        {{"decompose"}, "--arma-max-order", in(0, pl::kMaxArmaOrder), std::to_string(pl::kMaxArmaOrder + 1)},
        {{"emotion"}, "--weight", in(bunraku::analysis::kMinEmotionWeight, bunraku::analysis::kMaxEmotionWeight), "3.5"},
    };
    // The matcher's own limit: T_cmp 20000 used to pass the options and fail in the analysis.
    CHECK(pl::kMaxSearchBand == 16000);
    for (const Option& option : options) {
        std::vector<std::string> help = option.command;
        help.push_back("--help");
        const auto run = runBunraku(help);
        REQUIRE(run.exitCode == 0);
        std::istringstream lines(run.out);
        std::string line, found;
        while (std::getline(lines, line))
            if (line.find("  " + option.option + " ") != std::string::npos) found = line;
        INFO(option.command.front() << " " << option.option << ": " << found);
        CHECK(found.find(option.range) != std::string::npos);
        // A value past the range is refused by the option, naming it, before any work.
        std::vector<std::string> beyond = option.command;
        const std::string corpus = option.command.front() == "normalise" ? folder : std::string("demo");
        for (const std::string& word : {corpus, option.option, option.beyond}) beyond.push_back(word);
        const auto refused = runBunraku(beyond);
        INFO(refused.err);
        CHECK(refused.exitCode == 2);
        CHECK(refused.err.find(option.option) != std::string::npos);
    }
}

TEST_CASE("bunraku help with an unknown subcommand names the ones there are", "[cli][help]")
{
    const auto run = runBunraku({"help", "normalize"});
    CHECK(run.exitCode == 2); // a usage error
    CHECK(run.out.empty());
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK(run.err.rfind("bunraku: error: 'bunraku' has no subcommand 'normalize' (expected one of: ", 0) == 0);
    CHECK(run.err.find("normalise") != std::string::npos);

    const auto nested = runBunraku({"help", "experiment", "nope"});
    CHECK(nested.exitCode == 2);
    CHECK(nested.err.find("'bunraku experiment' has no subcommand 'nope' (expected one of: noise, truth, km2o, design, approximation, kimono)")
          != std::string::npos);
    CHECK(runBunraku({"help", "demo", "extra"}).exitCode == 2);
}

TEST_CASE("bunraku --version names the version, the commit and the licence", "[cli][help]")
{
    const auto run = runBunraku({"--version"});
    REQUIRE(run.exitCode == 0);
    CHECK(run.out.rfind("bunraku " BUNRAKU_TEST_PROJECT_VERSION "\ncommit " + std::string(bunraku::app::buildCommit()), 0) == 0);
    CHECK(std::regex_search(run.out, std::regex("\ncommit [0-9a-f]{12}(-dirty)? \\(\\d{4}-\\d{2}-\\d{2}\\)\n")));
    CHECK(run.out.find("License GPL-3.0-or-later") != std::string::npos);
}

TEST_CASE("exit codes: 0 done, 1 bad input, 2 usage, 3 I/O, as bunraku --help says", "[cli][help]")
{
    const auto help = runBunraku({"--help"});
    CHECK(help.exitCode == 0);
    CHECK(help.out.find("Exit status: 0 done; 1 bad input") != std::string::npos);
    CHECK(help.out.find("2 bad command line") != std::string::npos);
    CHECK(help.out.find("3 a file could not be read or written") != std::string::npos);

    const auto dir = bunraku::test::scratchDir("cli_exit_codes");
    CHECK(runBunraku({"analyse"}).exitCode == 2);                                  // CORPUS and -o missing
    CHECK(runBunraku({"analyse", "demo", "-o", (dir / "a").string(), "--threads", "-1"}).exitCode == 2); // out of range
    CHECK(runBunraku({"frobnicate"}).exitCode == 2);
    // Bad input: a corpus folder without corpus.json.
    std::filesystem::create_directories(dir / "empty");
    const auto bad = runBunraku({"analyse", (dir / "empty").string(), "-o", (dir / "b").string()});
    CHECK(bad.exitCode == 1);
    CHECK(bad.err.rfind("bunraku: error: ", 0) == 0);
    // I/O: the output's parent is a file, so nothing can be written there.
    bunraku::test::writeText(dir / "file", "x");
    const auto io = runBunraku({"demo", "-o", (dir / "file" / "demo").string()});
    INFO(io.err);
    CHECK(io.exitCode == 3);
    CHECK(io.err.rfind("bunraku: error: ", 0) == 0);
}

TEST_CASE("every subcommand that does work offers a --json summary for batch jobs", "[cli][help]")
{
    const auto root = runBunraku({"--help"});
    REQUIRE(root.exitCode == 0);
    std::vector<std::string> commands;
    for (const auto& name : listedSubcommands(root.out)) {
        if (name == "help") continue;
        const auto help = runBunraku({name, "--help"});
        REQUIRE(help.exitCode == 0);
        const auto nested = listedSubcommands(help.out);
        if (nested.empty()) commands.push_back(name);
        for (const auto& inner : nested) commands.push_back(name + " " + inner);
    }
    REQUIRE(commands.size() >= 18);

    // Each one run with --json on the demo corpus (and what the earlier ones wrote): standard
    // output is JSON (`analyse`: one JSON document per line, progress then the summary).
    const auto dir = bunraku::test::scratchDir("cli-json-every-command");
    const auto s = [&](const std::string& name) { return (dir / name).string(); };
    const std::string demo = s("demo"), take = s("demo") + "/greeting_hostile_1.csv", neutral = s("demo") + "/greeting_none_1.csv";
    const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
        {"demo", {"demo", "-o", demo}},
        {"info", {"info", demo}},
        {"convert", {"convert", take, "-o", s("converted.bvh")}},
        {"preprocess", {"preprocess", demo, "-o", s("preprocessed")}},
        {"corpus", {"corpus", take, neutral, "-o", s("two")}},
        {"normalise", {"normalise", demo, "--function", "greeting", "--emotion", "hostile", "-o", s("normalised")}},
        {"decompose", {"decompose", demo, "-o", s("decomposed")}},
        {"emotion", {"emotion", demo, "--function", "greeting", "--emotion", "hostile", "--weight", "2", "-o", s("weighted.csv")}},
        {"axis", {"axis", take, "-o", s("axis.csv")}},
        {"phase", {"phase", "--reference", neutral, "--sample", take, "-o", s("warp.csv")}},
        {"gains", {"gains", "--reference", neutral, "--sample", take, "--warp", s("warp.csv"), "-o", s("gains.json")}},
        {"design", {"design", neutral, "--warp", s("warp.csv"), "--gains", s("gains.json"), "-o", s("designed.csv")}},
        {"analyse", {"analyse", "demo", "-o", s("analysis")}},
        {"summary", {"summary", s("analysis"), "--table", s("summary.csv")}},
        {"render", {"render", take, "--size", "160x90", "-o", s("frame.png")}},
        {"experiment noise", {"experiment", "noise"}},
        {"experiment truth", {"experiment", "truth", demo}},
        {"experiment km2o", {"experiment", "km2o", "--seeds", "1", "--M", "3:4"}},
        {"experiment design", {"experiment", "design", demo}},
        {"experiment approximation", {"experiment", "approximation", "demo", "--max-scale", "4"}},
        {"experiment kimono", {"experiment", "kimono", s("two")}},
    };
    std::set<std::string> run;
    for (auto [name, arguments] : runs) {
        INFO(name);
        run.insert(name);
        arguments.push_back("--json");
        const auto result = runBunraku(arguments);
        INFO(result.err);
        REQUIRE(result.exitCode == 0);
        std::vector<std::string> documents{result.out};
        if (name == "analyse") {
            documents.clear();
            std::istringstream lines(result.out);
            for (std::string line; std::getline(lines, line);) documents.push_back(line);
            REQUIRE(documents.size() >= 2);
        }
        for (const auto& document : documents) {
            INFO(document.substr(0, 300));
            nlohmann::json parsed;
            REQUIRE_NOTHROW(parsed = nlohmann::json::parse(document));
            CHECK(parsed.is_object());
            CHECK_FALSE(parsed.empty());
        }
    }
    // A subcommand added later without a --json run here fails this test.
    for (const auto& command : commands) {
        INFO(command << " has no --json run in this test");
        CHECK(run.count(command) == 1);
    }
}

TEST_CASE("an option bound to a parameter refuses what the parameter files refuse with their message", "[cli][help][limits]")
{
    namespace pl = bunraku::analysis::pipeline;
    struct Bound {
        std::vector<std::string> words; ///< the command and what it needs before the option is checked
        std::string option;
        std::string path; ///< the parameter in the files ("normalise.tau")
        std::string value;
    };
    const std::string folder = bunraku::test::scratchDir("cli-parameter-ranges").string();
    const std::vector<Bound> bound = {
        {{"normalise", folder}, "--tau", "normalise.tau", "201"},
        {{"normalise", folder}, "--tcmp", "normalise.searchBand", "16001"},
        {{"normalise", folder}, "--approximation-weight", "normalise.approximationWeight", "2e6"},
        {{"normalise", folder}, "--exclude", "normalise.averageExcluded", "0"},
        {{"normalise", folder}, "--base", "normalise.averageBase", "1000001"},
        {{"normalise", folder}, "--tau", "normalise.tau", "abc"},
        {{"phase"}, "--tau", "axis.tau", "2.5"},
        {{"phase"}, "--tcmp", "axis.searchBand", "16001"},
        {{"phase"}, "--max-scale", "axis.maxScale", "0"},
        {{"experiment", "approximation", "demo"}, "--max-scale", "axis.maxScale", "257"},
        {{"phase"}, "--control-spacing", "axis.controlSpacing", "0"},
        {{"phase"}, "--spacing", "axis.massSpacing", "0.25"},
        {{"phase"}, "--approximation-weight", "axis.approximationWeight", "2e6"},
        {{"decompose", "demo"}, "--M", "decompose.M", "1001"},
        {{"decompose", "demo"}, "--arma-table", "fluctuations.armaP", "5"},
        {{"emotion", "demo"}, "--weight", "design.emotionWeight", "3.5"},
        {{"preprocess", folder}, "--reference-take", "preprocess.referenceTake", "1000001"},
        // Just past the limit: the message names the value as given, not rounded to the limit.
        {{"normalise", folder}, "--tau", "normalise.tau", "200.0000001"},
        {{"emotion", "demo"}, "--weight", "design.emotionWeight", "3.0000001"},
        // Text the files would not read as a number either.
        {{"normalise", folder}, "--tau", "normalise.tau", "0x10"},
        {{"emotion", "demo"}, "--weight", "design.emotionWeight", "0x1"},
    };
    for (const Bound& b : bound) {
        // The parameter files' reader, the peer: the same value at the same path.
        const auto dot = b.path.find('.');
        const nlohmann::json number = nlohmann::json::parse(b.value, nullptr, false);
        nlohmann::json value = number.is_number() ? number : nlohmann::json(b.value);
        if (b.path == "normalise.averageExcluded") value = nlohmann::json::array({value});
        const nlohmann::json file = {{b.path.substr(0, dot), {{b.path.substr(dot + 1), value}}}};
        const auto read = pl::chainParametersFromJson(file, "file");
        REQUIRE_FALSE(read.ok());
        const std::string message = read.error().message.substr(read.error().message.rfind(": expected") + 2);
        std::vector<std::string> words = b.words;
        words.push_back(b.option);
        words.push_back(b.value);
        if (b.option == "--arma-table") words.push_back("0");
        const auto run = runBunraku(words);
        INFO(b.words.front() << " " << b.option << " " << b.value << ": " << run.err << "\nthe files: " << read.error().message);
        CHECK(run.exitCode == 2);
        CHECK(run.err.find(b.option + ": " + message) != std::string::npos);
    }
    // What the files read as an integer in range ("1e2") the option takes too, as the same value.
    const auto accepted = runBunraku({"normalise", folder, "--tau", "1e2", "--function", "f", "--emotion", "e", "-o",
                                      folder + "/out"});
    INFO(accepted.err);
    CHECK(accepted.err.find("--tau") == std::string::npos);
    CHECK(accepted.err.find("corpus.json: no such file") != std::string::npos); // past the options, at the corpus
    // Every entry of the table is a parameter the files read, with the range they check.
    for (const pl::ParameterRange& range : pl::parameterRanges()) {
        const std::string path(range.path);
        const auto dot = path.find('.');
        nlohmann::json past = range.high + 1.0;
        if (path == "normalise.averageExcluded") past = nlohmann::json::array({past});
        const auto read = pl::chainParametersFromJson({{path.substr(0, dot), {{path.substr(dot + 1), past}}}}, "file");
        INFO(path);
        REQUIRE_FALSE(read.ok());
        CHECK(read.error().message.find(range.expected()) != std::string::npos);
    }
}
