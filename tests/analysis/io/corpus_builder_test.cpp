// Corpora from take files: labels from file names, one rate, the neutral emotion, and the
// skeleton of every take kept in the corpus folder and read back unchanged.
#include "analysis/core/puppet_layout.h"
#include "analysis/io/corpus_builder.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/skeleton_io.h"
#include "tests/analysis/io/io_test_support.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <sstream>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

/// The largest difference between two skeletal motions: structure must be equal, numbers within `tolerance`.
void requireSameSkeleton(const SkeletalMotion& a, const SkeletalMotion& b, double tolerance)
{
    REQUIRE(a.skeleton);
    REQUIRE(b.skeleton);
    const Skeleton& s = *a.skeleton;
    const Skeleton& t = *b.skeleton;
    CHECK(s.name == t.name);
    REQUIRE(s.joints.size() == t.joints.size());
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
        INFO("joint " << s.joints[j].name);
        CHECK(s.joints[j].name == t.joints[j].name);
        CHECK(s.joints[j].parent == t.joints[j].parent);
        CHECK(s.joints[j].channels == t.joints[j].channels);
        CHECK(s.joints[j].endSite == t.joints[j].endSite);
        CHECK((s.joints[j].offset - t.joints[j].offset).norm() <= tolerance);
        CHECK((a.staticTranslations[j] - b.staticTranslations[j]).norm() <= tolerance);
    }
    CHECK(s.source.upAxis == t.source.upAxis);
    CHECK(s.source.cmPerUnit == t.source.cmPerUnit);
    CHECK(s.source.world_R_source.angularDistance(t.source.world_R_source) <= tolerance);
    CHECK(s.positionMode == t.positionMode);
    REQUIRE(s.parts.size() == t.parts.size());
    for (std::size_t p = 0; p < s.parts.size(); ++p) {
        CHECK(s.parts[p].part == t.parts[p].part);
        CHECK(s.parts[p].joint == t.parts[p].joint);
        CHECK(s.parts[p].joint_T_part.rotation.angularDistance(t.parts[p].joint_T_part.rotation) <= tolerance);
        CHECK((s.parts[p].joint_T_part.translation - t.parts[p].joint_T_part.translation).norm() <= tolerance);
    }
    CHECK(a.movingJoints == b.movingJoints);
    REQUIRE(a.frameCount() == b.frameCount());
    REQUIRE(a.rotations.size() == b.rotations.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.rotations.size(); ++i) worst = std::max(worst, (a.rotations[i].coeffs() - b.rotations[i].coeffs()).cwiseAbs().maxCoeff());
    CHECK(worst <= tolerance);
    CHECK((a.movingTranslations - b.movingTranslations).cwiseAbs().maxCoeff() <= tolerance);
}

fs::path writeFixture(const fs::path& dir, const std::string& name, const bunraku::test::BvhFamily& family, double rateHz = 30.0)
{
    std::string text = bunraku::test::fixtureBvh(family);
    if (rateHz != 30.0) text.replace(text.find("Frame Time: 0.0333333"), 21, "Frame Time: " + std::to_string(1.0 / rateHz));
    return bunraku::test::writeText(dir / name, text);
}

} // namespace

TEST_CASE("file-name patterns give the labels of each take")
{
    struct Case {
        std::string stem, pattern;
        std::optional<TakeLabels> labels;
    };
    const Case cases[] = {
        {"wave-right-hand_active_003", kDefaultLabelPattern, TakeLabels{"wave-right-hand", "active", 3, ""}},
        {"dataset-2_wave-right-hand_active_003", "{any}_{function}_{emotion}_{take}", TakeLabels{"wave-right-hand", "active", 3, ""}},
        {"dataset-2_wave-right-hand_active_003", "dataset-2_{function}_{emotion}_{take}", TakeLabels{"wave-right-hand", "active", 3, ""}},
        {"bye_happy_001", kDefaultLabelPattern, TakeLabels{"bye", "happy", 1, ""}},
        {"greeting-angry", "{function}-{emotion}", TakeLabels{"greeting", "angry", 0, ""}},
        {"walk", "{function}", TakeLabels{"walk", "", 0, ""}},
        {"wave_active", kDefaultLabelPattern, std::nullopt},
        {"wave_active_x3", kDefaultLabelPattern, std::nullopt},
    };
    for (const auto& c : cases) {
        INFO(c.stem << " ~ " << c.pattern);
        CHECK(parseTakeLabels(c.stem, c.pattern) == c.labels);
    }
    for (const std::string bad : {"{function}{emotion}", "{function}_{mood}", "{emotion}_{take}", "{function", "{function}_{take}_{take}"}) {
        INFO(bad);
        const auto status = checkLabelPattern(bad);
        REQUIRE_FALSE(status.ok());
        CHECK_THAT(status.error().message, Contains("'" + bad + "'"));
    }
}

