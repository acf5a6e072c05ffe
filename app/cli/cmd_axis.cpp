// Subcommands: axis, phase, gains, design, experiment design.
#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addMotionAxisCommands(CommandSet& commands)
{
    (void)commands;
}

} // namespace bunraku::app::cli
