// Subcommands: decompose, emotion, experiment km2o.
#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addDecompositionCommands(CommandSet& commands)
{
    (void)commands;
}

} // namespace bunraku::app::cli
