#include "tests/cli/cli_runner.h"
#include "tests/support/test_paths.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

namespace bunraku::test {
namespace {

std::string slurp(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

} // namespace

CliRun runBunraku(const std::vector<std::string>& arguments)
{
    static int counter = 0;
    const auto dir = std::filesystem::path(BUNRAKU_BINARY_DIR) / "test-scratch" / "cli-output";
    std::filesystem::create_directories(dir);
    const auto outPath = dir / ("out" + std::to_string(counter) + ".txt");
    const auto errPath = dir / ("err" + std::to_string(counter) + ".txt");
    ++counter;
    std::string command = "'" BUNRAKU_CLI "'";
    for (const auto& a : arguments) {
        if (a.find('\'') != std::string::npos) throw std::invalid_argument("quote in argument: " + a);
        command += " '" + a + "'";
    }
    command += " >'" + outPath.string() + "' 2>'" + errPath.string() + "' </dev/null";
    const int status = std::system(command.c_str());
    CliRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = slurp(outPath);
    run.err = slurp(errPath);
    return run;
}

} // namespace bunraku::test
