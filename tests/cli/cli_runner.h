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

/// Arguments are single-quoted for the shell; none may contain a single quote.
CliRun runBunraku(const std::vector<std::string>& arguments);

} // namespace bunraku::test
