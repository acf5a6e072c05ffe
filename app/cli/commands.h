#pragma once
/// One registration function per command family; each lives in its own cmd_*.cpp file.
#include "app/cli/cli.h"

#include "analysis/cloth/kimono_cloth.h"

namespace bunraku::app::cli {

/// info, convert, preprocess (cmd_io.cpp)
void addIoCommands(CommandSet& commands);
/// corpus (cmd_corpus.cpp)
void addCorpusCommands(CommandSet& commands);
/// demo (cmd_demo.cpp)
void addDemoCommands(CommandSet& commands);
/// normalise, experiment noise|truth (cmd_normalise.cpp)
void addNormalisationCommands(CommandSet& commands);
/// decompose, emotion, experiment km2o (cmd_decompose.cpp)
void addDecompositionCommands(CommandSet& commands);
/// axis, phase, gains, design, experiment design (cmd_axis.cpp)
void addMotionAxisCommands(CommandSet& commands);
/// experiment approximation (cmd_approximation.cpp)
void addApproximationCommands(CommandSet& commands);
/// experiment kimono (cmd_kimono.cpp)
void addKimonoCommands(CommandSet& commands);
/// The kimono cloth's options (--cloth-mass, -bend, -damping, -drag, -substeps) onto `cloth`, with
/// the ranges analysis::validate checks; for convert --kimono and experiment kimono.
void addClothOptions(CLI::App* command, analysis::ClothParameters& cloth);
/// analyse (cmd_analyse.cpp)
void addAnalyseCommands(CommandSet& commands);
/// summary (cmd_summary.cpp)
void addSummaryCommands(CommandSet& commands);
/// render (cmd_render.cpp)
void addRenderCommands(CommandSet& commands);
/// help (cmd_help.cpp)
void addHelpCommands(CommandSet& commands);
} // namespace bunraku::app::cli