TEST_CASE("takes without an index are numbered in file order within their cell")
{
    auto sources = labelTakeFiles({"a/greet-happy.bvh", "a/greet-happy-2.bvh", "a/greet-sad.bvh"}, "{function}-{emotion}{any}");
    REQUIRE_FALSE(sources.ok()); // {emotion}{any} has no literal between them
    sources = labelTakeFiles({"a/greet_happy_x.bvh", "a/greet_happy_y.bvh", "a/greet_sad_x.bvh", "a/walk.bvh"}, "{function}_{emotion}_{any}");
    REQUIRE_FALSE(sources.ok());
    CHECK_THAT(sources.error().message, Contains("a/walk.bvh") && Contains("does not match the pattern"));
    sources = labelTakeFiles({"a/greet_happy_x.bvh", "a/greet_happy_y.bvh", "a/greet_sad_x.bvh"}, "{function}_{emotion}_{any}");
    REQUIRE(sources.ok());
    CHECK((*sources)[0].labels.takeIndex == 1);
    CHECK((*sources)[1].labels.takeIndex == 2);
    CHECK((*sources)[2].labels.takeIndex == 1);
    sources = labelTakeFiles({"a/walk.bvh"}, "{function}");
    REQUIRE(sources.ok());
    CHECK((*sources)[0].labels.emotion == "none");
}

TEST_CASE("a corpus from the bandai folder: labels, part maps, the neutral emotion, and skeletons read back to 1e-9")
{
    const auto files = bunraku::test::bandaiFilesOrSkip();
    if (files.empty()) return;
    auto collected = collectTakeFiles({bunraku::test::bandaiDir()});
    REQUIRE(collected.ok());
    CHECK(collected->size() == files.size());
    auto sources = labelTakeFiles(*collected, kDefaultLabelPattern);
    REQUIRE(sources.ok());
    CorpusBuildOptions options;
    options.import.bvh.guessUnits = true;
    options.name = "bandai";
    auto build = buildCorpus(*sources, options);
    INFO((build.ok() ? std::string() : build.error().message));
    REQUIRE(build.ok());
    const Corpus& corpus = build->corpus;
    CHECK(corpus.takes.size() == files.size());
    CHECK(corpus.rateHz == 30.0);
    CHECK(corpus.neutralEmotion == "normal");
    CHECK(corpus.functions() == std::vector<std::string>{"bye", "wave-right-hand"});
    REQUIRE(corpus.find("wave-right-hand", "active", 3));
    for (const auto& f : build->files) {
        CHECK(f.partMap == "head=Head (name), shoulder=Chest (topology), arm=LowerArm_R (name), hand=Hand_R (name), right side");
        CHECK_FALSE(f.resampled);
    }
    const auto dir = bunraku::test::scratchDir("corpus_bandai") / "bandai";
    REQUIRE(writeCorpus(corpus, dir).ok());
    CHECK(fs::exists(dir / "wave-right-hand_active_3.skeleton.json"));
    CHECK(fs::exists(dir / "wave-right-hand_active_3.motion.csv"));
    auto back = readCorpus(dir);
    INFO((back.ok() ? std::string() : back.error().message));
    REQUIRE(back.ok());
    REQUIRE(back->takes.size() == corpus.takes.size());
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        INFO(corpus.takes[i].displayName());
        REQUIRE(back->takes[i].skeleton);
        requireSameSkeleton(*corpus.takes[i].skeleton, *back->takes[i].skeleton, 1e-9);
        CHECK((back->takes[i].values - corpus.takes[i].values).cwiseAbs().maxCoeff() <= 1e-9);
    }
}

