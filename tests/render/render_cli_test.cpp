// `bunraku render` end to end: the built command line writes PNGs of the demo corpus, and bad
// input fails with one line and a non-zero exit. Skips (with a warning) when the command line
// has not been built in this build tree.
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "render/take_scene.h"
#include "analysis/io/take_csv.h"
#include "render_test_support.h"
#include "analysis/core/puppet_layout.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <QImage>
#include <QProcess>
#include <QStandardPaths>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sys/wait.h>
#include <fstream>
#include <sstream>
#include <string>

using namespace bunraku;

namespace {

std::filesystem::path cliPath() { return std::filesystem::path(BUNRAKU_BINARY_DIR) / "bin" / "bunraku"; }

/// Runs the command line; returns the exit code and what it printed on standard error.
/// A path in single quotes for the shell.
std::string quoted(const std::filesystem::path& path)
{
    std::ostringstream text;
    text << '\'' << path.string() << '\'';
    return text.str();
}

/// Runs the command line; returns the exit code and what it printed on standard error.
std::pair<int, std::string> runCli(const std::string& arguments, const std::filesystem::path& dir)
{
    const auto errors = dir / "stderr.txt";
    std::ostringstream command;
    command << quoted(cliPath()) << ' ' << arguments << " 2> " << quoted(errors) << " > " << quoted(dir / "stdout.txt");
    const int status = std::system(command.str().c_str());
    std::ifstream file(errors);
    std::stringstream text;
    text << file.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

int distinctColours(const QImage& image)
{
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

} // namespace

TEST_CASE("bunraku render writes a PNG of a demo take and a frame sequence", "[render][cli]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    const auto dir = test::scratchDir("render_cli");
    const auto [code, errors] = runCli("render demo:greeting/friendly/2 --take-b demo:greeting/hostile/2 --frame 30 "
                                       "--camera 90 --size 320x200 --show puppet,axis,orbits,grid -o " +
                                           quoted(dir / "two.png"),
                                       dir);
    INFO(errors);
    REQUIRE(code == 0);
    const QImage image(QString::fromStdString((dir / "two.png").string()));
    REQUIRE(image.size() == QSize(320, 200));
    CHECK(distinctColours(image) > 20); // shaded puppets, not a blank frame

    const auto [sequenceCode, sequenceErrors] =
        runCli("render demo:serving-tea/none/1 --frames 3:5 --size 64x48 -o " + quoted(dir / "seq"), dir);
    INFO(sequenceErrors);
    REQUIRE(sequenceCode == 0);
    for (const char* name : {"frame_00000.png", "frame_00001.png", "frame_00002.png"})
        CHECK(QImage(QString::fromStdString((dir / "seq" / name).string())).size() == QSize(64, 48));
    CHECK_FALSE(std::filesystem::exists(dir / "seq" / "frame_00003.png"));
}

TEST_CASE("bunraku render draws the figures' shadows on the floor unless --show leaves them out", "[render][cli][shadow]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    const auto dir = test::scratchDir("render_cli_shadows");
    const std::string take = "render demo:greeting/friendly/2 --frame 40 --camera 200 --elevation 60 --size 320x240 --samples 0 ";
    for (const char* show : {"puppet,grid,shadows", "puppet,grid"}) {
        const auto [code, errors] = runCli(take + "--show " + show + " -o " + quoted(dir / (std::string(show) + ".png")), dir);
        INFO(errors);
        REQUIRE(code == 0);
    }
    const QImage with(QString::fromStdString((dir / "puppet,grid,shadows.png").string()));
    const QImage without(QString::fromStdString((dir / "puppet,grid.png").string()));
    REQUIRE(with.size() == without.size());
    int darker = 0, lighter = 0;
    for (int y = 0; y < with.height(); ++y)
        for (int x = 0; x < with.width(); ++x) {
            const int a = qGray(with.pixel(x, y)), b = qGray(without.pixel(x, y));
            darker += a < b - 20 ? 1 : 0;
            lighter += a > b + 1 ? 1 : 0;
        }
    CHECK(darker > 200);
    CHECK(lighter == 0);
    // "shadows" is one of the names --show knows (its default draws them).
    const auto [code, errors] = runCli("render demo:greeting/friendly/2 --show puppet,shadow -o " + quoted(dir / "x.png"), dir);
    CHECK(code != 0);
    CHECK(errors.find("grid, shadows, partner") != std::string::npos);
}

TEST_CASE("bunraku render --follow keeps a walking take in the middle of the picture", "[render][cli][travel]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    const auto dir = test::scratchDir("render_cli_follow");
    REQUIRE(analysis::io::writeTakeCsv(test::travellingTake(60, 400.0), dir / "walk.csv").ok());
    // The middle column of the figure's pixels, as a fraction of the width from the centre.
    const auto offset = [&dir](const std::string& options) {
        const auto [code, errors] = runCli("render " + quoted(dir / "walk.csv") + " --frame 59 --camera 0 --elevation 10 "
                                           "--distance 300 --show puppet --size 200x150 --samples 0 " + options + " -o " +
                                               quoted(dir / "walk.png"), dir);
        INFO(errors);
        REQUIRE(code == 0);
        const QImage image(QString::fromStdString((dir / "walk.png").string()));
        double sum = 0.0;
        int count = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (!test::isBackground(image.pixel(x, y))) {
                    sum += x;
                    ++count;
                }
        if (count < 50) return 1.0; // out of the picture
        return std::abs(sum / count - 0.5 * image.width()) / image.width();
    };
    CHECK(offset("--follow") < 0.05);
    CHECK(offset("") > 0.2); // the camera stays where it was framed: the walker has left
}

TEST_CASE("bunraku render rejects bad input with a one-line error", "[render][cli]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    const auto dir = test::scratchDir("render_cli_errors");
    const std::string out = " -o " + quoted(dir / "x.png");
    const std::string demo = "render demo:greeting/none/1";
    for (const std::string& arguments :
         {"render demo:greeting/sleepy/1" + out, demo + " --size 10" + out, demo + " --frame 100000" + out,
          demo + " --show puppet,kimono" + out, "render " + quoted(dir / "absent.csv") + out}) {
        const auto [code, errors] = runCli(arguments, dir);
        INFO(arguments << "\n" << errors);
        CHECK(code != 0);
        CHECK(errors.find("bunraku: error: ") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir / "x.png"));
    }
}

TEST_CASE("bunraku render --mp4 without ffmpeg on PATH says how to get it and writes nothing", "[render][cli]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    const auto dir = test::scratchDir("render_cli_mp4");
    // An empty PATH: ffmpeg cannot be found whether or not the machine has it.
    const auto [code, errors] = runCli("--help > /dev/null; PATH= " + quoted(cliPath()) +
                                           " render demo:greeting/none/1 --frames 0:3 --mp4 " + quoted(dir / "take.mp4") +
                                           " -o " + quoted(dir / "frames"),
                                       dir);
    INFO(errors);
    CHECK(code != 0);
    CHECK(errors.find("bunraku: error: --mp4 needs ffmpeg") != std::string::npos);
    CHECK(std::count(errors.begin(), errors.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(dir / "take.mp4"));
}

TEST_CASE("bunraku render --frames --mp4 writes the frames and their MP4 into paths with a quote and a space", "[render][cli][video]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    if (!test::requirePeer(!QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty() &&
                               !QStandardPaths::findExecutable(QStringLiteral("ffprobe")).isEmpty(),
                           "ffmpeg and ffprobe on PATH (render --mp4)", "apt-get install ffmpeg"))
        return;
    // The encoder once ran through a shell, and a quote in a path broke it.
    const auto dir = test::scratchDir("render_cli_mp4_quote") / "it's a take";
    std::filesystem::create_directories(dir);
    QProcess cli;
    cli.start(QString::fromStdString(cliPath().string()),
              {"render", "demo:greeting/friendly/1", "--frames", "2:7", "--size", "322x240", "--samples", "0", "-o",
               QString::fromStdString((dir / "frames").string()), "--mp4", QString::fromStdString((dir / "take's.mp4").string())});
    REQUIRE(cli.waitForFinished(300000));
    INFO(cli.readAllStandardError().toStdString());
    REQUIRE(cli.exitCode() == 0);
    for (int k = 0; k < 6; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", k);
        CHECK(QImage(QString::fromStdString((dir / "frames" / name).string())).size() == QSize(322, 240));
    }
    CHECK_FALSE(std::filesystem::exists(dir / "frames" / "frame_00006.png"));
    // ffprobe, the peer: six frames of the size asked for (even already: nothing cropped).
    QProcess probe;
    probe.start(QStringLiteral("ffprobe"), {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                            "stream=nb_read_frames,width,height", "-of", "csv=p=0",
                                            QString::fromStdString((dir / "take's.mp4").string())});
    REQUIRE(probe.waitForFinished(30000));
    CHECK(QString::fromLatin1(probe.readAllStandardOutput()).trimmed() == QStringLiteral("322,240,6"));
    // Only the two outputs: no temporary file or folder of the encoder is left beside them.
    std::set<std::string> entries;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) entries.insert(entry.path().filename().string());
    CHECK(entries == std::set<std::string>{"frames", "take's.mp4"});
}

