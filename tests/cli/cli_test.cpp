#include "tests/cli/cli_runner.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

using bunraku::test::runBunraku;
using nlohmann::json;

namespace {

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

} // namespace

TEST_CASE("bunraku demo writes the thesis-shaped corpus and info reports it", "[cli]")
{
    const auto dir = bunraku::test::scratchDir("cli-demo") / "corpus";
    const auto demo = runBunraku({"demo", "-o", dir.string(), "--seed", "7", "--json"});
    INFO(demo.err);
    REQUIRE(demo.exitCode == 0);
    const auto summary = json::parse(demo.out);
    CHECK(summary.at("takes") == 30);

    const auto info = runBunraku({"info", dir.string(), "--json"});
    INFO(info.err);
    REQUIRE(info.exitCode == 0);
    const auto report = json::parse(info.out);
    CHECK(report.at("takes") == 30);
    CHECK(report.at("channels") == 24);
    CHECK(report.at("frames") == 106);
    CHECK(report.at("rate_hz").get<double>() == Approx(5.0));
}

TEST_CASE("every subcommand answers --help", "[cli]")
{
    const std::vector<std::vector<std::string>> commands = {
        {"demo"}, {"info"}, {"convert"}, {"preprocess"}, {"normalise"}, {"decompose"}, {"emotion"},
        {"axis"}, {"phase"}, {"gains"}, {"design"}, {"render"}, {"experiment", "noise"},
        {"experiment", "truth"}, {"experiment", "km2o"}, {"experiment", "design"}, {"experiment", "approximation"}};
    for (auto command : commands) {
        command.push_back("--help");
        const auto run = runBunraku(command);
        INFO(command.front() << " " << command[1]);
        CHECK(run.exitCode == 0);
        CHECK(run.out.find("Usage") != std::string::npos);
    }
}

TEST_CASE("bad input gives a one-line error and a non-zero exit", "[cli]")
{
    const auto missing = runBunraku({"info", "/nonexistent/corpus-folder", "--json"});
    CHECK(missing.exitCode != 0);
    CHECK(lineCount(missing.err) == 1);
    CHECK(missing.err.rfind("bunraku: error:", 0) == 0);
    CHECK(missing.err.find("/nonexistent/corpus-folder") != std::string::npos);

    const auto unknown = runBunraku({"no-such-command"});
    CHECK(unknown.exitCode != 0);
    CHECK(unknown.err.rfind("bunraku: error:", 0) == 0);
}
