// The command line never destroys what it reads or what the user keeps beside its outputs: an
// output equal to an input (or a folder holding one) is refused, a folder with the user's files
// is never replaced, a write that fails or is killed leaves the previous output whole, and every
// error names the file.
#include "tests/cli/cli_files.h"
#include "tests/cli/cli_runner.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <map>
#include <csignal>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using bunraku::test::isOneLineError;
using bunraku::test::readTextFile;
using bunraku::test::runBunraku;
using bunraku::test::runBunrakuWith;
using bunraku::test::writeText;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

/// A demo corpus written once per test folder.
fs::path demoCorpus(const fs::path& dir)
{
    const fs::path corpus = dir / "demo";
    const auto run = runBunraku({"demo", "-o", corpus.string()});
    REQUIRE(run.exitCode == 0);
    return corpus;
}

/// Every file under `folder` with its content (to show nothing changed).
std::map<std::string, std::string> snapshot(const fs::path& folder)
{
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files[entry.path().lexically_relative(folder).string()] = readTextFile(entry.path());
    return files;
}

} // namespace

TEST_CASE("an output equal to an input, or a folder holding one, is refused and the input kept", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-inputs");
    const fs::path corpus = demoCorpus(dir);
    const fs::path take = corpus / "greeting_none_1.csv";
    const fs::path other = corpus / "greeting_friendly_1.csv";
    const std::string before = readTextFile(take);
    fs::copy_file(bunraku::test::sourceDir() / "tests" / "data" / "io" / "two_joint_chain.bvh", dir / "x.bvh");
    const std::string bvh = readTextFile(dir / "x.bvh");
    const auto corpusBefore = snapshot(corpus);

    const std::vector<std::vector<std::string>> commands = {
        {"phase", "--reference", other.string(), "--sample", take.string(), "-o", take.string()},
        {"axis", take.string(), "-o", take.string()},
        {"axis", take.string(), "-o", (corpus / "." / "greeting_none_1.csv").string()},
        {"convert", (dir / "x.bvh").string(), "-o", (dir / "x.bvh").string()},
        {"convert", corpus.string(), "-o", corpus.string()},
        {"convert", corpus.string(), "-o", dir.string()},
        {"preprocess", corpus.string(), "-o", corpus.string()},
        {"normalise", corpus.string(), "--function", "greeting", "--emotion", "none", "-o", corpus.string()},
        {"decompose", corpus.string(), "--pad", "-o", dir.string()},
        // the files of an input corpus are inputs too
        {"normalise", corpus.string(), "--function", "greeting", "--emotion", "none", "-o",
         (corpus / "greeting_none_2.csv").string()},
        {"normalise", corpus.string(), "--function", "greeting", "--emotion", "none", "--reference", "average", "-o",
         (corpus / "greeting_friendly_1.csv").string()},
        {"emotion", corpus.string(), "--pad", "--function", "greeting", "--emotion", "hostile", "--weight", "1", "-o",
         (corpus / "." / "greeting_hostile_1.csv").string()},
    };
    for (const auto& arguments : commands) {
        const auto run = runBunraku(arguments);
        INFO(arguments[0] << " " << arguments.back() << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK_THAT(run.err, Contains("input") && Contains("choose another"));
    }
    CHECK(readTextFile(take) == before);
    CHECK(readTextFile(dir / "x.bvh") == bvh);
    CHECK(snapshot(corpus) == corpusBefore); // truth/ included
}

TEST_CASE("a folder output never replaces a folder holding the user's files", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-foreign");
    const fs::path corpus = demoCorpus(dir);
    for (const std::string command : {"demo", "convert", "preprocess"}) {
        const fs::path out = dir / ("out-" + command);
        fs::create_directories(out / "sub");
        writeText(out / "notes.txt", "my notes");
        writeText(out / "sub" / "photo.jpg", "a photo");
        const auto run = command == "demo" ? runBunraku({"demo", "-o", out.string()})
                                           : runBunraku({command, corpus.string(), "-o", out.string()});
        INFO(command << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK_THAT(run.err, Contains("notes.txt") && Contains("sub/photo.jpg"));
        CHECK(readTextFile(out / "notes.txt") == "my notes");
        CHECK(readTextFile(out / "sub" / "photo.jpg") == "a photo");
        CHECK(snapshot(out).size() == 2);
    }
    // a folder the program wrote itself is replaced as a whole
    REQUIRE(runBunraku({"preprocess", corpus.string(), "-o", (dir / "pre").string()}).exitCode == 0);
    REQUIRE(runBunraku({"preprocess", corpus.string(), "--no-pad", "-o", (dir / "pre").string()}).exitCode == 0);
    CHECK(fs::exists(dir / "pre" / "truth" / "truth.json"));
}

TEST_CASE("a write that fails on a full disk leaves the previous file whole", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-full-disk");
    const fs::path corpus = demoCorpus(dir);
    const std::string reference = (corpus / "greeting_none_1.csv").string();
    const std::string sample = (corpus / "greeting_friendly_1.csv").string();
    const fs::path warp = dir / "w.csv", gains = dir / "g.json";
    REQUIRE(runBunraku({"phase", "--reference", reference, "--sample", sample, "-o", warp.string()}).exitCode == 0);
    REQUIRE(runBunraku({"gains", "--reference", reference, "--sample", sample, "--warp", warp.string(), "-o", gains.string()})
                .exitCode == 0);
    const std::string old = readTextFile(gains);
    REQUIRE(old.size() > 4096);
    // Files of this process may not grow past 4096 bytes: the disk is full for it.
    const auto run = runBunrakuWith("sh -c 'trap \"\" XFSZ; exec prlimit --fsize=4096 \"$0\" \"$@\"'",
                                    {"gains", "--reference", reference, "--sample", sample, "--warp", warp.string(), "-o",
                                     gains.string()});
    INFO(run.err);
    CHECK(isOneLineError(run.exitCode, run.err));
    CHECK_THAT(run.err, Contains("g.json"));
    CHECK(readTextFile(gains) == old);
    int others = 0;
    for (const auto& entry : fs::directory_iterator(dir)) others += entry.path().filename().string().rfind(".g.json", 0) == 0;
    CHECK(others == 0);
}

TEST_CASE("normalise killed as soon as its output appears has written all of it", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-normalise-kill");
    const fs::path corpus = demoCorpus(dir);
    const fs::path out = dir / "normalised";
    const std::string program = bunraku::test::bunrakuPath();
    const pid_t child = ::fork();
    if (child == 0) {
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execl(program.c_str(), program.c_str(), "normalise", corpus.c_str(), "--function", "greeting", "--emotion", "none", "-o",
                out.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Killed the moment the first output file shows (polled every 0.2 ms).
    int status = 0;
    bool exited = false;
    while (!fs::exists(out / "reference.csv")) {
        if (::waitpid(child, &status, WNOHANG) == child) {
            exited = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (!exited) {
        ::kill(child, SIGKILL);
        ::waitpid(child, &status, 0);
    }
    REQUIRE(fs::exists(out / "summary.json"));
    const auto summary = nlohmann::json::parse(readTextFile(out / "summary.json"));
    for (const auto& file : summary["files"]) CHECK(fs::exists(out / file.get<std::string>()));
    CHECK(summary["files"].size() == 12); // with summary.json the 13 files of a complete output
}

TEST_CASE("readers refuse a FIFO and devices at once, naming the file", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-special");
    REQUIRE(::mkfifo((dir / "take.csv").c_str(), 0600) == 0);
    const auto fifo = runBunrakuWith("", {"info", (dir / "take.csv").string()}, 20);
    INFO(fifo.err);
    CHECK(isOneLineError(fifo.exitCode, fifo.err));
    CHECK_THAT(fifo.err, Contains("take.csv") && Contains("FIFO"));
    fs::create_symlink("/dev/zero", dir / "zero.csv");
    const auto zero = runBunrakuWith("", {"info", (dir / "zero.csv").string()}, 20);
    CHECK(isOneLineError(zero.exitCode, zero.err));
    CHECK_THAT(zero.err, Contains("zero.csv") && Contains("device"));
    fs::create_directories(dir / "corpus");
    fs::create_symlink("/dev/urandom", dir / "corpus" / "corpus.json");
    const auto urandom = runBunrakuWith("", {"info", (dir / "corpus").string()}, 20);
    CHECK(isOneLineError(urandom.exitCode, urandom.err));
    CHECK_THAT(urandom.err, Contains("corpus.json") && Contains("device"));
}

TEST_CASE("errors of phase, --rate and allocation failures name the file", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-names");
    const fs::path corpus = demoCorpus(dir);
    const std::string reference = (corpus / "greeting_none_1.csv").string();
    const std::string sample = (corpus / "greeting_friendly_1.csv").string();

    // A scale the demo's takes are too short for (T_cmp beyond the matcher's limit is refused by
    // --tcmp itself).
    const auto phase = runBunraku({"phase", "--reference", reference, "--sample", sample, "--max-scale", "256", "-o",
                                   (dir / "w.csv").string()});
    CHECK(isOneLineError(phase.exitCode, phase.err));
    CHECK_THAT(phase.err, Contains("greeting_friendly_1.csv") && Contains("matching:"));

    writeText(dir / "s.txt", "1 0 0 0 0 0 0\n2 0 0 0 0 0 0\n3 0 0 0 0 0 0\n4 0 0 0 0 0 0\n");
    for (const std::string rate : {"0", "-5", "1e400", "2e6"}) {
        const auto run = runBunraku({"info", (dir / "s.txt").string(), "--rate", rate});
        INFO("--rate " << rate << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK_THAT(run.err, Contains("s.txt") && Contains("--rate"));
    }
    const auto fine = runBunraku({"info", (dir / "s.txt").string(), "--rate", "10", "--json"});
    REQUIRE(fine.exitCode == 0);
    CHECK(nlohmann::json::parse(fine.out)["rate_hz"] == 10.0);

    // An allocation that fails (address space limited to 300 MB) names the inputs.
    writeText(dir / "long.csv", "output_frame,source_frame\n0,0\n999999,100\n");
    const auto memory = runBunrakuWith("prlimit --as=300000000", {"design", reference, "--warp", (dir / "long.csv").string(), "-o",
                                                                  (dir / "d.csv").string()});
    INFO(memory.err);
    CHECK(isOneLineError(memory.exitCode, memory.err));
    CHECK_THAT(memory.err, Contains("out of memory") && Contains("greeting_none_1.csv"));
}

TEST_CASE("a FASTRAK rate of 0 is an error, not 5 Hz", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-fastrak-rate");
    writeText(dir / "f.txt", "1 0 0 0 0 0 0\n2 0 0 0 0 0 0\n3 0 0 0 0 0 0\n4 0 0 0 0 0 0\n");
    const auto run = runBunraku({"convert", (dir / "f.txt").string(), "--rate", "0", "-o", (dir / "f.csv").string()});
    CHECK(isOneLineError(run.exitCode, run.err));
    CHECK_THAT(run.err, Contains("f.txt") && Contains("--rate 0"));
    CHECK_FALSE(fs::exists(dir / "f.csv"));
}

TEST_CASE("design with a warp reaching output frame 1e7 or 1e9 is refused at once, naming the line", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-warp-bound");
    const fs::path corpus = demoCorpus(dir);
    const std::string take = (corpus / "greeting_none_1.csv").string();
    for (const std::string last : {"10000000", "1000000000", "2000000"}) {
        std::string warp = "output_frame,source_frame\n0,0\n";
        warp += last;
        warp += ",40\n";
        writeText(dir / "w.csv", warp);
        const auto run = runBunrakuWith("prlimit --as=2000000000", {"design", take, "--warp", (dir / "w.csv").string(), "-o",
                                                                    (dir / "d.csv").string()}, 60);
        INFO(last << ": " << run.err);
        CHECK(isOneLineError(run.exitCode, run.err));
        CHECK_THAT(run.err, Contains("w.csv:3") && Contains("output_frame"));
        CHECK_FALSE(fs::exists(dir / "d.csv"));
    }
}

TEST_CASE("folder names that are not UTF-8 are written and reported, never an error naming nothing", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-not-utf8");
    const std::string corpus = (dir / "corpus\xff").string();
    const auto demo = runBunraku({"demo", "-o", corpus, "--json"});
    INFO(demo.err);
    REQUIRE(demo.exitCode == 0);
    CHECK(nlohmann::json::parse(demo.out)["takes"] == 30); // the name shown with a replacement character
    const auto info = runBunraku({"info", corpus, "--json"});
    REQUIRE(info.exitCode == 0);
    const auto decomposed = runBunraku({"decompose", corpus, "--pad", "-o", (dir / "out\xff").string()});
    INFO(decomposed.err);
    REQUIRE(decomposed.exitCode == 0);
    CHECK(fs::exists(dir / "out\xff" / "summary.json"));
}

TEST_CASE("a BVH joint named with a comma converts to a CSV that reads back", "[cli][safety]")
{
    const auto dir = bunraku::test::scratchDir("cli-safety-comma-joint");
    writeText(dir / "comma.bvh", "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
                                 "Yrotation\n JOINT Left,Arm\n {\n  OFFSET 10 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                                 "  End Site\n  {\n   OFFSET 5 0 0\n  }\n }\n}\nMOTION\nFrames: 2\nFrame Time: 0.2\n"
                                 "0 0 0 0 0 0 0 0 0\n1 2 3 10 20 30 5 6 7\n");
    const auto convert = runBunraku({"convert", (dir / "comma.bvh").string(), "--all-joints", "-o", (dir / "comma.csv").string()});
    REQUIRE(convert.exitCode == 0);
    const auto info = runBunraku({"info", (dir / "comma.csv").string(), "--json"});
    INFO(info.err);
    REQUIRE(info.exitCode == 0);
    const auto names = nlohmann::json::parse(info.out)["channel_names"];
    REQUIRE(names.size() == 12);
    CHECK(names[6] == "Left,Arm.x");
    CHECK(names[11] == "Left,Arm.roll");
}
