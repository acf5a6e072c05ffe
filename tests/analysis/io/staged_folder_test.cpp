// Folder outputs are built beside the target and swapped in; a folder is only replaced when it
// holds nothing but what this program wrote there, and writing a corpus never deletes a user's
// files.
#include "analysis/core/puppet_layout.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/staged_folder.h"
#include "tests/analysis/io/io_test_support.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

Corpus oneTakeCorpus(double value)
{
    Corpus corpus;
    corpus.rateHz = 5.0;
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values = Eigen::MatrixXd::Constant(4, kPuppetChannelCount, value);
    take.labels = TakeLabels{"greeting", "none", 1, ""};
    corpus.takes.push_back(take);
    return corpus;
}

std::vector<std::string> entries(const fs::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST_CASE("a staged folder appears whole with its manifest, and replaces what it wrote before", "[io][staged]")
{
    const auto dir = bunraku::test::scratchDir("staged-basic");
    {
        auto staged = StagedFolder::begin(dir / "out");
        REQUIRE(staged.ok());
        REQUIRE(staged->writeFile("a.csv", "one").ok());
        REQUIRE(staged->writeFile("sub/b.csv", "two").ok());
        CHECK_FALSE(fs::exists(dir / "out")); // nothing in place before the commit
        REQUIRE(staged->commit().ok());
    }
    CHECK(bunraku::test::fileBytes(dir / "out" / "a.csv") == "one");
    CHECK(bunraku::test::fileBytes(dir / "out" / "sub" / "b.csv") == "two");
    CHECK(foreignFiles(dir / "out").empty());
    CHECK(entries(dir) == std::vector<std::string>{"out"});

    auto again = StagedFolder::begin(dir / "out/");
    REQUIRE(again.ok());
    REQUIRE(again->writeFile("c.csv", "three").ok());
    REQUIRE(again->commit().ok());
    CHECK(entries(dir / "out") == std::vector<std::string>{kWrittenFilesManifest, "c.csv"});
    CHECK(entries(dir) == std::vector<std::string>{"out"});

    { // abandoned: nothing changes and the staging folder goes
        auto abandoned = StagedFolder::begin(dir / "out");
        REQUIRE(abandoned.ok());
        REQUIRE(abandoned->writeFile("d.csv", "four").ok());
    }
    CHECK(entries(dir / "out") == std::vector<std::string>{kWrittenFilesManifest, "c.csv"});
    CHECK(entries(dir) == std::vector<std::string>{"out"});
    CHECK_FALSE(StagedFolder::begin(dir / "out")->writeFile("../escape.csv", "x").ok());
}

TEST_CASE("a folder holding files this program did not write is refused, naming them", "[io][staged]")
{
    const auto dir = bunraku::test::scratchDir("staged-foreign");
    REQUIRE(writeCorpus(oneTakeCorpus(1.0), dir / "corpus").ok());
    fs::create_directories(dir / "corpus" / "sub");
    bunraku::test::writeText(dir / "corpus" / "notes.txt", "my notes");
    bunraku::test::writeText(dir / "corpus" / "sub" / "photo.jpg", "a photo");

    const Status status = writeCorpus(oneTakeCorpus(2.0), dir / "corpus");
    REQUIRE_FALSE(status.ok());
    CHECK_THAT(status.error().message, Contains("corpus") && Contains("notes.txt") && Contains("sub/photo.jpg") &&
                                           Contains("did not write"));
    CHECK(bunraku::test::fileBytes(dir / "corpus" / "notes.txt") == "my notes");
    CHECK(bunraku::test::fileBytes(dir / "corpus" / "sub" / "photo.jpg") == "a photo");
    CHECK(readCorpus(dir / "corpus")->takes.front().values(0, 0) == 1.0);
    CHECK(entries(dir) == std::vector<std::string>{"corpus"}); // no staging folder left

    // a file the program wrote but the user edited since is the user's now
    fs::remove(dir / "corpus" / "notes.txt");
    fs::remove_all(dir / "corpus" / "sub");
    REQUIRE(writeCorpus(oneTakeCorpus(3.0), dir / "corpus").ok());
    std::string edited = bunraku::test::fileBytes(dir / "corpus" / "greeting_none_1.csv");
    edited.back() = '4';
    bunraku::test::writeText(dir / "corpus" / "greeting_none_1.csv", edited);
    CHECK_THAT(writeCorpus(oneTakeCorpus(5.0), dir / "corpus").error().message, Contains("greeting_none_1.csv"));

    // a corpus folder written before manifests existed is refused too: its files are named
    fs::create_directories(dir / "old");
    bunraku::test::writeText(dir / "old" / "corpus.json", "{}");
    CHECK_THAT(checkReplaceableFolder(dir / "old").error().message, Contains("corpus.json"));
    // an empty folder and a missing one are fine; a file of that name is not
    fs::create_directories(dir / "empty");
    CHECK(writeCorpus(oneTakeCorpus(1.0), dir / "empty").ok());
    CHECK(writeCorpus(oneTakeCorpus(1.0), dir / "new" / "deeper").ok());
    bunraku::test::writeText(dir / "plain", "x");
    CHECK_THAT(writeCorpus(oneTakeCorpus(1.0), dir / "plain").error().message, Contains("not a folder"));
}

TEST_CASE("a staged write removes the folders of killed runs beside its target", "[io][staged]")
{
    const auto dir = bunraku::test::scratchDir("staged-stale");
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    const std::string dead = std::to_string(child);
    fs::create_directories(dir / (".corpus.bunraku-tmp-" + dead + "-0") / "half");
    bunraku::test::writeText(dir / (".corpus.bunraku-tmp-" + dead + "-0") / "half" / "x.csv", std::string(4096, 'x'));
    fs::create_directories(dir / (".corpus.bunraku-old-" + dead + "-1"));
    REQUIRE(writeCorpus(oneTakeCorpus(1.0), dir / "corpus").ok());
    CHECK(entries(dir) == std::vector<std::string>{"corpus"});
}
