#include "analysis/synth/demo_corpus.h"
#include "analysis/synth/demo_corpus_io.h"
#include "analysis/io/corpus_io.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace bunraku::analysis;
using namespace bunraku::analysis::synth;

TEST_CASE("ground truth survives a write and read round trip exactly", "[synth]")
{
    DemoOptions options;
    options.seed = 11;
    const DemoGroundTruth truth = generateDemoCorpus(options).truth;
    const auto folder = bunraku::test::scratchDir("synth-truth-roundtrip") / "truth";
    REQUIRE(writeGroundTruth(truth, folder).ok());
    CHECK(std::filesystem::exists(folder / "truth.json"));
    CHECK(std::filesystem::exists(folder / "functions" / "greeting_y.csv"));
    CHECK(std::filesystem::exists(folder / "cells" / "serving-tea_hostile_z.csv"));
    CHECK(std::filesystem::exists(folder / "takes" / "greeting_none_1_warp.csv"));

    const auto back = readGroundTruth(folder);
    REQUIRE(back.ok());
    CHECK(back->seed == 11);
    CHECK(back->rateHz == truth.rateHz);
    CHECK(back->nominalFrames == truth.nominalFrames);
    CHECK(back->positionNoiseCm == truth.positionNoiseCm);
    CHECK(back->angleNoiseDeg == truth.angleNoiseDeg);
    CHECK(back->neutralEmotion == truth.neutralEmotion);
    CHECK(back->parameterNames == truth.parameterNames);
    REQUIRE(back->functions.size() == truth.functions.size());
    for (std::size_t i = 0; i < truth.functions.size(); ++i) {
        CHECK(back->functions[i].function == truth.functions[i].function);
        CHECK(back->functions[i].phraseNames == truth.functions[i].phraseNames);
        CHECK(back->functions[i].phraseBoundaries == truth.functions[i].phraseBoundaries);
        CHECK(back->functions[i].phraseDisplacements == truth.functions[i].phraseDisplacements);
        CHECK(back->functions[i].motion == truth.functions[i].motion);
    }
    REQUIRE(back->cells.size() == truth.cells.size());
    for (std::size_t i = 0; i < truth.cells.size(); ++i) {
        const CellTruth& a = truth.cells[i];
        const CellTruth& b = back->cells[i];
        CHECK(b.function == a.function);
        CHECK(b.emotion == a.emotion);
        CHECK(b.phaseWarp == a.phaseWarp);
        CHECK(b.functionalToEmotional == a.functionalToEmotional);
        CHECK(b.phraseBoundaries == a.phraseBoundaries);
        CHECK(b.phraseGains == a.phraseGains);
        CHECK(b.phraseOffsets == a.phraseOffsets);
        CHECK(b.motion == a.motion);
        CHECK(b.emotionComponent == a.emotionComponent);
    }
    REQUIRE(back->takes.size() == truth.takes.size());
    for (std::size_t i = 0; i < truth.takes.size(); ++i) {
        const TakeTruth& a = truth.takes[i];
        const TakeTruth& b = back->takes[i];
        CHECK(b.labels == a.labels);
        CHECK(b.takeToCell == a.takeToCell);
        CHECK(b.lateStartFrames == a.lateStartFrames);
        CHECK(b.amplitudeGain == a.amplitudeGain);
        CHECK(b.positionOffset == a.positionOffset);
        CHECK(b.yawOffsetDeg == a.yawOffsetDeg);
        CHECK(b.yawWraps == a.yawWraps);
    }
    // The read truth rebuilds the same expected takes.
    const auto expected = noiselessTake(*back, truth.takes[3].labels);
    REQUIRE(expected.ok());
    CHECK(*expected == *noiselessTake(truth, truth.takes[3].labels));
}

TEST_CASE("reading a damaged ground truth names the file and line", "[synth]")
{
    const DemoGroundTruth truth = generateDemoCorpus().truth;
    const auto folder = bunraku::test::scratchDir("synth-truth-damaged");
    REQUIRE(writeGroundTruth(truth, folder).ok());

    SECTION("a non-number in a warp file")
    {
        const auto file = folder / "takes" / "greeting_none_2_warp.csv";
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        in.close();
        std::string content = text.str();
        const auto third = content.find('\n', content.find('\n', content.find('\n') + 1) + 1); // end of line 3
        content.replace(content.rfind(',', third) + 1, third - content.rfind(',', third) - 1, "abc");
        std::ofstream(file) << content;
        const auto back = readGroundTruth(folder);
        REQUIRE_FALSE(back.ok());
        CHECK(back.error().code == ErrorCode::Parse);
        CHECK(back.error().message.find("greeting_none_2_warp.csv:3:") != std::string::npos);
    }
    SECTION("a cell motion with a frame missing")
    {
        const auto file = folder / "cells" / "greeting_friendly_x.csv";
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        in.close();
        std::string content = text.str();
        content.erase(content.rfind('\n', content.size() - 2) + 1); // drop the last row
        std::ofstream(file) << content;
        const auto back = readGroundTruth(folder);
        REQUIRE_FALSE(back.ok());
        CHECK(back.error().code == ErrorCode::Parse);
        CHECK(back.error().message.find("greeting/friendly") != std::string::npos);
    }
    SECTION("a missing manifest")
    {
        std::filesystem::remove(folder / "truth.json");
        const auto back = readGroundTruth(folder);
        REQUIRE_FALSE(back.ok());
        CHECK(back.error().code == ErrorCode::NotFound);
        CHECK(back.error().message.find("truth.json") != std::string::npos);
    }
    SECTION("a manifest of another format")
    {
        std::ofstream(folder / "truth.json") << R"({"format": "something-else", "version": 1})";
        const auto back = readGroundTruth(folder);
        REQUIRE_FALSE(back.ok());
        CHECK(back.error().message.find("bunraku-demo-truth") != std::string::npos);
    }
}

TEST_CASE("writing the ground truth into an unwritable place fails with an Io error", "[synth]")
{
    const auto folder = bunraku::test::scratchDir("synth-truth-unwritable");
    std::ofstream(folder / "blocker") << "a file, not a folder";
    const auto status = writeGroundTruth(generateDemoCorpus().truth, folder / "blocker" / "truth");
    REQUIRE_FALSE(status.ok());
    CHECK(status.error().code == ErrorCode::Io);
}

TEST_CASE("the demo corpus folder reads back as the same takes with its ground truth beside it", "[synth]")
{
    const DemoCorpus demo = generateDemoCorpus();
    const auto folder = bunraku::test::scratchDir("synth-demo-folder") / "demo";
    REQUIRE(writeDemoCorpus(demo, folder).ok());
    const auto corpus = io::readCorpus(folder);
    REQUIRE(corpus.ok());
    REQUIRE(corpus->takes.size() == demo.corpus.takes.size());
    for (std::size_t i = 0; i < demo.corpus.takes.size(); ++i) {
        const Take& a = demo.corpus.takes[i];
        const Take* b = corpus->find(a.labels.function, a.labels.emotion, a.labels.takeIndex);
        REQUIRE(b != nullptr);
        REQUIRE(b->values.rows() == a.values.rows());
        CHECK((b->values - a.values).cwiseAbs().maxCoeff() < 1e-9);
        CHECK(b->rateHz == a.rateHz);
        CHECK(b->channels == a.channels);
    }
    const auto truth = readGroundTruth(groundTruthFolder(folder));
    REQUIRE(truth.ok());
    CHECK(truth->takes.size() == 30);
    CHECK(truth->takes[5].takeToCell == demo.truth.takes[5].takeToCell);
}