TEST_CASE("a take scene carries the motion axis of every take, one pose per frame", "[render][scene]")
{
    analysis::Take take;
    take.channels = analysis::puppetChannels();
    take.values = Eigen::MatrixXd::Zero(4, analysis::kPuppetChannelCount);
    for (Eigen::Index f = 0; f < 4; ++f) {
        take.values(f, 2) = 103.0;       // head z
        take.values(f, 8) = 100.0;       // shoulder z
        take.values(f, 13) = -13.0;      // arm y
        take.values(f, 14) = 95.0;       // arm z
        take.values(f, 19) = -13.0;      // hand y
        take.values(f, 20) = 67.0 + f;   // hand z
    }
    const auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), {take, take});
    REQUIRE(scene.ok());
    REQUIRE(scene->takes.size() == 2);
    for (const auto& slot : scene->takes) {
        REQUIRE(slot.world_T_axis.size() == 4);
        // A symmetric upright puppet: the centre of mass is on its sagittal plane, axis z up.
        CHECK(slot.world_T_axis[0].translation.y() == Approx(0.0).margin(0.5));
        CHECK((slot.world_T_axis[0].rotation * Eigen::Vector3d::UnitZ()).z() > 0.9);
    }
    const auto tooMany = render::makeTakeScene(analysis::defaultBodyDescription(), {take, take, take});
    CHECK_FALSE(tooMany.ok());
}

