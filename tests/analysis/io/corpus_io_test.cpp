#include "analysis/core/puppet_layout.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/staged_folder.h"
#include "tests/analysis/io/io_test_support.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <stop_token>
#include <vector>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;

namespace {

Corpus smallCorpus()
{
    Corpus corpus;
    corpus.name = "small";
    corpus.rateHz = 5.0;
    int seed = 1;
    for (const std::string function : {"greeting", "serving tea"})
        for (const std::string emotion : {"none", "hostile"})
            for (int k = 1; k <= 2; ++k) {
                Take take;
                take.channels = puppetChannels();
                take.rateHz = 5.0;
                take.values.resize(3 + k, kPuppetChannelCount);
                for (Eigen::Index f = 0; f < take.values.rows(); ++f)
                    for (int c = 0; c < kPuppetChannelCount; ++c) take.values(f, c) = std::sin(0.37 * double(seed++)) * 100.0;
                take.labels = TakeLabels{function, emotion, k, ""};
                corpus.takes.push_back(take);
            }
    return corpus;
}

} // namespace

TEST_CASE("a corpus written and read back is identical")
{
    const auto dir = bunraku::test::scratchDir("corpus_round_trip");
    const Corpus original = smallCorpus();
    REQUIRE(writeCorpus(original, dir / "corpus").ok());
    CHECK(isCorpusFolder(dir / "corpus"));
    auto back = readCorpus(dir / "corpus");
    REQUIRE(back.ok());
    CHECK(back->name == original.name);
    CHECK(back->rateHz == original.rateHz);
    CHECK(back->neutralEmotion == original.neutralEmotion);
    CHECK(back->convention == original.convention);
    REQUIRE(back->takes.size() == original.takes.size());
    for (std::size_t i = 0; i < original.takes.size(); ++i) {
        CHECK(back->takes[i].labels.function == original.takes[i].labels.function);
        CHECK(back->takes[i].labels.emotion == original.takes[i].labels.emotion);
        CHECK(back->takes[i].labels.takeIndex == original.takes[i].labels.takeIndex);
        CHECK(back->takes[i].channels == original.takes[i].channels);
        CHECK(back->takes[i].values == original.takes[i].values);
    }
    const auto manifest = nlohmann::json::parse(bunraku::test::fileBytes(dir / "corpus" / "corpus.json"));
    CHECK(manifest["format"] == kCorpusFormatName);
    CHECK(manifest["version"] == kCorpusFormatVersion);
    CHECK(manifest["channels"].size() == 24);
    CHECK(manifest["takes"][4]["file"] == "serving-tea_none_1.csv");
    CHECK(manifest["takes"][0]["frames"] == 4);
}

TEST_CASE("a corpus is read with the fraction of its takes reported, and stops between two takes when asked")
{
    const auto dir = bunraku::test::scratchDir("corpus_read_progress");
    REQUIRE(writeCorpus(smallCorpus(), dir / "corpus").ok());
    std::vector<double> fractions;
    auto read = readCorpus(dir / "corpus", RunControl{{}, [&](double fraction) { fractions.push_back(fraction); }});
    REQUIRE(read.ok());
    REQUIRE(fractions.size() == 8);
    for (std::size_t i = 0; i < fractions.size(); ++i) CHECK(fractions[i] == Approx(double(i) / 8.0));

    std::stop_source stop;
    int reports = 0;
    auto stopped = readCorpus(dir / "corpus", RunControl{stop.get_token(), [&](double) {
                                                             if (++reports == 3) stop.request_stop();
                                                         }});
    REQUIRE_FALSE(stopped.ok());
    CHECK(stopped.error().code == ErrorCode::Cancelled);
    CHECK(reports == 3);
}

TEST_CASE("rewriting a corpus replaces it and leaves no temporary folders")
{
    const auto dir = bunraku::test::scratchDir("corpus_rewrite");
    Corpus corpus = smallCorpus();
    REQUIRE(writeCorpus(corpus, dir / "c").ok());
    corpus.takes.resize(2);
    corpus.name = "smaller";
    REQUIRE(writeCorpus(corpus, dir / "c").ok());
    auto back = readCorpus(dir / "c");
    REQUIRE(back.ok());
    CHECK(back->takes.size() == 2);
    CHECK(back->name == "smaller");
    int entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
    CHECK(entries == 1);
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir / "c")) ++files;
    CHECK(files == 4); // corpus.json, 2 takes and the manifest of the files written
    CHECK(std::filesystem::is_regular_file(dir / "c" / kWrittenFilesManifest));
}

