#pragma once
/// Shared plumbing of the `bunraku` command line: every subcommand registers itself on the root
/// (or on `experiment`), reports bad input by throwing CliError (printed as one line, exit 1, or 3
/// for an I/O error)
/// and prints machine-readable summaries with printJson when --json is given.

#include "analysis/core/result.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace bunraku::app::cli {

/// The exit codes of every subcommand (documented in `bunraku --help` and the man page).
inline constexpr int kExitOk = 0;       ///< done
inline constexpr int kExitBadInput = 1; ///< bad input: a file or value the command cannot use
inline constexpr int kExitUsage = 2;    ///< bad command line: unknown option, missing argument
inline constexpr int kExitIo = 3;       ///< a file could not be read or written (disk, permission)

/// Bad input or a failed operation: the message is printed as "bunraku: error: <message>" and
/// the process exits with `exitCode`.
struct CliError : std::runtime_error {
    explicit CliError(const std::string& message, int code = kExitBadInput) : std::runtime_error(message), exitCode(code) {}
    int exitCode;
};

/// kExitIo for an I/O error, kExitBadInput for the others.
inline int exitCodeOf(const analysis::Error& error) { return error.code == analysis::ErrorCode::Io ? kExitIo : kExitBadInput; }

/// Where commands attach: the root app and the `experiment` group.
struct CommandSet {
    CLI::App& root;
    CLI::App& experiment;
};

/// The value of a Result, or a CliError carrying its message.
template <class T>
T unwrap(analysis::Result<T> result)
{
    if (!result.ok()) throw CliError(result.error().message, exitCodeOf(result.error()));
    return std::move(result).value();
}
inline void unwrap(const analysis::Status& status)
{
    if (!status.ok()) throw CliError(status.error().message, exitCodeOf(status.error()));
}

/// Pretty-prints JSON on standard output, one document per call.
void printJson(const nlohmann::json& document);

/// How every command reports what it did: with --json the summary (one JSON document, what a
/// folder output's summary.json holds too), else the command's lines, which `text` prints.
template <class Text>
void report(bool json, const nlohmann::json& summary, Text&& text)
{
    if (json) printJson(summary);
    else text();
}

/// A registered subcommand: its CLI11 app and the arguments its options bind to.
template <class Arguments>
struct Command {
    CLI::App* app;
    Arguments& arguments;
};

/// The description of `parent`'s subcommand `name`: one table of them (app/cli/commands.cpp).
const std::string& commandDescription(const CLI::App& parent, const std::string& name);

/// A subcommand of `parent` whose callback is `run(arguments)`; the arguments live as long as the
/// command line, the caller binds its options to them. Arguments with a `json` member get --json
/// (`jsonHelp` its help line).
template <class Arguments>
Command<Arguments> addCommand(CLI::App& parent, const std::string& name, void (*run)(const Arguments&),
                              const char* jsonHelp = "Print a machine-readable summary")
{
    auto arguments = std::make_shared<Arguments>();
    CLI::App* command = parent.add_subcommand(name, commandDescription(parent, name));
    if constexpr (requires { arguments->json; }) command->add_flag("--json", arguments->json, jsonHelp);
    command->callback([arguments, run] { run(*arguments); });
    return {command, *arguments};
}

/// Registers every subcommand (app/cli/commands.cpp).
void addAllCommands(CommandSet& commands);

/// Runs the command line; returns the process exit code.
int runCli(int argc, char** argv);

} // namespace bunraku::app::cli
