// Subcommands: normalise, experiment noise, experiment truth.
#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addNormalisationCommands(CommandSet& commands)
{
    (void)commands;
}

} // namespace bunraku::app::cli
