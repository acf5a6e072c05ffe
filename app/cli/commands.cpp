#include "app/cli/commands.h"

namespace bunraku::app::cli {

void addAllCommands(CommandSet& commands)
{
    addIoCommands(commands);
    addCorpusCommands(commands);
    addDemoCommands(commands);
    addNormalisationCommands(commands);
    addDecompositionCommands(commands);
    addMotionAxisCommands(commands);
    addApproximationCommands(commands);
    addKimonoCommands(commands);
    addAnalyseCommands(commands);
    addSummaryCommands(commands);
    addRenderCommands(commands);
    addHelpCommands(commands);
}

} // namespace bunraku::app::cli
