// Subcommands: render.
#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addRenderCommands(CommandSet& commands)
{
    (void)commands;
}

} // namespace bunraku::app::cli