TEST_CASE("files at another rate are resampled to the corpus rate, joints by spherical interpolation, and said")
{
    const auto families = bunraku::test::bvhFamilies();
    const auto dir = bunraku::test::scratchDir("corpus_rates");
    const std::vector<fs::path> files{writeFixture(dir, "wave_happy_1.bvh", families[3]), writeFixture(dir, "wave_happy_2.bvh", families[3]),
                                      writeFixture(dir, "wave_sad_1.bvh", families[3], 60.0)};
    auto sources = labelTakeFiles(files, kDefaultLabelPattern);
    REQUIRE(sources.ok());
    auto build = buildCorpus(*sources, {});
    INFO((build.ok() ? std::string() : build.error().message));
    REQUIRE(build.ok());
    CHECK(build->corpus.rateHz == 30.0);
    CHECK(build->files[2].rateHz == 60.0);
    CHECK(build->files[2].resampled);
    CHECK(build->files[2].frames == 12);
    CHECK(build->files[2].framesInCorpus == 6); // 11 frames of 1/60 s: 0.183 s, 6 frames of 1/30 s
    REQUIRE(build->notes.size() == 2);
    CHECK_THAT(build->notes[0], Contains("corpus rate 30 Hz") && Contains("resampled to it: wave_sad_1.bvh (60 Hz)"));
    CHECK(build->notes[1] == "neutral emotion 'happy' (the first; give --neutral to choose)");
    // 60 -> 30 Hz: frame k is the source's frame 2k.
    auto source = readBvh(files[2]);
    REQUIRE(source.ok());
    auto original = bvhToPuppetTake(*source);
    REQUIRE(original.ok());
    const Take& resampled = *build->corpus.find("wave", "sad", 1);
    REQUIRE(resampled.skeleton);
    for (Eigen::Index k = 0; k < resampled.frameCount(); ++k)
        for (int j = 0; j < resampled.skeleton->jointSlots(); ++j)
            CHECK(resampled.skeleton->rotation(k, j).angularDistance(original->skeleton->rotation(2 * k, j)) < 1e-12);
    CHECK((resampled.values.row(2) - original->values.row(4)).cwiseAbs().maxCoeff() < 1e-9);
    // Given rate and neutral emotion.
    CorpusBuildOptions options;
    options.rateHz = 60.0;
    options.neutralEmotion = "sad";
    build = buildCorpus(*sources, options);
    REQUIRE(build.ok());
    CHECK(build->corpus.rateHz == 60.0);
    CHECK(build->files[0].resampled);
    CHECK(build->corpus.neutralEmotion == "sad");
    options.neutralEmotion = "calm";
    build = buildCorpus(*sources, options);
    REQUIRE_FALSE(build.ok());
    CHECK_THAT(build.error().message, Contains("'calm'") && Contains("happy, sad"));
}

TEST_CASE("two files with the same labels are refused, naming both")
{
    const auto families = bunraku::test::bvhFamilies();
    const auto dir = bunraku::test::scratchDir("corpus_duplicates");
    const std::vector<fs::path> files{writeFixture(dir, "wave_happy_1.bvh", families[0]), writeFixture(dir, "wave_happy_01.bvh", families[0])};
    auto sources = labelTakeFiles(files, kDefaultLabelPattern);
    REQUIRE(sources.ok());
    auto build = buildCorpus(*sources, {});
    REQUIRE_FALSE(build.ok());
    CHECK_THAT(build.error().message, Contains("wave_happy_01.bvh") && Contains("wave_happy_1.bvh") && Contains("wave/happy/1"));
}

