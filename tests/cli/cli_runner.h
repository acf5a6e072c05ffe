#pragma once
/// Runs the built `bunraku` executable with arguments and captures its exit code, standard
/// output and standard error.
#include <string>
#include <vector>

namespace bunraku::test {

struct CliRun {
    int exitCode = -1;
    std::string out;
    std::string err;
};

/// Arguments are single-quoted for the shell; none may contain a single quote. A run longer than
/// 300 s is killed (exit code 124 or 137). The environment variable BUNRAKU_CLI_UNDER_TEST names
/// another `bunraku` to run instead of the one built with the tests.
CliRun runBunraku(const std::vector<std::string>& arguments);
/// runBunraku with a shell `prefix` before the executable (e.g. "prlimit --fsize=4096") and a
/// time limit in seconds.
CliRun runBunrakuWith(const std::string& prefix, const std::vector<std::string>& arguments, int timeoutSeconds = 300);
/// The `bunraku` under test (BUNRAKU_CLI_UNDER_TEST or the one built with the tests).
std::string bunrakuPath();

} // namespace bunraku::test
