// Readers check every numeric field when they parse: rates, positions and angles within what a
// take can hold, a corpus's takes at the corpus's rate, numbers JSON cannot hold; and names that
// need quoting in a CSV header read back unchanged.
#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/skeleton_io.h"
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

namespace {

/// tests/data/io/two_joint_chain.bvh with `from` replaced by `to` (the Elbow's OFFSET is line 8,
/// the two motion rows lines 19 and 20).
std::string chainBvh(const std::string& from = "", const std::string& to = "")
{
    std::string text = bunraku::test::fileBytes(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    if (!from.empty()) {
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
    }
    return text;
}

} // namespace

TEST_CASE("BVH offsets and positions beyond 1e7 cm after the unit scale are refused with the line", "[io][limits]")
{
    auto offset = parseBvh(chainBvh("OFFSET 10 0 0", "OFFSET 1e308 0 0"), "o.bvh");
    REQUIRE(offset.ok());
    const auto lengths = checkBvhLengths(*offset, 1.0);
    REQUIRE_FALSE(lengths.ok());
    CHECK_THAT(lengths.error().message, Contains("o.bvh:8") && Contains("OFFSET") && Contains("Elbow") && Contains("beyond"));
    // every reader of BVH takes checks them
    auto joints = bvhToJointTake(*offset, BvhImportOptions{});
    REQUIRE_FALSE(joints.ok());
    CHECK_THAT(joints.error().message, Contains("o.bvh:8"));

    auto position = parseBvh(chainBvh("1.0e1 0 0 90", "1e308 0 0 90"), "p.bvh");
    REQUIRE(position.ok());
    CHECK_THAT(checkBvhLengths(*position, 1.0).error().message, Contains("p.bvh:20") && Contains("'Base' Xposition"));
    // a blank line before the row moves it to line 21
    auto moved = parseBvh(chainBvh("1.0e1 0 0 90", "\n1e308 0 0 90"), "m.bvh");
    REQUIRE(moved.ok());
    CHECK_THAT(checkBvhLengths(*moved, 1.0).error().message, Contains("m.bvh:21"));

    // after the unit scale: 2e6 is 2e6 cm, or 2e8 cm in metres
    auto far = parseBvh(chainBvh("1.0e1 0 0 90", "2e6 0 0 90"), "f.bvh");
    REQUIRE(far.ok());
    CHECK(checkBvhLengths(*far, 1.0).ok());
    CHECK_THAT(checkBvhLengths(*far, 100.0).error().message, Contains("f.bvh:20") && Contains("2e+08 cm"));
    BvhImportOptions metres;
    metres.guessUnits = false;
    metres.unitScale = 100.0;
    CHECK_FALSE(bvhToJointTake(*far, metres).ok());
    metres.unitScale = 1.0;
    CHECK(bvhToJointTake(*far, metres).ok());
}

TEST_CASE("BVH angles beyond 1e9 deg are refused at parse time with the line", "[io][limits]")
{
    for (const std::string angle : {"-1e308", "1e12", "1000000001"}) {
        auto parsed = parseBvh(chainBvh("1.0e1 0 0 90 0 0 90 0 0", "1.0e1 0 0 90 0 0 " + angle + " 0 0"), "a.bvh");
        INFO(angle);
        REQUIRE_FALSE(parsed.ok());
        CHECK_THAT(parsed.error().message, Contains("a.bvh:20") && Contains("'Elbow' Zrotation") && Contains("beyond +-1e+09 deg"));
    }
    CHECK(parseBvh(chainBvh("1.0e1 0 0 90 0 0 90 0 0", "1.0e1 0 0 90 0 0 -1000000000 0 0"), "a.bvh").ok());
}

TEST_CASE("a BVH joint name that is not UTF-8 is refused with the line", "[io][limits]")
{
    auto parsed = parseBvh(chainBvh("JOINT Elbow", "JOINT El\xff" "bow"), "n.bvh");
    REQUIRE_FALSE(parsed.ok());
    CHECK_THAT(parsed.error().message, Contains("n.bvh:6") && Contains("\\xff") && Contains("UTF-8"));
    CHECK(parseBvh(chainBvh("JOINT Elbow", "JOINT Ell\xc3\xa9" "bow"), "n.bvh").ok()); // UTF-8 names are fine
}

TEST_CASE("a skeleton file with a number JSON cannot hold or ill-formed UTF-8 is an error naming the file", "[io][limits]")
{
    const auto dir = bunraku::test::scratchDir("limits-skeleton-json");
    auto bvh = parseBvh(chainBvh(), "chain.bvh");
    REQUIRE(bvh.ok());
    auto take = bvhToJointTake(*bvh, BvhImportOptions{});
    REQUIRE(take.ok());
    take->labels = TakeLabels{"greeting", "none", 1, ""};
    Corpus corpus;
    corpus.rateHz = take->rateHz;
    corpus.takes.push_back(*take);
    REQUIRE(writeCorpus(corpus, dir / "c").ok());
    const fs::path skeleton = dir / "c" / "greeting_none_1.skeleton.json";
    const std::string original = bunraku::test::fileBytes(skeleton);
    REQUIRE(readCorpus(dir / "c").ok());
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string text = original;
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
        return text;
    };
    const std::vector<std::string> broken = {
        replaced("\"Elbow\"", "\"El\xff" "bow\""),
        replaced("\"offset\": [\n    0.0,\n    10.0", "\"offset\": [\n    0.0,\n    1e400"),
    };
    for (const std::string& text : broken) {
        bunraku::test::writeText(skeleton, text);
        const auto read = readCorpus(dir / "c");
        REQUIRE_FALSE(read.ok());
        INFO(read.error().message);
        CHECK_THAT(read.error().message, Contains("greeting_none_1.skeleton.json:"));
        CHECK(read.error().message.find('\n') == std::string::npos);
        CHECK(read.error().message.find('\xff') == std::string::npos); // bytes written as \xff
    }
    // a skeleton named after a file whose name is not UTF-8 is written (the name with U+FFFD)
    auto named = parseBvh(chainBvh(), (dir / "\xff.bvh").string());
    REQUIRE(named.ok());
    auto namedTake = bvhToJointTake(*named, BvhImportOptions{});
    REQUIRE(namedTake.ok());
    namedTake->labels = TakeLabels{"greeting", "none", 1, ""};
    corpus.takes = {*namedTake};
    REQUIRE(writeCorpus(corpus, dir / "n").ok());
    REQUIRE(readCorpus(dir / "n").ok());
    // the BVH part map file too
    const fs::path map = bunraku::test::writeText(dir / "map.json", "{\"head\": 1e400}");
    const auto joints = readJointMapJson(map);
    REQUIRE_FALSE(joints.ok());
    CHECK_THAT(joints.error().message, Contains("map.json:1") && Contains("1e400"));
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
    options.scene.animation = "walk";
    options.scene.rateHz = 24.0;
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
    CHECK(back->scene.animation == "walk");
    CHECK(back->scene.rateHz == 24.0);

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
    CHECK(sizeof(SceneTakeOptions) == 40);
    CHECK(sizeof(ImportOptions) == 600);
}