TEST_CASE("every fixture family's skeleton is kept by a corpus folder, bit for bit")
{
    const auto dir = bunraku::test::scratchDir("corpus_families");
    Corpus corpus;
    corpus.rateHz = 30.0;
    int k = 0;
    for (const auto& family : bunraku::test::bvhFamilies()) {
        auto file = parseBvh(bunraku::test::fixtureBvh(family), family.id + ".bvh");
        REQUIRE(file.ok());
        BvhImportOptions options;
        options.guessUnits = true;
        options.labels = TakeLabels{"wave", family.id, ++k, ""};
        auto take = bvhToPuppetTake(*file, options);
        REQUIRE(take.ok());
        corpus.takes.push_back(std::move(take).value());
    }
    REQUIRE(writeCorpus(corpus, dir / "families").ok());
    auto back = readCorpus(dir / "families");
    INFO((back.ok() ? std::string() : back.error().message));
    REQUIRE(back.ok());
    for (std::size_t i = 0; i < corpus.takes.size(); ++i) {
        INFO(corpus.takes[i].labels.emotion);
        requireSameSkeleton(*corpus.takes[i].skeleton, *back->takes[i].skeleton, 0.0);
        // A moving joint's "translation" in the file is its first frame's, never uninitialised.
        const SkeletalMotion& motion = *corpus.takes[i].skeleton;
        for (std::size_t m = 0; m < motion.movingJoints.size(); ++m)
            CHECK(motion.staticTranslations[std::size_t(motion.movingJoints[m])] ==
                  motion.movingTranslations.block<1, 3>(0, Eigen::Index(3 * m)).transpose());
    }
    // The same corpus written again gives the same files, byte for byte.
    REQUIRE(writeCorpus(corpus, dir / "again").ok());
    for (const auto& entry : fs::directory_iterator(dir / "families")) {
        if (entry.path().filename().string().rfind(".", 0) == 0) continue;
        INFO(entry.path().filename().string());
        std::ifstream a(entry.path(), std::ios::binary);
        std::ifstream b(dir / "again" / entry.path().filename(), std::ios::binary);
        const std::string first((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
        const std::string second((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>());
        CHECK(first == second);
    }
}

TEST_CASE("bad skeleton files in a corpus are errors naming the file and what was expected")
{
    const auto families = bunraku::test::bvhFamilies();
    const auto root = bunraku::test::scratchDir("corpus_bad_skeleton");
    auto file = parseBvh(bunraku::test::fixtureBvh(families[0]), "bandai.bvh");
    REQUIRE(file.ok());
    BvhImportOptions options;
    options.labels = TakeLabels{"wave", "none", 1, ""};
    auto take = bvhToPuppetTake(*file, options);
    REQUIRE(take.ok());
    Corpus corpus;
    corpus.rateHz = 30.0;
    corpus.takes.push_back(*take);
    const auto fresh = [&](const std::string& name) {
        const fs::path dir = root / name;
        REQUIRE(writeCorpus(corpus, dir).ok());
        return dir;
    };
    const auto edit = [](const fs::path& path, const std::string& from, const std::string& to) {
        std::string text = bunraku::test::fileBytes(path);
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
        bunraku::test::writeText(path, text);
    };
    {
        const auto dir = fresh("quaternion");
        // A rotation that is not a unit quaternion: frame 0's first rotation column doubled.
        const fs::path motion = dir / "wave_none_1.motion.csv";
        std::string text = bunraku::test::fileBytes(motion);
        const std::string header = text.substr(0, text.find('\n'));
        const std::size_t column = std::size_t(std::count(header.begin(), header.begin() + std::ptrdiff_t(header.find(".qw")), ','));
        std::size_t start = header.size() + 1;
        for (std::size_t c = 0; c < column; ++c) start = text.find(',', start) + 1;
        text.replace(start, text.find(',', start) - start, "7");
        bunraku::test::writeText(motion, text);
        auto back = readCorpus(dir);
        REQUIRE_FALSE(back.ok());
        CHECK_THAT(back.error().message, Contains("wave_none_1.motion.csv: frame 0, joint") && Contains("expected a unit quaternion"));
    }
    {
        const auto dir = fresh("json");
        edit(dir / "wave_none_1.skeleton.json", "\"joints\"", "\"bones\"");
        auto back = readCorpus(dir);
        REQUIRE_FALSE(back.ok());
        CHECK_THAT(back.error().message, Contains("wave_none_1.skeleton.json: top level: missing \"joints\""));
    }
    {
        const auto dir = fresh("missing");
        fs::remove(dir / "wave_none_1.motion.csv");
        auto back = readCorpus(dir);
        REQUIRE_FALSE(back.ok());
        CHECK_THAT(back.error().message, Contains("corpus.json") && Contains("no such file \"wave_none_1.motion.csv\""));
    }
    {
        const auto dir = fresh("frames");
        edit(dir / "corpus.json", "\"motion\": \"wave_none_1.motion.csv\"", "\"motion\": \"../x.csv\"");
        auto back = readCorpus(dir);
        REQUIRE_FALSE(back.ok());
        CHECK_THAT(back.error().message, Contains("must be a file name inside the corpus folder"));
    }
}
