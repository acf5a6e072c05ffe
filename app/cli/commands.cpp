#include "app/cli/commands.h"

#include "analysis/report/analysis_files.h"
#include "analysis/synth/demo_corpus_io.h"

#include <iostream>
#include <map>

namespace bunraku::app::cli {

namespace {

/// Every command's description, as `bunraku --help` lists it and `bunraku COMMAND --help` starts
/// with (the man page too), by its path: "corpus", "experiment km2o".
const std::map<std::string, std::string> kDescriptions{
    {"info",
     "Describe a corpus folder or a take file (.csv, .bvh, .fbx, .glb/.gltf, .dae, .txt/.fastrak): labels, frames, rate, "
     "channels, ranges, and a BVH (or converted FBX, glTF, Collada) file's joints"},
    {"convert",
     "Convert a take file (.csv, .bvh, .fbx, .glb/.gltf, .dae, .txt/.fastrak) to .csv, .bvh (on the take's own skeleton when it "
     "has one) or .glb (glTF binary) by the output's extension, or a corpus folder to a corpus folder"},
    {"preprocess",
     "Thesis 2.2 preprocessing of a corpus: unwrap angles, pad to the longest take, align start times to "
     "each cell's reference take and start positions to each function's reference take"},
    {"corpus",
     "Make a corpus folder from take files (BVH, FBX, glTF, Collada, CSV, FASTRAK) or folders of them: labels from the file names, each "
     "file's part map reported, takes resampled to one rate when their rates differ"},
    {"demo",
     "Write the synthetic Bunraku corpus (2 functions x 3 emotions x 5 takes) and its ground truth "
     "(DIR/truth, see docs/DEMO-CORPUS.md)"},
    {"normalise",
     "Normalise the takes of one function x emotion cell in time by wavelet matching (thesis ch. 3): "
     "writes the normalised takes, correspondences, the reference and the variance table"},
    {"experiment noise",
     "Thesis 3.4: wavelet matching below the noise band vs with it vs amplitude matching"},
    {"experiment truth",
     "Normalise every take of the synthetic corpus to its cell's reference and compare the "
     "correspondences with the ground truth (greedy, optimal, amplitude DTW)"},
    {"decompose",
     "Decompose a corpus into function y^i, emotion z^{ij} and fluctuation eta (thesis ch. 4) as the "
     "workbench's Emotion tab does (preprocess 2.2, normalise every cell 3, KM2O with M chosen by P); write "
     "components, spectra and ARMA tables"},
    {"emotion",
     "Design a motion with an emotion weight: x = y^i + a z^{ij} (thesis eq. 4.45), the workbench's weighted "
     "take: the same chain as `decompose`"},
    {"experiment km2o",
     "Thesis 4.4.3: identify the exogenous inputs of simulated ARX series (eq. 4.39) for each M and compare "
     "the relative error P with Table 4.4"},
    {"axis",
     "Motion axis of a take (thesis 5.2.1): principal axes of inertia of the posed body per frame, "
     "written as the thesis's 6 axis channels"},
    {"phase",
     "Phase component (thesis 5.3): match the sample's (emotional) axis to the reference's (functional) "
     "on all 6 DOF; writes the warp curve (emotional frame -> functional frame control points)"},
    {"gains",
     "Amplitude component (thesis 5.4): per phrase and axis DOF the gains g0, g1 of the functional axis "
     "against the phase-adjusted emotional axis"},
    {"design",
     "Motion design (thesis 5.5): scale the functional take's axis per phrase, recombine with its "
     "relative motion and warp time"},
    {"experiment design",
     "Thesis 5.5 on the synthetic corpus: per function and emotion extract phase and gains between the "
     "functional and emotional means, design from the functional mean, compare with the measured axis "
     "(eq. 5.18 relative error) and the phase with the ground truth"},
    {"experiment approximation",
     "Thesis 5.4.1 (eq. 5.18, Fig. 5.16): per largest scale c, the error between the wavelet "
     "approximations of the functional axis and of the phase-adjusted emotional axis, per axis DOF"},
    {"experiment kimono",
     "The kimono simulated as cloth over every take of a corpus: per take and per emotion, each sleeve's and the hem's "
     "own swing (RMS cm beyond what the parts carry) and the sleeve's lag behind the hand (docs/KIMONO.md)"},
    {"analyse",
     "The thesis's whole chain: preprocess (2.2), normalise every cell (3), decompose (4: KM2O with M chosen by "
     "P), spectra and ARMA (4.3.2), motion axes, phase and gains (5); writes the data files and report.html. A corpus of a "
     "skeleton's joints (--all-joints) is normalised with the chains coupling; the motion axes need the puppet's 4 "
     "parts and are skipped with a note"},
    {"summary",
     "One table (CSV) and one HTML index over folders written by 'bunraku analyse': per corpus its takes, cells, "
     "KM2O M and mean P, mean design error, and the link to its report.html (workflows/Snakefile)"},
    {"render",
     "Render the puppet, motion axis and orbits of a take (or two side by side) to PNG offscreen"},
};

} // namespace

const std::string& commandDescription(const CLI::App& parent, const std::string& name)
{
    return kDescriptions.at(parent.get_name() == "experiment" ? "experiment " + name : name);
}

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

analysis::synth::DemoGroundTruth groundTruthOf(const std::string& corpus)
{
    const std::filesystem::path truthFolder = analysis::synth::groundTruthFolder(corpus);
    auto truth = analysis::synth::readGroundTruth(truthFolder);
    if (!truth.ok())
        throw CliError("no ground truth for " + corpus + " (expected " + truthFolder.string() + ", written by `bunraku demo`): " +
                       truth.error().message);
    return std::move(truth).value();
}

void skipPreprocessing(pl::PreprocessParameters& parameters)
{
    parameters.pad = parameters.alignStart = parameters.alignHeading = parameters.alignPosition = false;
}

void addKm2oSummary(nlohmann::json& summary, const pl::DecomposeOutput& decomposed)
{
    if (!decomposed.km2o) return;
    summary["km2o"] = rp::km2oOutcomeJson(*decomposed.km2o);
    if (decomposed.km2o->estimable()) { // else no M was chosen: y, z by least squares
        summary["M"] = decomposed.km2o->correlationLength;
        summary["mean_P_percent"] = decomposed.km2o->meanCellErrorPercent;
    }
}

void printKm2oNotes(const pl::DecomposeOutput& decomposed)
{
    if (!decomposed.km2o || decomposed.km2o->notes.empty()) return;
    std::cout << decomposed.km2o->outcome() << "\n";
    for (const auto& note : decomposed.km2o->notes) std::cout << "  " << note << "\n";
}

} // namespace bunraku::app::cli