TEST_CASE("bunraku render --figure draws a Bandai take's 22-joint skeleton, the puppet, or both", "[render][cli][skeleton]")
{
    const auto source = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(source)))
        return;
    const auto dir = test::scratchDir("render_cli_figure");
    std::map<std::string, QImage> images;
    for (const std::string figure : {"puppet", "skeleton", "both"}) {
        const auto png = dir / (figure + ".png");
        const auto [code, errors] = runCli("render " + quoted(source) + " --figure " + figure + " --show puppet,grid --size 320x240 --samples 0 --json -o " +
                                               quoted(png),
                                           dir);
        INFO(errors);
        REQUIRE(code == 0);
        std::ifstream out(dir / "stdout.txt");
        std::stringstream summary;
        summary << out.rdbuf();
        INFO(summary.str());
        CHECK(summary.str().find(std::string("\"skeleton\": ") + (figure == "puppet" ? "false" : "true")) != std::string::npos);
        CHECK(summary.str().find(std::string("\"puppet\": ") + (figure == "skeleton" ? "false" : "true")) != std::string::npos);
        images[figure] = QImage(QString::fromStdString(png.string()));
        REQUIRE(!images[figure].isNull());
    }
    // The whole performer is in the picture: rows from the head to the feet differ from the
    // background grey... (the floor grid aside); the skeleton's picture differs from the puppet's.
    const auto figureRows = [](const QImage& image) {
        int first = image.height(), last = -1;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb p = image.pixel(x, y);
                if (std::abs(qRed(p) - qBlue(p)) > 25 || qGray(p) < 150) { // coloured or dark: the figure, not the grid or background
                    first = std::min(first, y);
                    last = std::max(last, y);
                }
            }
        return last - first;
    };
    CHECK(figureRows(images["skeleton"]) > images["skeleton"].height() / 3);
    CHECK(images["skeleton"] != images["puppet"]);
    CHECK(images["both"] != images["skeleton"]);
    const auto [code, errors] = runCli("render " + quoted(source) + " --figure bones -o " + quoted(dir / "x.png"), dir);
    CHECK(code != 0);
    CHECK(errors.find("--figure 'bones': expected puppet, skeleton, both, body or mesh") != std::string::npos);
}

TEST_CASE("bunraku render --kimono dresses the puppet in its simulated kimono", "[render][cli][kimono]")
{
    if (!test::requirePeer(std::filesystem::exists(cliPath()), "the bunraku executable (" + cliPath().string() + ")",
                           "build the target bunraku"))
        return;
    const auto dir = test::scratchDir("render_cli_kimono");
    const std::string common = "render demo:greeting/friendly/2 --frame 30 --camera 300 --size 320x320 --samples 0 --show puppet ";
    const auto [plainCode, plainErrors] = runCli(common + "-o " + quoted(dir / "skinned.png"), dir);
    INFO(plainErrors);
    REQUIRE(plainCode == 0);
    const auto [code, errors] = runCli(common + "--kimono -o " + quoted(dir / "cloth.png"), dir);
    INFO(errors);
    REQUIRE(code == 0);
    const auto [softCode, softErrors] = runCli(common + "--kimono --cloth-bend 0.01 --cloth-damping 0.2 -o " + quoted(dir / "soft.png"), dir);
    INFO(softErrors);
    REQUIRE(softCode == 0);
    const QImage skinned(QString::fromStdString((dir / "skinned.png").string()));
    const QImage cloth(QString::fromStdString((dir / "cloth.png").string()));
    const QImage soft(QString::fromStdString((dir / "soft.png").string()));
    REQUIRE(skinned.size() == cloth.size());
    REQUIRE(soft.size() == cloth.size());
    const auto differing = [](const QImage& a, const QImage& b) {
        int count = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x) count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
        return count;
    };
    INFO("cloth against skinned: " << differing(cloth, skinned) << " pixels; softer cloth: " << differing(cloth, soft));
    CHECK(differing(cloth, skinned) > 200);
    CHECK(differing(cloth, soft) > 50); // the cloth options reach the simulation

    const auto [badCode, badErrors] = runCli(common + "--kimono --cloth-damping -1 -o " + quoted(dir / "bad.png"), dir);
    CHECK(badCode != 0);
    CHECK(badErrors.find("--cloth-damping") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "bad.png"));
}
