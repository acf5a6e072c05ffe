// The one write helper and the one read helper every file goes through: atomic and durable
// writes that keep a file's permissions and clean up after killed runs; reads of regular files
// only, within a size bound, never blocking on a FIFO or filling memory from a device.
#include "analysis/io/atomic_file.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"
#include "tests/analysis/io/io_test_support.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <fstream>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

/// Names in `folder` other than `keep`.
std::vector<std::string> othersIn(const fs::path& folder, const std::string& keep)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename() != keep) names.push_back(entry.path().filename().string());
    return names;
}

/// The pid of a process that has exited (a child that was reaped).
pid_t deadPid()
{
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

} // namespace

TEST_CASE("a write replaces the file whole and keeps its permissions", "[io][atomic]")
{
    const auto dir = bunraku::test::scratchDir("atomic-write");
    const fs::path file = dir / "gains.json";
    REQUIRE(writeFileAtomically(file, "first").ok());
    ::chmod(file.c_str(), 0640);
    REQUIRE(writeFileAtomically(file, "second, longer").ok());
    CHECK(bunraku::test::fileBytes(file) == "second, longer");
    struct stat info {};
    REQUIRE(::stat(file.c_str(), &info) == 0);
    CHECK((info.st_mode & 0777) == 0640);
    CHECK(othersIn(dir, "gains.json").empty());
    CHECK_THAT(writeFileAtomically(dir / "missing" / "x.csv", "x").error().message, Contains("does not exist"));
    fs::create_directories(dir / "folder.csv");
    CHECK_THAT(writeFileAtomically(dir / "folder.csv", "x").error().message, Contains("folder of that name"));
}

TEST_CASE("a write that fails on a full disk leaves the old file whole and no temporary", "[io][atomic]")
{
    const auto dir = bunraku::test::scratchDir("atomic-full-disk");
    const fs::path file = dir / "g.json";
    const std::string old(10000, 'o');
    REQUIRE(writeFileAtomically(file, old).ok());
    // A child process whose files may not grow past 4096 bytes: the disk is "full" for it.
    const pid_t child = ::fork();
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        const Status status = writeFileAtomically(file, std::string(100000, 'n'));
        const bool named = !status.ok() && status.error().message.find("g.json") != std::string::npos &&
                           status.error().message.find("larger than") != std::string::npos;
        ::_exit(named ? 0 : 1);
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0); // refused, naming the file and the cause
    CHECK(bunraku::test::fileBytes(file) == old);
    CHECK(othersIn(dir, "g.json").empty());
}

TEST_CASE("the next write to a place removes the temporaries killed writes left there", "[io][atomic]")
{
    const auto dir = bunraku::test::scratchDir("atomic-stale");
    const fs::path file = dir / "take.csv";
    const std::string dead = std::to_string(deadPid());
    const std::string alive = std::to_string(::getppid()); // a running process: its write may be under way
    bunraku::test::writeText(dir / (".take.csv.bunraku-tmp-" + dead + "-0"), std::string(1000, 'x'));
    fs::create_directories(dir / (".take.csv.bunraku-old-" + dead + "-3"));
    bunraku::test::writeText(dir / (".take.csv.bunraku-tmp-" + alive + "-1"), "in progress");
    bunraku::test::writeText(dir / (".other.csv.bunraku-tmp-" + dead + "-0"), "another file's");
    bunraku::test::writeText(dir / ".take.csv.notes", "the user's");
    REQUIRE(writeFileAtomically(file, "time_s,a.x\n0,1\n").ok());
    auto left = othersIn(dir, "take.csv");
    std::sort(left.begin(), left.end());
    CHECK(left == std::vector<std::string>{".other.csv.bunraku-tmp-" + dead + "-0", ".take.csv.bunraku-tmp-" + alive + "-1",
                                           ".take.csv.notes"});
}

TEST_CASE("readers refuse a FIFO, a device and a folder at once and files beyond their bound", "[io][atomic]")
{
    const auto dir = bunraku::test::scratchDir("read-special");
    const fs::path fifo = dir / "take.csv";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    auto fromFifo = readTextFile(fifo); // would block forever waiting for a writer
    REQUIRE_FALSE(fromFifo.ok());
    CHECK_THAT(fromFifo.error().message, Contains("take.csv") && Contains("FIFO"));
    auto take = readTakeFile(fifo);
    REQUIRE_FALSE(take.ok());
    CHECK_THAT(take.error().message, Contains("FIFO"));

    for (const char* device : {"/dev/zero", "/dev/urandom"}) {
        auto text = readTextFile(device); // 8 GB and more before bad_alloc
        REQUIRE_FALSE(text.ok());
        CHECK_THAT(text.error().message, Contains(device) && Contains("device"));
        // through a take file's name and through a corpus's manifest
        fs::remove(dir / "linked.csv");
        fs::create_symlink(device, dir / "linked.csv");
        CHECK_THAT(readTakeFile(dir / "linked.csv").error().message, Contains("device"));
        fs::create_directories(dir / "corpus");
        fs::remove(dir / "corpus" / "corpus.json");
        fs::create_symlink(device, dir / "corpus" / "corpus.json");
        CHECK_THAT(readCorpus(dir / "corpus").error().message, Contains("corpus.json") && Contains("device"));
    }

    CHECK_THAT(readTextFile(dir).error().message, Contains("is a folder"));
    bunraku::test::writeText(dir / "big.txt", std::string(5000, 'x'));
    auto big = readTextFile(dir / "big.txt", 4096);
    REQUIRE_FALSE(big.ok());
    CHECK_THAT(big.error().message, Contains("big.txt") && Contains("5000 bytes") && Contains("4096"));
    auto fits = readTextFile(dir / "big.txt", 5000);
    REQUIRE(fits.ok());
    CHECK(fits->size() == 5000);
}
