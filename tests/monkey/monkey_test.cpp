// The workbench's monkey test (tests/monkey/README.md). Environment:
//   BUNRAKU_MONKEY_SEED     the first seed (default 1)
//   BUNRAKU_MONKEY_SEEDS    how many seeds, each a new window (default 2: one on the demo corpus,
//                           one on the Bandai corpus)
//   BUNRAKU_MONKEY_ACTIONS  actions per seed (default 500 in the ASan build, 250 in others)
//   BUNRAKU_MONKEY_VERBOSE  1: print every action as it is done
// A failure prints the seed, the step and the last actions, and the command that replays it.

#include "tests/monkey/monkey.h"

#include "tests/app/app_test_support.h"
#include "tests/app/bandai_corpus_support.h"
#include "tests/support/test_paths.h"

#include "app/file_controller.h"
#include "app/project_file.h"

#include <catch2/catch.hpp>

#include <QApplication>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BUNRAKU_MONKEY_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define BUNRAKU_MONKEY_ASAN 1
#endif
#ifdef BUNRAKU_MONKEY_ASAN
#include <sanitizer/common_interface_defs.h>
#include <sanitizer/lsan_interface.h>
#endif

using namespace bunraku;

namespace {

std::uint64_t envNumber(const char* name, std::uint64_t fallback)
{
    const char* text = std::getenv(name);
    if (!text || !*text) return fallback;
    return std::strtoull(text, nullptr, 10);
}

/// Printed when the process dies (a sanitizer's report, an escaped exception, a Qt fatal error):
/// the seed and the last actions, so that the death can be replayed.
void printMonkeyLog(const char* why)
{
    if (auto* monkey = test::Monkey::current())
        std::fprintf(stderr, "\nmonkey: %s after %zu actions; the last ones:\n%s", why, monkey->actions(), monkey->log(80).c_str());
}

void installCrashReports()
{
    static const bool done = [] {
        std::set_terminate([] {
            printMonkeyLog("an exception escaped (std::terminate)");
            std::abort();
        });
#ifdef BUNRAKU_MONKEY_ASAN
        __sanitizer_set_death_callback([] { printMonkeyLog("a sanitizer stopped the run"); });
#endif
        static QtMessageHandler previous = qInstallMessageHandler([](QtMsgType type, const QMessageLogContext& context, const QString& message) {
            if (type == QtFatalMsg) printMonkeyLog("Qt fatal error");
            if (previous) previous(type, context, message);
        });
        return true;
    }();
    (void)done;
}

void writeFile(const std::filesystem::path& file, const std::string& bytes)
{
    std::ofstream out(file, std::ios::binary);
    out << bytes;
}

/// The files the monkey opens: the Bandai corpus (made now with the corpus builder that `bunraku
/// corpus` runs; never committed), take files, and bad files that must be refused.
/// Its folders are the process's own (named by its id): monkeys run side by side in one build
/// (seeds on both cores) never touch each other's files.
std::string monkeyScratch(const std::string& name)
{
    return name + "-" + std::to_string(QCoreApplication::applicationPid());
}

test::MonkeyFiles monkeyFiles()
{
    test::MonkeyFiles files;
    const auto scratch = test::scratchDir(monkeyScratch("monkey"));
    files.scratch = QString::fromStdString(scratch.string());
    const auto bandai = test::bandaiCorpusFolder(
        {"wave-right-hand_normal_001.bvh", "wave-right-hand_normal_002.bvh", "wave-right-hand_active_001.bvh",
         "wave-right-hand_active_002.bvh"},
        monkeyScratch("monkey-bandai"), "waves");
    if (!bandai.empty()) {
        files.corpora << QString::fromStdString(bandai.string());
        files.takes << QString::fromStdString((test::bandaiDir() / "wave-right-hand_exhausted_001.bvh").string());
    }
    const auto data = test::sourceDir() / "tests" / "data" / "io";
    files.takes << QString::fromStdString((data / "semicolon_crlf.csv").string())
                << QString::fromStdString((data / "two_joint_chain.bvh").string())
                << QString::fromStdString((data / "fastrak_sample.txt").string());
    // Bad input: each must be refused with a message, never opened, never a crash.
    const auto bad = scratch / "bad";
    std::filesystem::create_directories(bad / "not-a-corpus");
    writeFile(bad / "garbage.csv", "time_s,a\n0,1\n0.1,x\n");
    writeFile(bad / "empty.csv", "");
    writeFile(bad / "truncated.bvh", "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0\n");
    writeFile(bad / "broken.bunraku.json", "{\"format\": \"bunraku-project\", \"version\": ");
    writeFile(bad / "wrong.bunraku.json", "[1, 2, 3]\n");
    writeFile(bad / "not-a-corpus" / "corpus.json", "{\"takes\": 1e400}");
    for (const char* name : {"garbage.csv", "empty.csv", "truncated.bvh", "broken.bunraku.json", "wrong.bunraku.json", "not-a-corpus"})
        files.bad << QString::fromStdString((bad / name).string());
    files.bad << QString::fromStdString((bad / "missing.csv").string());
    return files;
}

} // namespace

