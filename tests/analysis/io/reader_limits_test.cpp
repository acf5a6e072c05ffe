// Readers check every numeric field when they parse: rates, positions and angles within what a
// take can hold, a corpus's takes at the corpus's rate, numbers JSON cannot hold; and names that
// need quoting in a CSV header read back unchanged.
#include "analysis/core/puppet_layout.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/fastrak.h"
#include "analysis/io/import_options_json.h"
#include "analysis/io/take_csv.h"
#include "tests/analysis/io/io_test_support.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

Corpus twoTakeCorpus()
{
    Corpus corpus;
    corpus.rateHz = 5.0;
    for (int k = 1; k <= 2; ++k) {
        Take take;
        take.channels = puppetChannels();
        take.rateHz = 5.0;
        take.values = Eigen::MatrixXd::Constant(6, kPuppetChannelCount, double(k));
        take.labels = TakeLabels{"greeting", "none", k, ""};
        corpus.takes.push_back(take);
    }
    return corpus;
}

} // namespace

TEST_CASE("a take of another rate inside a corpus is an error naming the file and line", "[io][limits]")
{
    const auto dir = bunraku::test::scratchDir("limits-corpus-rate");
    REQUIRE(writeCorpus(twoTakeCorpus(), dir / "c").ok());
    // take 2 rewritten at 10 Hz (time steps of 0.1 s) inside the 5 Hz corpus
    Take fast = twoTakeCorpus().takes[1];
    fast.rateHz = 10.0;
    bunraku::test::writeText(dir / "c" / "greeting_none_2.csv", formatTakeCsv(fast));
    auto corpus = readCorpus(dir / "c");
    REQUIRE_FALSE(corpus.ok());
    CHECK_THAT(corpus.error().message, Contains("greeting_none_2.csv:3") && Contains("10 Hz") && Contains("5 Hz"));
}

TEST_CASE("a corpus.json number JSON cannot hold is an error naming the file, not an abort", "[io][limits]")
{
    const auto dir = bunraku::test::scratchDir("limits-corpus-1e400");
    REQUIRE(writeCorpus(twoTakeCorpus(), dir / "c").ok());
    std::string manifest = bunraku::test::fileBytes(dir / "c" / "corpus.json");
    const auto at = manifest.find("\"rate_hz\": 5.0");
    REQUIRE(at != std::string::npos);
    manifest.replace(at, 14, "\"rate_hz\": 1e400");
    bunraku::test::writeText(dir / "c" / "corpus.json", manifest);
    auto corpus = readCorpus(dir / "c");
    REQUIRE_FALSE(corpus.ok());
    CHECK_THAT(corpus.error().message, Contains("corpus.json") && Contains("1e400"));
    CHECK_FALSE(parseCorpusManifest("{\"takes\": [{\"frames\": 1e12}]}", "m.json").ok());
}

TEST_CASE("positions and angles beyond what a take can hold are refused at parse time", "[io][limits]")
{
    auto huge = parseTakeCsv("time_s,head.x,head.yaw\n0,1,2\n0.2,1e308,2\n", "big.csv");
    REQUIRE_FALSE(huge.ok());
    CHECK_THAT(huge.error().message, Contains("big.csv:3") && Contains("head.x") && Contains("beyond"));
    CHECK_FALSE(parseTakeCsv("time_s,head.yaw\n0,2e9\n", "a.csv").ok());
    CHECK(parseTakeCsv("time_s,head.yaw\n0,9e8\n", "a.csv").ok()); // unwrapped angles of long takes are fine
    CHECK_FALSE(parseTakeCsv("time_s,head.x\n1e300,0\n2e300,0\n", "t.csv").ok());
    Take take = twoTakeCorpus().takes[0];
    take.values(2, 3) = 1e300;
    CHECK_THAT(validateTake(take).error().message, Contains("frame 2") && Contains("beyond"));
}

