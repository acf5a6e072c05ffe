// Subcommands: demo.
#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addDemoCommands(CommandSet& commands)
{
    (void)commands;
}

} // namespace bunraku::app::cli
