#include "tests/package/installed_run.h"
#include "tests/support/peer.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace bunraku::test {
namespace fs = std::filesystem;
namespace {

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

int exitCodeOf(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

/// A fresh folder for the streams and traces of the runs of this process.
fs::path logDir()
{
    static const fs::path dir = [] {
        const fs::path path = fs::path(BUNRAKU_PACKAGE_STAGE) / ("logs-" + std::to_string(::getpid()));
        fs::create_directories(path);
        return path;
    }();
    return dir;
}

fs::path nextLog(const std::string& suffix)
{
    static int counter = 0;
    return logDir() / (std::to_string(counter++) + suffix);
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

} // namespace

fs::path installedRoot() { return fs::path(BUNRAKU_PACKAGE_STAGE) / "root"; }
fs::path packageFile() { return fs::path(BUNRAKU_PACKAGE_STAGE) / "package.deb"; }
fs::path dbgsymFile() { return fs::path(BUNRAKU_PACKAGE_STAGE) / "package-dbgsym.ddeb"; }

fs::path stageDir(const std::string& name)
{
    const fs::path dir = fs::path(BUNRAKU_PACKAGE_STAGE) / "scratch" / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string shellQuoted(const std::string& text)
{
    if (text.find('\'') != std::string::npos) throw std::invalid_argument("quote in shell argument: " + text);
    std::string quoted = "'";
    quoted += text;
    quoted += '\'';
    return quoted;
}

bool hasTool(const std::string& tool) { return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0; }

void failOrSkip(const std::string& why)
{
    // The one peer rule (tests/support/peer.h): fails under CI=true, else says why it is skipped.
    bunraku::test::requirePeer(false, why, "scripts/install-deps.sh installs it");
    std::fflush(stdout);
    std::_Exit(77);
}

ProgramRun runTool(const std::string& commandLine)
{
    const fs::path out = nextLog(".out");
    const fs::path err = nextLog(".err");
    const std::string command = "(" + commandLine + ") > " + shellQuoted(out.string()) + " 2> " + shellQuoted(err.string()) + " < /dev/null";
    ProgramRun run;
    run.exitCode = exitCodeOf(std::system(command.c_str()));
    run.out = slurp(out);
    run.err = slurp(err);
    return run;
}

ProgramRun runInstalled(const std::string& program, const std::vector<std::string>& arguments, const fs::path& home,
                        Display display)
{
    const fs::path root = installedRoot();
    const fs::path runtime = home / ".runtime";
    fs::create_directories(runtime);
    fs::permissions(runtime, fs::perms::owner_all, fs::perm_options::replace);
    const fs::path trace = nextLog(".strace");

    std::string environment = "env -i PATH=" + shellQuoted((root / "usr/bin").string() + ":/usr/bin:/bin") +
                              " HOME=" + shellQuoted(home.string()) + " XDG_RUNTIME_DIR=" + shellQuoted(runtime.string()) +
                              " LANG=C.UTF-8";
    for (const char* name : {"DISPLAY", "XAUTHORITY"})
        if (const char* value = std::getenv(name); value != nullptr && display == Display::Given) environment += std::string(" ") + name + "=" + shellQuoted(value);
    std::string command = "cd " + shellQuoted(home.string()) + " && " + environment + " strace -f -qq -s 4096 -e trace=%file -o " +
                          shellQuoted(trace.string()) + " " + shellQuoted((root / "usr/bin" / program).string());
    // Appended piecewise: GCC 12 reports a false -Wrestrict on `" " + string` here at -O3.
    for (const std::string& argument : arguments) {
        command += ' ';
        command += shellQuoted(argument);
    }

    ProgramRun run = runTool(command);
    run.trace = slurp(trace);
    static const std::regex quotedPath("\"(/[^\"]*)\"");
    for (std::sregex_iterator it(run.trace.begin(), run.trace.end(), quotedPath), end; it != end; ++it)
        run.paths.push_back((*it)[1].str());
    return run;
}

std::vector<std::string> pathsInBuildOrSourceTree(const ProgramRun& run)
{
    std::vector<std::string> trees;
    for (const fs::path& tree : {fs::path(BUNRAKU_BINARY_DIR), fs::path(BUNRAKU_SOURCE_DIR)}) {
        trees.push_back(tree.lexically_normal().string());
        std::error_code error;
        const fs::path canonical = fs::canonical(tree, error);
        if (!error) trees.push_back(canonical.string());
    }
    std::vector<std::string> found;
    for (const std::string& path : run.paths)
        for (const std::string& tree : trees)
            if (path == tree || startsWith(path, tree + "/")) found.push_back(path);
    return found;
}

bool foundInTrace(const ProgramRun& run, const fs::path& path)
{
    // With -f a call interrupted by another thread's is logged in two lines, "PID call(args
    // <unfinished ...>" and "PID <... call resumed>...) = result": join them by PID first.
    std::istringstream lines(run.trace);
    std::map<std::string, std::string> pending;
    std::string quoted = "\"";
    quoted += path.string();
    quoted += '"';
    for (std::string line; std::getline(lines, line);) {
        const std::string pid = line.substr(0, line.find(' '));
        if (const auto unfinished = line.find(" <unfinished ...>"); unfinished != std::string::npos) {
            pending[pid] = line.substr(0, unfinished);
            continue;
        }
        if (line.find(" resumed>") != std::string::npos && pending.count(pid) != 0) {
            line = pending[pid] + line.substr(line.find(" resumed>") + 9);
            pending.erase(pid);
        }
        if (line.find(quoted) != std::string::npos && line.find(" = -1 ") == std::string::npos) return true;
    }
    return false;
}

} // namespace bunraku::test