TEST_CASE("channel names holding separators or quotes survive a CSV round trip", "[io][limits]")
{
    Take take;
    take.rateHz = 30.0;
    take.channels = {Channel{"Left,Arm", "x", "cm"}, Channel{"say \"hi\"", "y", "cm"}, Channel{"semi;colon", "z", "cm"},
                     Channel{" padded ", "roll", "deg"}, Channel{"plain", "x", "cm"}};
    take.values = Eigen::MatrixXd::Random(3, 5);
    const std::string csv = formatTakeCsv(take);
    auto back = parseTakeCsv(csv, "quoted.csv");
    REQUIRE(back.ok());
    REQUIRE(back->channels.size() == 5);
    for (std::size_t c = 0; c < 5; ++c) CHECK(back->channels[c].name() == take.channels[c].name());
    CHECK(back->values == take.values);
    CHECK_THAT(parseTakeCsv("time_s,\"open.x\n0,1\n", "bad.csv").error().message, Contains("bad.csv:1") && Contains("quoted"));
    CHECK_THAT(parseTakeCsv("time_s,\"a\"b.x\n0,1\n", "bad.csv").error().message, Contains("after the closing quote"));
}

TEST_CASE("import options survive a JSON round trip, and every field is stored", "[io][limits]")
{
    ImportOptions options;
    options.csv.rateHz = 120.0;
    options.bvh.jointMap = JointMap{{"Head", "Chest", "LeftForeArm", "LeftHand"}};
    options.bvh.upAxis = BvhUpAxis::Z;
    options.bvh.unitScale = 100.0;
    options.bvh.kinematics.positionMode = BvhPositionMode::AddToOffset;
    options.bvh.guessUnits = true;
    options.bvh.side = BodySide::Left;
    options.bvh.calibrationFrame = 12;
    options.bvhLayout = BvhTakeLayout::AllJoints;
    options.fastrak.rateHz = 7.5;
    options.fastrak.units = FastrakUnits::Inches;
    options.fastrak.stations = {4, 3, 2, 1};
    const nlohmann::json json = importOptionsToJson(options);
    auto back = importOptionsFromJson(nlohmann::json::parse(json.dump()), "p.json");
    REQUIRE(back.ok());
    CHECK(importOptionsToJson(*back) == json);
    CHECK(back->bvh.jointMap->joints == options.bvh.jointMap->joints);
    CHECK(back->bvh.upAxis == BvhUpAxis::Z);
    CHECK(back->bvh.guessUnits);
    CHECK(back->bvh.side == BodySide::Left);
    CHECK(back->bvh.calibrationFrame == 12);
    CHECK(back->fastrak.stations == options.fastrak.stations);

    // older projects: missing fields keep their defaults; wrong ones are refused by name
    auto defaults = importOptionsFromJson(nlohmann::json::object(), "p.json");
    REQUIRE(defaults.ok());
    CHECK_FALSE(defaults->bvh.jointMap.has_value());
    CHECK_THAT(importOptionsFromJson({{"bvh", {{"upAxis", "sideways"}}}}, "p.json").error().message, Contains("upAxis"));
    CHECK_THAT(importOptionsFromJson({{"fastrak", {{"rateHz", 0}}}}, "p.json").error().message, Contains("fastrak.rateHz"));
    CHECK_THAT(importOptionsFromJson({{"bvh", {{"unitScale", -1}}}}, "p.json").error().message, Contains("unitScale"));
    CHECK_THAT(importOptionsFromJson({{"bvh", {{"side", "middle"}}}}, "p.json").error().message, Contains("side"));
    // A number no field can hold (found by fuzz_project: 1.2e50 as a FASTRAK station was converted
    // to int with undefined behaviour) is refused with where it is.
    CHECK_THAT(importOptionsFromJson({{"fastrak", {{"stations", {1.2e50, 2, 3, 4}}}}}, "p.json").error().message,
               Contains("p.json") && Contains("/fastrak/stations/0") && Contains("out of range"));
    CHECK_THAT(importOptionsFromJson({{"csv", {{"labels", {{"takeIndex", 3e9}}}}}}, "p.json").error().message, Contains("takeIndex"));
    CHECK_THAT(importOptionsFromJson({{"bvh", {{"calibrationFrame", -3}}}}, "p.json").error().message, Contains("calibrationFrame"));

    // Every field of the options structs must be named in import_options_json.cpp: when one of
    // these sizes changes, a field was added or removed; list it there and update the figure.
    CHECK(sizeof(TakeCsvOptions) == 136);
    CHECK(sizeof(BvhImportOptions) == 280);
    CHECK(sizeof(FastrakOptions) == 136);
    CHECK(sizeof(ImportOptions) == 560);
}
