// Every write survives a kill at any moment: a child process writes project saves, take exports,
// corpora and PNG frame sequences over and over and is killed (SIGKILL) at a random point, 200
// times; after each kill the target holds the previous complete version or the new complete one,
// never a mix, a cut or nothing, and the next complete write removes what the killed ones left.
#include "tests/app/write_loop_content.h"
#include "tests/support/test_paths.h"

#include "analysis/io/atomic_file.h"

#include <catch2/catch.hpp>

#include <QProcess>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

using namespace bunraku;
using namespace bunraku::test::writeloop;
namespace fs = std::filesystem;

namespace {

/// Runs the child until it says "ready", waits `delay`, kills it; returns the versions it
/// reported complete.
int runAndKill(const std::string& kind, const fs::path& target, int firstVersion, std::chrono::microseconds delay)
{
    QProcess child;
    child.setProgram(QStringLiteral(BUNRAKU_WRITE_LOOP));
    child.setArguments({QString::fromStdString(kind), QString::fromStdString(target.string()), QString::number(firstVersion)});
    child.start();
    REQUIRE(child.waitForStarted(10000));
    REQUIRE(child.waitForReadyRead(20000)); // "ready": set up, about to write
    std::this_thread::sleep_for(delay);
    ::kill(pid_t(child.processId()), SIGKILL);
    REQUIRE(child.waitForFinished(20000));
    return int(QString::fromLatin1(child.readAllStandardOutput()).count(QStringLiteral("wrote")));
}

/// Hidden temporary siblings of `target` (what killed writes leave until the next write).
int temporariesBeside(const fs::path& target)
{
    int count = 0;
    std::string prefix = target.filename().string(); // built stepwise: GCC 12's false -Wrestrict
    prefix.insert(0, 1, '.');
    prefix += ".bunraku-";
    for (const auto& entry : fs::directory_iterator(target.parent_path()))
        if (entry.path().filename().string().rfind(prefix, 0) == 0) ++count;
    return count;
}

} // namespace

TEST_CASE("a write killed at any moment leaves the old or the new version whole, 200 times", "[app][kill]")
{
    const fs::path folder = test::scratchDir("kill-writes");
    const std::pair<const char*, Kind> kinds[] = {
        {"project", Kind::Project}, {"take", Kind::Take}, {"corpus", Kind::Corpus}, {"frames", Kind::Frames}};
    const std::string targets[] = {"work.bunraku.json", "take.csv", "corpus", "frames"};
    std::mt19937 rng(16);
    std::uniform_int_distribution<int> microseconds(0, 40000);
    int version = 1;
    int killedWithTemporaries = 0;
    int replaced = 0;
    for (int run = 0; run < 200; ++run) {
        const auto& [kind, which] = kinds[run % 4];
        const fs::path target = folder / targets[run % 4];
        const Verdict before = verify(which, target);
        REQUIRE(before.problem.empty());
        const int wrote = runAndKill(kind, target, version, std::chrono::microseconds(microseconds(rng)));
        const Verdict after = verify(which, target);
        INFO("run " << run << " (" << kind << "), versions " << version << " on, " << wrote << " written before the kill");
        INFO("problem: " << after.problem);
        REQUIRE(after.problem.empty());
        if (before.exists) REQUIRE(after.exists); // never nothing where something was
        if (after.exists && after.version != before.version) ++replaced;
        if (temporariesBeside(target) > 0) ++killedWithTemporaries;
        version += wrote + 1;
    }
    // The kills landed inside writes (temporaries left) and between them (new versions in place).
    std::printf("kill test: 200 kills, %d inside a write (temporaries left), %d replaced the version on disk, %d versions "
                "written\n",
                killedWithTemporaries, replaced, version - 1);
    CHECK(killedWithTemporaries > 20);
    CHECK(replaced > 20);

    // One complete write to each place removes every temporary the killed runs left there.
    for (int k = 0; k < 4; ++k) {
        const fs::path target = folder / targets[k];
        QProcess child;
        child.start(QStringLiteral(BUNRAKU_WRITE_LOOP), {QString::fromLatin1(kinds[k].first), QString::fromStdString(target.string()),
                                                        QString::number(version), QString::number(version)});
        REQUIRE(child.waitForFinished(60000));
        REQUIRE(child.exitCode() == 0);
        const Verdict last = verify(kinds[k].second, target);
        REQUIRE(last.problem.empty());
        CHECK(temporariesBeside(target) == 0);
    }
}
