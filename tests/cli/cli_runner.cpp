#include "tests/cli/cli_runner.h"
#include "tests/support/test_paths.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

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

std::string bunrakuPath()
{
    const char* other = std::getenv("BUNRAKU_CLI_UNDER_TEST");
    return other != nullptr && *other ? other : BUNRAKU_CLI;
}

CliRun runBunraku(const std::vector<std::string>& arguments) { return runBunrakuWith("", arguments); }

CliRun runBunrakuWith(const std::string& prefix, const std::vector<std::string>& arguments, int timeoutSeconds)
{
    static int counter = 0;
    const auto dir = std::filesystem::path(BUNRAKU_BINARY_DIR) / "test-scratch" / "cli-output";
    std::filesystem::create_directories(dir);
    // ctest runs each case in its own process, two at a time: name the files by process too.
    const std::string stem = std::to_string(::getpid()) + "-" + std::to_string(counter);
    const auto outPath = dir / ("out-" + stem + ".txt");
    const auto errPath = dir / ("err-" + stem + ".txt");
    ++counter;
    // BUNRAKU_CLI_UNDER_TEST runs the cases against another build (an older one shows which
    // cases it fails); `timeout` turns a hang (a reader blocked on a FIFO) into a failure.
    std::string command = "timeout -k 5 " + std::to_string(timeoutSeconds) + " " + prefix + " '" + bunrakuPath() + "'";
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
