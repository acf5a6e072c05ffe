// Subcommands: info, convert, preprocess.
#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addIoCommands(CommandSet& commands)
{
    (void)commands;
}

} // namespace bunraku::app::cli
