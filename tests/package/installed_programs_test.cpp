// The programs of the unpacked package, run from its root alone: a scrubbed environment, a fresh
// HOME and working folder outside the build and source trees, and strace proving that no file of
// either tree was touched. The Bandai Namco Research Motion Dataset (CC BY-NC 4.0,
// ../shared/data/bandai, never part of the repository) is read from a scratch copy.
#include "tests/package/installed_run.h"

#include "app/build_info.h"

#include <catch2/catch.hpp>

#include <QImage>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace bunraku::test;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

void requireStrace()
{
    if (!hasTool("strace")) failOrSkip("strace is not installed (scripts/install-deps.sh installs it)");
}

/// The run touched nothing in the build or source tree, and ran the installed program.
void requireOnlyInstalled(const ProgramRun& run, const std::string& program)
{
    const auto leaks = pathsInBuildOrSourceTree(run);
    INFO("paths in the build or source tree: " << (leaks.empty() ? std::string("none") : leaks.front()) << " ("
                                               << leaks.size() << " in all)");
    CHECK(leaks.empty());
    CHECK(foundInTrace(run, installedRoot() / "usr/bin" / program));
}

/// Distinct colours on a coarse grid of `image`.
int distinctColours(const QImage& image)
{
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

} // namespace

TEST_CASE("the installed bunraku writes the demo corpus, reading nothing from the build or source tree", "[package][installed]")
{
    requireStrace();
    const fs::path home = stageDir("demo");
    const ProgramRun run = runInstalled("bunraku", {"demo", "-o", "demo", "--json"}, home);
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    requireOnlyInstalled(run, "bunraku");
    // 2 functions x 3 emotions x 5 takes, each a CSV beside the manifest.
    const std::string manifest = slurp(home / "demo/corpus.json");
    REQUIRE(manifest.find("\"bunraku-corpus\"") != std::string::npos);
    int takes = 0;
    for (const auto& entry : fs::directory_iterator(home / "demo"))
        if (entry.path().extension() == ".csv") ++takes;
    CHECK(takes == 30);
}

TEST_CASE("the installed bunraku describes a Bandai BVH as JSON with the frames, rate and joints of its header",
          "[package][installed][bandai]")
{
    requireStrace();
    const fs::path source = fs::path(BUNRAKU_SHARED_DIR) / "data/bandai/bye_normal_001.bvh";
    if (!fs::exists(source)) failOrSkip(source.string() + " is absent (the shared Bandai data, CC BY-NC 4.0)");
    const fs::path home = stageDir("bandai");
    fs::copy_file(source, home / "bye_normal_001.bvh");

    // The peer: the file's own header.
    const std::string bvh = slurp(source);
    std::smatch frames;
    std::smatch frameTime;
    REQUIRE(std::regex_search(bvh, frames, std::regex(R"(Frames:\s*(\d+))")));
    REQUIRE(std::regex_search(bvh, frameTime, std::regex(R"(Frame Time:\s*([0-9.]+))")));
    const std::regex joint(R"((^|\n)\s*(ROOT|JOINT)\s)");
    const auto joints = std::distance(std::sregex_iterator(bvh.begin(), bvh.end(), joint), std::sregex_iterator());

    const ProgramRun run = runInstalled("bunraku", {"info", "bye_normal_001.bvh", "--json"}, home);
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    requireOnlyInstalled(run, "bunraku");
    std::smatch value;
    REQUIRE(std::regex_search(run.out, value, std::regex(R"("frames": (\d+))")));
    CHECK(value[1].str() == frames[1].str());
    REQUIRE(std::regex_search(run.out, value, std::regex(R"("joint_count": (\d+))")));
    CHECK(std::stol(value[1].str()) == joints);
    REQUIRE(std::regex_search(run.out, value, std::regex(R"("rate_hz": ([0-9.]+))")));
    CHECK(std::stod(value[1].str()) == Approx(1.0 / std::stod(frameTime[1].str())).epsilon(1e-5));
    CHECK(run.out.find("\"format\": \"bvh\"") != std::string::npos);
}

TEST_CASE("the installed bunraku renders a demo take offscreen with its own shaders and puppet", "[package][installed][render]")
{
    requireStrace();
    const fs::path home = stageDir("render");
    const ProgramRun run = runInstalled("bunraku", {"render", "demo:greeting/none/1", "--size", "320x240", "-o", "take.png"}, home);
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    requireOnlyInstalled(run, "bunraku");
    const QImage image(QString::fromStdString((home / "take.png").string()));
    CHECK(image.size() == QSize(320, 240));
    CHECK(distinctColours(image) > 20); // a shaded puppet, not a blank frame
}

TEST_CASE("the installed workbench starts, finds its user guide and writes a screenshot of its window", "[package][installed][gui]")
{
    requireStrace();
    if (std::getenv("DISPLAY") == nullptr) failOrSkip("no X display (run the tests under xvfb-run)");
    const fs::path home = stageDir("workbench");
    const ProgramRun run = runInstalled("bunraku-workbench", {"--screenshot", "window.png"}, home);
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    requireOnlyInstalled(run, "bunraku-workbench");
    CHECK(run.err.find("warning") == std::string::npos);
    // Help > User Guide is enabled only when the guide is found: here, in the unpacked root.
    CHECK(foundInTrace(run, installedRoot() / "usr/share/bunraku/doc/USER-GUIDE.md"));
    const QImage image(QString::fromStdString((home / "window.png").string()));
    REQUIRE(!image.isNull());
    CHECK(image.width() >= 1000);
    CHECK(image.height() >= 600);
    CHECK(distinctColours(image) > 100); // graphs, the puppet and the docks, not an empty window
}

TEST_CASE("both installed programs answer --version with the version and commit, and bunraku help SUBCOMMAND", "[package][installed]")
{
    requireStrace();
    const fs::path home = stageDir("version");
    const std::string commit(bunraku::app::buildCommit());
    for (const char* program : {"bunraku", "bunraku-workbench"}) {
        // Without a display: --version must not need one.
        const ProgramRun run = runInstalled(program, {"--version"}, home, Display::None);
        INFO(program << "\n" << run.out << run.err);
        REQUIRE(run.exitCode == 0);
        CHECK(firstLine(run.out) == std::string(program) + " " + BUNRAKU_PROJECT_VERSION);
        CHECK(run.out.find("commit " + commit) != std::string::npos);
        CHECK(run.out.find("GPL-3.0-or-later") != std::string::npos);
        requireOnlyInstalled(run, program);
    }
    const ProgramRun workbenchHelp = runInstalled("bunraku-workbench", {"--help"}, home, Display::None);
    INFO(workbenchHelp.err);
    CHECK(workbenchHelp.exitCode == 0);
    CHECK(workbenchHelp.out.find("--screenshot <file>") != std::string::npos);

    const ProgramRun help = runInstalled("bunraku", {"help", "normalise"}, home);
    const ProgramRun direct = runInstalled("bunraku", {"normalise", "--help"}, home);
    REQUIRE(help.exitCode == 0);
    CHECK(help.out == direct.out);
    CHECK(help.out.find("Usage: bunraku normalise") != std::string::npos);
}
