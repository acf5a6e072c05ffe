#include "app/cli/cli.h"

#include "app/build_info.h"

#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>

namespace bunraku::app::cli {

namespace {

/// An allocation failed somewhere in a command: say so, naming the command and the files and
/// folders on its command line (the inputs that asked for that much memory).
std::string outOfMemoryMessage(int argc, char** argv)
{
    std::string command = argc > 1 ? argv[1] : "";
    std::string inputs;
    for (int i = 2; i < argc; ++i) {
        std::error_code ec;
        if (std::filesystem::exists(argv[i], ec)) inputs += (inputs.empty() ? "" : ", ") + std::string(argv[i]);
    }
    return "out of memory while running `bunraku " + command + "`" + (inputs.empty() ? std::string() : " on " + inputs) +
           ": the input is larger than this machine can hold (or asks for more than its content justifies)";
}

} // namespace

void printJson(const nlohmann::json& document)
{
    std::cout << document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
}

int runCli(int argc, char** argv)
{
    CLI::App app{"Bunraku Motion Workbench command line: make, inspect, convert, normalise, decompose, "
                 "design and render motion takes.",
                 "bunraku"};
    app.set_version_flag("--version", versionText("bunraku"));
    app.set_help_all_flag("--help-all", "Print the help of every subcommand and exit");
    app.require_subcommand(1);
    app.footer("Exit status: 0 done; 1 bad input (a file or value the command cannot use); 2 bad command line (unknown "
               "option, missing argument); 3 a file could not be read or written. Errors are one line on standard error; "
               "progress goes to standard error only when it is a terminal; --json summaries go to standard output.");
    CLI::App* experiment = app.add_subcommand("experiment", "Reproduce the thesis's experiments");
    experiment->require_subcommand(1);
    CommandSet commands{app, *experiment};
    addAllCommands(commands);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "bunraku: error: " << e.what() << "\n";
        return kExitUsage;
    } catch (const CliError& e) {
        std::cerr << "bunraku: error: " << e.what() << "\n";
        return e.exitCode;
    } catch (const std::bad_alloc&) {
        std::cerr << "bunraku: error: " << outOfMemoryMessage(argc, argv) << "\n";
        return kExitBadInput;
    } catch (const std::length_error&) {
        std::cerr << "bunraku: error: " << outOfMemoryMessage(argc, argv) << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "bunraku: error: " << e.what() << "\n";
        return kExitBadInput;
    }
    return kExitOk;
}

} // namespace bunraku::app::cli
