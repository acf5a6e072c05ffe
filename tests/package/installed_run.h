#pragma once
/// Runs the programs of the unpacked package (the fixture "package: build the .deb and unpack it
/// outside the build tree" puts it in BUNRAKU_PACKAGE_STAGE/root) as a user's system would:
/// from that root alone, in a scrubbed environment (env -i: PATH=ROOT/usr/bin:/usr/bin:/bin, a
/// fresh HOME, the X display), under strace, so a test can prove that nothing was read from the
/// build or source tree. Also runs the machine's tools (dpkg-deb, lintian, validators).
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::test {

/// STAGE/root: ROOT/usr/bin/bunraku, ROOT/usr/share/...
std::filesystem::path installedRoot();
/// STAGE/package.deb and STAGE/package-dbgsym.ddeb (copies of what the package target made).
std::filesystem::path packageFile();
std::filesystem::path dbgsymFile();
/// An empty folder in the stage (outside the build and source trees) for one test's files.
std::filesystem::path stageDir(const std::string& name);

struct ProgramRun {
    int exitCode = -1;
    std::string out;
    std::string err;
    /// Every absolute path in the strace log of the run (arguments and results of file calls).
    std::vector<std::string> paths;
    /// The strace log, for messages.
    std::string trace;
};

enum class Display { Given, None };

/// Runs ROOT/usr/bin/`program` with `arguments` from `home` (also its HOME), with the X display
/// of the tests (Display::Given) or without any.
ProgramRun runInstalled(const std::string& program, const std::vector<std::string>& arguments,
                        const std::filesystem::path& home, Display display = Display::Given);
/// The paths of `run` that lie in the build tree or the source tree (none for a clean run).
std::vector<std::string> pathsInBuildOrSourceTree(const ProgramRun& run);
/// Whether `run` opened or examined `path` and the call succeeded.
bool foundInTrace(const ProgramRun& run, const std::filesystem::path& path);

/// Runs a shell command line of the machine's tools; captures both streams.
ProgramRun runTool(const std::string& commandLine);
/// Whether the machine has `tool` on PATH.
bool hasTool(const std::string& tool);

/// A peer is missing: under CI=true the test fails; otherwise it says why and the process
/// exits with 77, which ctest reports as skipped (SKIP_RETURN_CODE).
void failOrSkip(const std::string& why);

/// `text` in single quotes for the shell (a quote inside is refused).
std::string shellQuoted(const std::string& text);

} // namespace bunraku::test
