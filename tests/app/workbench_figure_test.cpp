// bunraku-workbench --figure: the 3D view's figure for takes A and B from the command line (the
// guide's screenshots are made this way).
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <QImage>

#include <cstdlib>
#include <fstream>
#include <sys/wait.h>

namespace {

std::string quoted(const std::filesystem::path& path)
{
    std::string text(1, '\'');
    text.append(path.string());
    text.push_back('\'');
    return text;
}

int runWorkbench(const std::string& arguments, const std::filesystem::path& errors)
{
    std::string command = quoted(BUNRAKU_WORKBENCH);
    command.append(" ").append(arguments).append(" >/dev/null 2>").append(quoted(errors)).append(" </dev/null");
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST_CASE("bunraku-workbench --figure shows a Bandai take's skeleton in the window's screenshot", "[app][skeleton]")
{
    const auto source = bunraku::test::bandaiDir() / "bye_angry_001.bvh";
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(source))) return;
    const auto dir = bunraku::test::scratchDir("workbench_figure");
    for (const std::string figure : {"puppet", "skeleton"}) {
        const auto png = dir / (figure + ".png");
        INFO(figure);
        std::string arguments = quoted(source);
        arguments.append(" --figure ").append(figure).append(" --default-layout --screenshot ").append(quoted(png));
        REQUIRE(runWorkbench(arguments, dir / "err.txt") == 0);
        REQUIRE(std::filesystem::exists(png));
    }
    const QImage puppet(QString::fromStdString((dir / "puppet.png").string()));
    const QImage skeleton(QString::fromStdString((dir / "skeleton.png").string()));
    REQUIRE(puppet.size() == skeleton.size());
    CHECK(puppet != skeleton);
    CHECK(runWorkbench(std::string("--figure bones --screenshot ").append(quoted(dir / "x.png")), dir / "err.txt") == 1);
    std::ifstream errors(dir / "err.txt");
    const std::string text((std::istreambuf_iterator<char>(errors)), std::istreambuf_iterator<char>());
    CHECK(text.find("--figure 'bones': expected puppet, skeleton, both, body or mesh") != std::string::npos);
}
