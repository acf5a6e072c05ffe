#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addAllCommands(CommandSet& commands)
{
    addIoCommands(commands);
    addDemoCommands(commands);
    addNormalisationCommands(commands);
    addDecompositionCommands(commands);
    addMotionAxisCommands(commands);
    addAnalyseCommands(commands);
    addRenderCommands(commands);
    addHelpCommands(commands);
}

} // namespace bunraku::app::cli
