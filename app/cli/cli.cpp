#include "app/cli/cli.h"

#include "app/build_info.h"

#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string_view>

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

/// The error as the one line printed: line breaks become spaces, and any run of more than 300
/// characters without a space (a 1 MB label, a path of a 1 MB name) keeps its first 160 and last
/// 100 characters around "...", so the line stays readable and still ends with the file name.
std::string errorLine(const std::string& message)
{
    constexpr std::size_t kLongest = 300, kHead = 160, kTail = 100;
    std::string line;
    std::size_t start = 0;
    while (start < message.size()) {
        std::size_t end = message.find(' ', start);
        if (end == std::string::npos) end = message.size();
        std::string_view word(message.data() + start, end - start);
        if (word.size() > kLongest) {
            std::size_t head = kHead, tail = word.size() - kTail;
            // never cut a UTF-8 character
            while (head > 0 && (static_cast<unsigned char>(word[head]) & 0xC0) == 0x80) --head;
            while (tail < word.size() && (static_cast<unsigned char>(word[tail]) & 0xC0) == 0x80) ++tail;
            line.append(word.substr(0, head)).append("...").append(word.substr(tail));
        } else {
            line.append(word);
        }
        if (end < message.size()) line.push_back(' ');
        start = end + 1;
    }
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    return line;
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
    } catch (const CLI::Success& e) { // --help, --help-all, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "bunraku: error: " << errorLine(e.what()) << "\n";
        return kExitUsage;
    } catch (const CliError& e) {
        std::cerr << "bunraku: error: " << errorLine(e.what()) << "\n";
        return e.exitCode;
    } catch (const std::bad_alloc&) {
        std::cerr << "bunraku: error: " << errorLine(outOfMemoryMessage(argc, argv)) << "\n";
        return kExitBadInput;
    } catch (const std::length_error&) {
        std::cerr << "bunraku: error: " << errorLine(outOfMemoryMessage(argc, argv)) << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "bunraku: error: " << errorLine(e.what()) << "\n";
        return kExitBadInput;
    }
    return kExitOk;
}

} // namespace bunraku::app::cli
