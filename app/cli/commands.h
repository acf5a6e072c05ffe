#pragma once
/// One registration function per command family; each lives in its own cmd_*.cpp file.
#include "app/cli/cli.h"

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/pipeline/stages.h"
#include "analysis/report/analysis_files.h"
#include "analysis/synth/demo_corpus.h"

namespace bunraku::app::cli {

// The analysis's namespaces as the commands name them.
namespace an = bunraku::analysis;
namespace pl = bunraku::analysis::pipeline;
namespace rp = bunraku::analysis::report;

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

/// The ground truth of the synthetic corpus `corpus` (its truth/ folder, written by `bunraku
/// demo`), or a CliError saying where it was expected (`experiment truth` and `design`).
analysis::synth::DemoGroundTruth groundTruthOf(const std::string& corpus);

/// `--no-preprocess` of `normalise`, `decompose` and `emotion`: the takes as stored, thesis 2.2's
/// padding and alignments off (angles are still unwrapped).
void skipPreprocessing(pl::PreprocessParameters& parameters);

/// What `analyse` and `decompose` say about a decomposition's KM2O (thesis 4.4.4): into the
/// summary "km2o" (report::km2oOutcomeJson) and, when estimable, the M chosen and its mean P.
void addKm2oSummary(nlohmann::json& summary, const pl::DecomposeOutput& decomposed);
/// Its outcome and notes as lines, when it has notes.
void printKm2oNotes(const pl::DecomposeOutput& decomposed);
} // namespace bunraku::app::cli
