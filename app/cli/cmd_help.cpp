// Subcommand: help (`bunraku help [SUBCOMMAND [SUBCOMMAND]]`), the same text as
// `bunraku SUBCOMMAND --help`, for users who type the word first.
#include "app/cli/commands.h"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace bunraku::app::cli {
namespace {

/// The subcommands of `app` by name, in the order they were added.
std::vector<const CLI::App*> subcommandsOf(const CLI::App& app)
{
    return app.get_subcommands([](const CLI::App* sub) { return !sub->get_name().empty(); });
}

std::string namesOf(const std::vector<const CLI::App*>& subcommands)
{
    std::string names;
    for (const CLI::App* sub : subcommands) names += (names.empty() ? "" : ", ") + sub->get_name();
    return names;
}

} // namespace

void addHelpCommands(CommandSet& commands)
{
    CLI::App& root = commands.root;
    CLI::App* help = root.add_subcommand("help", "Show the help of the command line or of a subcommand (bunraku help "
                                                 "demo, bunraku help experiment km2o)");
    auto path = std::make_shared<std::vector<std::string>>();
    help->add_option("subcommand", *path, "The subcommand, and its own subcommand (experiment km2o)");
    help->callback([&root, path] {
        const CLI::App* target = &root;
        std::string usage = root.get_name();
        for (const std::string& name : *path) {
            const std::vector<const CLI::App*> subcommands = subcommandsOf(*target);
            const CLI::App* next = nullptr;
            for (const CLI::App* sub : subcommands)
                if (sub->check_name(name)) next = sub;
            if (next == nullptr) {
                if (subcommands.empty()) throw CliError("'" + usage + "' has no subcommands (asked for '" + name + "')", kExitUsage);
                throw CliError("'" + usage + "' has no subcommand '" + name + "' (expected one of: " + namesOf(subcommands) + ")",
                               kExitUsage);
            }
            usage += " " + name;
            target = next;
        }
        std::cout << target->get_formatter()->make_help(target, usage, CLI::AppFormatMode::Normal) << std::flush;
    });
}

} // namespace bunraku::app::cli
