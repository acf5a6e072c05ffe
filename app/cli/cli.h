#pragma once
/// Shared plumbing of the `bunraku` command line: every subcommand registers itself on the root
/// (or on `experiment`), reports bad input by throwing CliError (printed as one line, exit 1)
/// and prints machine-readable summaries with printJson when --json is given.

#include "analysis/core/result.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <utility>

namespace bunraku::app::cli {

/// Bad input or a failed operation: the message is printed as "bunraku: error: <message>".
struct CliError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Where commands attach: the root app and the `experiment` group.
struct CommandSet {
    CLI::App& root;
    CLI::App& experiment;
};

/// The value of a Result, or a CliError carrying its message.
template <class T>
T unwrap(analysis::Result<T> result)
{
    if (!result.ok()) throw CliError(result.error().message);
    return std::move(result).value();
}
inline void unwrap(const analysis::Status& status)
{
    if (!status.ok()) throw CliError(status.error().message);
}

/// Pretty-prints JSON on standard output, one document per call.
void printJson(const nlohmann::json& document);

/// Registers every subcommand (app/cli/commands.cpp).
void addAllCommands(CommandSet& commands);

/// Runs the command line; returns the process exit code.
int runCli(int argc, char** argv);

} // namespace bunraku::app::cli
