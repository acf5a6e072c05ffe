// `bunraku gains` says which phrases and axis DOF have an ill-conditioned g1 (thesis 5.4: the
// emotional first harmonic below 0.1 of the functional one), in its text and in --json
// ("ill_conditioned", beside the existing keys), and never writes a negative gain.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using bunraku::test::readNumericCsv;
using bunraku::test::readTextFile;
using bunraku::test::runBunraku;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

json runJson(const std::vector<std::string>& arguments)
{
    const auto run = runBunraku(arguments);
    INFO(arguments.front() << ": " << run.err);
    REQUIRE(run.exitCode == 0);
    return json::parse(run.out);
}

/// Every gain of a gains.json: g0 and g1 positive; the ones flagged ill-conditioned returned as
/// "phrase/dof" (phrase 1-based).
std::vector<std::string> checkGainsFile(const fs::path& file)
{
    const json gains = json::parse(readTextFile(file));
    std::vector<std::string> flagged;
    for (std::size_t p = 0; p < gains.at("phrases").size(); ++p)
        for (const json& gain : gains.at("phrases")[p].at("gains")) {
            INFO("phrase " << p + 1 << " " << gain.dump());
            CHECK(gain.at("g0").get<double>() > 0.0);
            CHECK(gain.at("g1").get<double>() > 0.0);
            if (gain.at("ill_conditioned").get<bool>()) {
                flagged.push_back(std::to_string(p + 1) + "/" + gain.at("dof").get<std::string>());
                CHECK(gain.at("g1").get<double>() == Approx(10.0));
                CHECK_THAT(gain.at("ill_conditioned_reason").get<std::string>(), Contains("x A1_no"));
            }
        }
    return flagged;
}

} // namespace

TEST_CASE("bunraku gains names the phrases whose emotional take is held still as ill-conditioned, in text and json", "[cli][gains]")
{
    const auto dir = bunraku::test::scratchDir("cli-gains-ill-conditioned");
    runJson({"demo", "-o", (dir / "demo").string(), "--json"});
    fs::path reference;
    for (const auto& entry : fs::directory_iterator(dir / "demo"))
        if (entry.path().extension() == ".csv" && entry.path().filename().string().find("greeting_none") != std::string::npos &&
            entry.path().filename().string().find(".motion.") == std::string::npos)
            reference = entry.path();
    REQUIRE_FALSE(reference.empty());
    const auto take = readNumericCsv(reference);
    const int frames = int(take.rows.size());
    REQUIRE(frames > 60);
    // The sample: the reference held still from frame `held` on (an emotion that stops early),
    // with the identity warp; phrases 0-held-last.
    const int held = frames / 2;
    std::ostringstream text;
    text.precision(17);
    for (std::size_t c = 0; c < take.header.size(); ++c) text << (c ? "," : "") << take.header[c];
    text << "\n";
    for (int t = 0; t < frames; ++t) {
        const auto& row = take.rows[std::size_t(std::min(t, held))];
        text << take.rows[std::size_t(t)][0];
        for (std::size_t c = 1; c < row.size(); ++c) text << "," << row[c];
        text << "\n";
    }
    const fs::path sample = dir / "held.csv", warp = dir / "identity.csv", gains = dir / "gains.json";
    bunraku::test::writeText(sample, text.str());
    bunraku::test::writeText(warp, "output_frame,source_frame\n0,0\n" + std::to_string(frames - 1) + "," + std::to_string(frames - 1) + "\n");
    const std::string phrases = "0," + std::to_string(held) + "," + std::to_string(frames - 1);
    const std::vector<std::string> arguments{"gains", "--reference", reference.string(), "--sample", sample.string(),
                                             "--warp", warp.string(), "--phrases", phrases, "-o", gains.string()};

    auto withJson = arguments;
    withJson.push_back("--json");
    const json printed = runJson(withJson);
    // the existing keys, unchanged
    CHECK(printed.at("phrases") == json::array({0, held, frames - 1}));
    CHECK(printed.at("output") == gains.string());
    CHECK(printed.at("notes").is_array());
    // the new one: only phrase 2, each entry with its frames, DOF, amplitudes, gain and reason
    const json& ill = printed.at("ill_conditioned");
    REQUIRE(ill.is_array());
    REQUIRE(ill.size() >= 4);
    std::string heldTail = "-"; // built in steps: GCC 12's -Wrestrict misfires on "-" + std::to_string(...) + "..."
    heldTail += std::to_string(frames - 1);
    heldTail += " (the emotional take stands still there";
    std::vector<std::string> listed;
    for (const json& entry : ill) {
        INFO(entry.dump());
        CHECK(entry.at("phrase") == 2);
        CHECK(entry.at("begin") == held);
        CHECK(entry.at("end") == frames - 1);
        CHECK(entry.at("A1_emotional").get<double>() < 0.1 * entry.at("A1_functional").get<double>());
        CHECK(entry.at("g1").get<double>() == Approx(10.0));
        CHECK_THAT(entry.at("reason").get<std::string>(),
                   Contains("below 0.1 x A1_no") && Contains("held still over frames") &&
                       Contains(heldTail));
        listed.push_back("2/" + entry.at("dof").get<std::string>());
    }
    // gains.json: every gain positive, the flagged ones exactly those listed
    CHECK(checkGainsFile(gains) == listed);

    const auto plain = runBunraku(arguments);
    INFO(plain.err);
    REQUIRE(plain.exitCode == 0);
    CHECK_THAT(plain.out, Contains(std::to_string(ill.size()) + " ill-conditioned g1 (A1_em below 0.1 x A1_no; regularised to 10):"));
    for (const json& entry : ill)
        CHECK_THAT(plain.out, Contains("  phrase 2 (frames " + std::to_string(held) + "-" + std::to_string(frames - 1) + "), " +
                                       entry.at("dof").get<std::string>() + ": A1_em = "));
}

TEST_CASE("bunraku gains on the Bandai bye takes writes non-negative gains and reports the ill-conditioned ones", "[cli][gains]")
{
    const auto normal = bunraku::test::bandaiDir() / "bye_normal_001.bvh";
    if (!bunraku::test::requireBandaiData(fs::exists(normal))) return;
    const auto dir = bunraku::test::scratchDir("cli-gains-bye");
    for (const std::string emotion : {"happy", "angry"}) {
        INFO(emotion);
        const auto sample = bunraku::test::bandaiDir() / ("bye_" + emotion + "_001.bvh");
        REQUIRE(fs::exists(sample));
        const auto warp = dir / (emotion + "_warp.csv"), gains = dir / (emotion + "_gains.json");
        runJson({"phase", "--reference", normal.string(), "--sample", sample.string(), "-o", warp.string(), "--json"});
        const json printed = runJson({"gains", "--reference", normal.string(), "--sample", sample.string(), "--warp", warp.string(),
                                      "-o", gains.string(), "--json"});
        std::vector<std::string> listed;
        for (const json& entry : printed.at("ill_conditioned"))
            listed.push_back(std::to_string(entry.at("phrase").get<int>()) + "/" + entry.at("dof").get<std::string>());
        std::cout << "bye_" << emotion << ": " << printed.at("phrases").dump() << ", ill-conditioned " << json(listed).dump() << "\n";
        CHECK(checkGainsFile(gains) == listed);
    }
}