TEST_CASE("a failed corpus write leaves the previous corpus untouched")
{
    const auto dir = bunraku::test::scratchDir("corpus_atomic");
    const Corpus original = smallCorpus();
    REQUIRE(writeCorpus(original, dir / "c").ok());
    Corpus broken = smallCorpus();
    broken.takes[3].values(1, 7) = std::numeric_limits<double>::infinity();
    auto status = writeCorpus(broken, dir / "c");
    REQUIRE_FALSE(status.ok());
    CHECK_THAT(status.error().message, Contains("frame 1"));
    auto back = readCorpus(dir / "c");
    REQUIRE(back.ok());
    CHECK(back->takes[3].values == original.takes[3].values);

    // a folder that is not a corpus is never replaced
    std::filesystem::create_directories(dir / "other");
    bunraku::test::writeText(dir / "other" / "notes.txt", "keep me");
    CHECK_FALSE(writeCorpus(original, dir / "other").ok());
    CHECK(bunraku::test::fileBytes(dir / "other" / "notes.txt") == "keep me");
    // a path under a regular file cannot be created
    bunraku::test::writeText(dir / "plain", "x");
    CHECK_FALSE(writeCorpus(original, dir / "plain" / "c").ok());
}

TEST_CASE("corpus reader errors name the file and what was expected")
{
    const auto dir = bunraku::test::scratchDir("corpus_errors");
    REQUIRE(writeCorpus(smallCorpus(), dir / "c").ok());
    const auto manifestPath = dir / "c" / "corpus.json";
    const auto manifest = nlohmann::json::parse(bunraku::test::fileBytes(manifestPath));

    SECTION("invalid JSON names the line")
    {
        bunraku::test::writeText(manifestPath, "{\n  \"format\": \"bunraku-corpus\",\n  oops\n}");
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("corpus.json:3") && Contains("invalid JSON"));
    }
    SECTION("a wrong format name")
    {
        auto changed = manifest;
        changed["format"] = "something-else";
        bunraku::test::writeText(manifestPath, changed.dump());
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("corpus.json") && Contains("bunraku-corpus"));
    }
    SECTION("a missing take file")
    {
        auto changed = manifest;
        changed["takes"][2]["file"] = "missing.csv";
        bunraku::test::writeText(manifestPath, changed.dump());
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("corpus.json: takes[2]") && Contains("missing.csv"));
    }
    SECTION("a frame count that disagrees with the CSV")
    {
        auto changed = manifest;
        changed["takes"][1]["frames"] = 99;
        bunraku::test::writeText(manifestPath, changed.dump());
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("greeting_none_2.csv") && Contains("99"));
    }
    SECTION("a take CSV with a bad value names the CSV line")
    {
        bunraku::test::writeText(dir / "c" / "greeting_none_1.csv", "time_s,head.x\n0,zz\n");
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("greeting_none_1.csv:2"));
    }
    SECTION("a take file outside the folder is refused")
    {
        auto changed = manifest;
        changed["takes"][0]["file"] = "../escape.csv";
        bunraku::test::writeText(manifestPath, changed.dump());
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("takes[0]"));
    }
    SECTION("a take file path that climbs out through a subfolder is refused")
    {
        std::filesystem::create_directories(dir / "c" / "sub");
        std::filesystem::copy_file(dir / "c" / "greeting_none_1.csv", dir / "escape.csv",
                                   std::filesystem::copy_options::overwrite_existing);
        auto changed = manifest;
        changed["takes"][0]["file"] = "sub/../../escape.csv";
        bunraku::test::writeText(manifestPath, changed.dump());
        auto corpus = readCorpus(dir / "c");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("corpus.json: takes[0]") && Contains("inside the corpus folder"));
    }
    SECTION("a missing folder")
    {
        auto corpus = readCorpus(dir / "nothing-here");
        REQUIRE_FALSE(corpus.ok());
        CHECK_THAT(corpus.error().message, Contains("nothing-here"));
    }
}

TEST_CASE("corpus manifests with absurd numbers are errors, not crashes")
{
    const auto dir = bunraku::test::scratchDir("corpus_absurd");
    REQUIRE(writeCorpus(smallCorpus(), dir / "c").ok());
    const auto manifestPath = dir / "c" / "corpus.json";
    const auto manifest = nlohmann::json::parse(bunraku::test::fileBytes(manifestPath));
    for (const char* key : {"take", "frames"}) {
        for (double value : {1e300, -5.0, 2.5}) {
            auto changed = manifest;
            changed["takes"][0][key] = value;
            bunraku::test::writeText(manifestPath, changed.dump());
            auto corpus = readCorpus(dir / "c");
            INFO(key << " = " << value);
            CHECK_FALSE(corpus.ok());
        }
    }
    auto changed = manifest;
    changed["version"] = 1e300;
    bunraku::test::writeText(manifestPath, changed.dump());
    CHECK(readCorpus(dir / "c").error().code == ErrorCode::Unsupported);
}