#ifdef BUNRAKU_MONKEY_ASAN
// Leaks are checked at the end of a case (checkLeaksNow), while the QApplication and the libraries
// it loaded are still there: at exit, Qt's plugins and the GL driver are unloaded and a leak inside
// them has no module to be named by (nor suppressed by). This check replaces the one at exit
// (ctest runs each case in a process of its own; in one process, the first case's check is the one).
extern "C" const char* __lsan_default_suppressions()
{
    // Allocations that D-Bus keeps for the process (the accessibility bus Qt connects to), and
    // fontconfig's caches (freed only by FcFini, which Qt never calls): the system's, not ours.
    return "leak:libdbus-1.so\nleak:libfontconfig.so\n";
}

#endif

namespace {
void checkLeaksNow()
{
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
#ifdef BUNRAKU_MONKEY_ASAN
    __lsan_do_leak_check(); // dies on a leak; the check at exit is then not made
#endif
}
} // namespace

// Regression tests of what the monkey found (they fail in the sanitizer build on the code before
// the fix; scripts/test.sh runs them there).
TEST_CASE("a main window is destroyed without its side columns' filter reading it half-destroyed", "[monkey][window]")
{
    // SideColumns filtered the window's ChildRemoved events of its destruction and read its
    // QPointer<QMainWindow> when it was no more a QMainWindow (UBSan: downcast of a QWidget).
    test::isolateSettings();
    auto window = std::make_unique<app::MainWindow>();
    window->files().corpora().openDemoCorpus();
    window->show();
    REQUIRE(QTest::qWaitForWindowExposed(window.get()));
    window.reset();
    checkLeaksNow();
}

TEST_CASE("the monkey: random user actions on the demo and Bandai corpora keep every invariant", "[monkey]")
{
    installCrashReports();
    test::isolateSettings();
    const auto firstSeed = envNumber("BUNRAKU_MONKEY_SEED", 1);
    const auto seeds = envNumber("BUNRAKU_MONKEY_SEEDS", 2);
#ifdef BUNRAKU_MONKEY_ASAN
    const std::uint64_t defaultActions = 500; // the sanitizer build's run: 1,000 actions, about 3 min of CPU
#else
    const std::uint64_t defaultActions = 250; // the Release build's short run (its other suites cover the rest)
#endif
    const auto actions = envNumber("BUNRAKU_MONKEY_ACTIONS", defaultActions);
    const bool verbose = envNumber("BUNRAKU_MONKEY_VERBOSE", 0) != 0;
    const auto files = monkeyFiles();
    std::uint64_t total = 0;
    for (auto seed = firstSeed; seed < firstSeed + seeds; ++seed) {
        auto executor = std::make_shared<test::MonkeyExecutor>();
        widgets::ManualClock clock; // outlives the window, whose timers run on it
        auto window = std::make_unique<app::MainWindow>(nullptr, executor);
        // Dialogs on: the monkey answers them (Monkey::answerModal), some of them midway.
        window->files().corpora().openDemoCorpus();
        window->resize(1400, 900);
        window->show();
        REQUIRE(QTest::qWaitForWindowExposed(window.get()));
        // Odd seeds start on the Bandai corpus, even ones on the demo corpus.
        if (seed % 2 == 1 && !files.corpora.isEmpty()) REQUIRE(window->files().corpora().openCorpusFolder(files.corpora.front()));
        test::Monkey monkey(*window, *executor, clock, files, seed);
        monkey.setVerbose(verbose);
        for (std::uint64_t k = 0; k < actions; ++k) {
            if (!monkey.step()) {
                FAIL("monkey: seed " << seed << ": " << monkey.failure() << "\nthe last actions:\n" << monkey.log()
                     << "replay: BUNRAKU_MONKEY_SEED=" << seed << " BUNRAKU_MONKEY_SEEDS=1 BUNRAKU_MONKEY_ACTIONS="
                     << monkey.actions() << " BUNRAKU_MONKEY_VERBOSE=1 tests_monkey");
            }
        }
        total += monkey.actions();
        if (envNumber("BUNRAKU_MONKEY_PROFILE", 0) != 0) std::printf("monkey: seed %llu\n%s", (unsigned long long)seed, monkey.profile().c_str());
        window->files().setDialogsEnabled(false);
        window->files().projects().setUnsavedAnswerForTesting({}); // closing asks nothing
        while (executor->runNext()) QCoreApplication::processEvents();
        window.reset();
        QCoreApplication::processEvents();
    }
    // Its own folders go (a failed run keeps them, to look at).
    std::filesystem::remove_all(files.scratch.toStdString());
    std::filesystem::remove_all(test::scratchRoot() / monkeyScratch("monkey-bandai"));
    checkLeaksNow();
    std::printf("monkey: %llu actions on %llu seeds from %llu, 0 failures\n", (unsigned long long)total,
                (unsigned long long)seeds, (unsigned long long)firstSeed);
}
