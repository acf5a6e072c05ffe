// Subcommands: decompose, emotion, experiment km2o.
#include "app/cli/commands.h"
#include "app/cli/chain_parameters.h"
#include "app/cli/take_output.h"
#include "app/cli/output_guard.h"

#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/km2o_experiment.h"
#include "analysis/core/parallel.h"
#include "analysis/io/corpus_io.h"
#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/pipeline/stages.h"
#include "analysis/report/analysis_files.h"
#include "analysis/report/experiment_tables.h"
#include "analysis/synth/demo_corpus.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;
using namespace bunraku::analysis;

/// Runs `work`; an error that does not name the corpus folder gets it in front, so every
/// message says which input it is about.
template <class Work>
auto aboutCorpus(const std::string& path, Work&& work)
{
    try {
        return work();
    } catch (const CliError& error) {
        const std::string message = error.what();
        if (message.find(path) != std::string::npos) throw;
        throw CliError(path + ": " + message);
    }
}

/// What the chain of `decompose` and `emotion` starts from and how: the workbench's Emotion
/// tab's chain by default (thesis 2.2 preprocessing, chapter 3 normalisation of every cell, then
/// chapter 4 on the normalised takes with KM2O, M chosen by P), with the parameters of
/// `--parameters` and the options below on top.
inline constexpr int kNotGiven = std::numeric_limits<int>::min();

struct ChainArgs {
    std::string corpus;
    std::string parameters;  ///< --parameters FILE (as `bunraku analyse`)
    std::string input;       ///< normalised | preprocessed; empty: the parameters' (normalised)
    std::string method;      ///< km2o | ls; empty: the parameters' (km2o)
    int correlationLength = kNotGiven; ///< --M; kNotGiven: the parameters' (0 = chosen by P)
    bool pad = false;
    bool noPreprocess = false;
};

/// The chain's results up to chapter 4 (and the fluctuations when asked), from the pipeline's
/// chain (chain.h), the stages the workbench's scheduler runs, with the parameters they ran with.
struct ChainOutcome : pipeline::ChainResult {
    pipeline::ChainParameters parameters;
};

pipeline::ChainParameters chainParameters(const ChainArgs& args)
{
    pipeline::ChainParameters parameters = readChainParameters(args.parameters);
    if (!args.input.empty())
        parameters.decompose.input = namedParameter<pipeline::DecomposeInput>(args.input);
    if (!args.method.empty())
        // "ls": the command line's short name of the parameter files' "least-squares"
        parameters.decompose.method = namedParameter<pipeline::DecomposeMethod>(args.method == "ls" ? "least-squares" : args.method);
    if (args.correlationLength != kNotGiven) {
        if (parameters.decompose.method == pipeline::DecomposeMethod::LeastSquares && args.correlationLength != 0)
            throw CliError("--M applies to --method km2o only");
        parameters.decompose.correlationLength = args.correlationLength;
    }
    if (args.noPreprocess) skipPreprocessing(parameters.preprocess); // as `bunraku normalise --no-preprocess`
    if (args.pad) parameters.preprocess.pad = true;
    if (auto valid = pipeline::validate(parameters); !valid)
        throw CliError(chainSubject(args.corpus, args.parameters) + ": " + valid.error().message);
    return parameters;
}

/// Runs every stage a chapter-4 result depends on (and the fluctuation stage after it when
/// asked); an error names the corpus and the stage.
/// `armaOrder`: p and q of the ARMA table, or empty for the parameters'.
ChainOutcome decomposeChain(const ChainArgs& args, bool fluctuations = false, const std::vector<int>& armaOrder = {})
{
    ChainOutcome out;
    out.parameters = chainParameters(args);
    if (armaOrder.size() == 2) {
        out.parameters.fluctuations.armaP = armaOrder[0];
        out.parameters.fluctuations.armaQ = armaOrder[1];
    }
    pipeline::ChainOptions options;
    options.fluctuations = fluctuations;
    options.normalisation = options.axes = false; // normalised only when decomposed
    options.threads = resolveThreads(0); // the workbench's thread count; the same bits for any
    auto chain = pipeline::runChain(unwrap(pipeline::importCorpus(args.corpus)), out.parameters, nullptr, options);
    if (!chain) {
        std::string message = chain.error().message;
        if (message.rfind(std::string(pipeline::stageTitle(pipeline::Stage::Decompose)) + ":", 0) == 0 && !out.parameters.preprocess.pad)
            message += " (--pad pads every take to the longest first)";
        throw CliError(chainSubject(args.corpus, args.parameters) + ": " + message);
    }
    static_cast<pipeline::ChainResult&>(out) = std::move(chain).value();
    return out;
}

/// What every summary says about the chain it ran.
nlohmann::json chainSummary(const ChainOutcome& chain)
{
    nlohmann::json summary;
    summary["input"] = pipeline::inputName(chain.parameters.decompose.input);
    const char* requested = chain.parameters.decompose.method == pipeline::DecomposeMethod::Km2o ? "km2o" : "ls"; // as --method
    summary["method"] = requested;
    summary["method_requested"] = requested;
    summary["parameters"] = pipeline::toJson(chain.parameters);
    if (const auto& km2o = chain.decomposed->km2o) {
        // The method really used: KM2O needs a cell of two takes; without one, y and z are least squares.
        if (!km2o->estimable()) summary["method"] = "ls";
        summary["method_note"] = km2o->outcome();
    }
    addKm2oSummary(summary, *chain.decomposed);
    return summary;
}

struct DecomposeArgs {
    ChainArgs chain;
    std::string output;
    std::string truth;
    std::string armaSearch = "equal";
    int armaMaxOrder = 4;
    std::vector<int> armaTableOrder; ///< empty: the parameters' (2 2)
    bool json = false;
};

void runDecompose(const DecomposeArgs& args)
{
    if (!args.armaTableOrder.empty() && args.armaTableOrder.size() != 2) throw CliError("--arma-table takes two orders: p q");
    refuseOutputOverInputs(args.output, OutputKind::Folder, {args.chain.corpus, args.chain.parameters, args.truth});
    // The stages `bunraku analyse` runs, up to the fluctuations (4.3.2), with its parameters.
    const ChainOutcome chain = decomposeChain(args.chain, true, args.armaTableOrder);
    const Decomposition& d = chain.decomposed->components;
    nlohmann::json summary = chainSummary(chain);
    summary["corpus"] = args.chain.corpus;
    const std::string& corpusPath = args.chain.corpus;

    // Every output is computed before anything is written: bad input writes nothing. The files
    // `analyse` writes too come from its writers (the same bytes); eta, each take's spectra
    // and ARMA orders are this command's own.
    std::vector<report::OutputFile> outputs;
    const auto add = [&](std::vector<report::OutputFile> files) { std::move(files.begin(), files.end(), std::back_inserter(outputs)); };
    const report::TakeFluctuationOptions takeOptions{chain.parameters.fluctuations.welchSegment,
                                                     args.armaSearch == "all" ? ArmaOrderSearch::AllPairs : ArmaOrderSearch::EqualOrders,
                                                     args.armaMaxOrder};
    aboutCorpus(corpusPath, [&] {
        add(unwrap(report::decompositionFiles(*chain.decomposed)));
        add(unwrap(report::fluctuationTakeFiles(d)));
        add(report::fluctuationFiles(*chain.fluctuations));
        add(unwrap(report::takeFluctuationFiles(d, takeOptions)));
    });
    if (chain.decomposed->km2o && chain.decomposed->km2o->estimable()) {
        summary["candidate_M"] = chain.decomposed->km2o->candidateLengths;
        summary["mean_P_percent_by_M"] = chain.decomposed->km2o->meanErrorPercent;
    }

    fs::path truthFolder = args.truth;
    if (truthFolder.empty() && fs::exists(fs::path(corpusPath) / "truth" / "truth.json"))
        truthFolder = fs::path(corpusPath) / "truth";
    if (!truthFolder.empty()) {
        summary["truth"] = unwrap(report::groundTruthErrorsJson(d, unwrap(synth::readGroundTruth(truthFolder))));
        summary["truth_folder"] = truthFolder.string();
    }
    summary["functions"] = nlohmann::json::array();
    for (const auto& f : d.functions) summary["functions"].push_back(f.function);
    summary["cells"] = nlohmann::json::array();
    for (const auto& z : d.emotions) summary["cells"].push_back(z.function + "/" + z.emotion);
    summary["frames"] = d.frameCount();
    summary["channels"] = d.channels.size();
    FolderOutput folder(args.output);
    folder.add(outputs);
    folder.commit(summary);
    report(args.json, summary, [&] {
        std::cout << "decomposed " << chain.corpus.corpus->takes.size() << " " << summary["input"].get<std::string>() << " takes ("
                  << summary["method"].get<std::string>() << ") into " << args.output << ": "
                  << d.functions.size() << " y, " << d.emotions.size() << " z, " << d.fluctuations.size() << " eta\n";
        if (summary.contains("M"))
            std::cout << "KM2O correlation length M = " << summary["M"] << ", mean P = " << summary["mean_P_percent"] << " %\n";
        printKm2oNotes(*chain.decomposed);
        if (summary.contains("truth")) std::cout << "error against ground truth: " << summary["truth"].dump() << "\n";
    });
}

struct EmotionArgs {
    ChainArgs chain;
    std::string function;
    std::string emotion;
    double weight = 1.0;
    std::string output;
    bool perChannel = false;
    bool json = false;
    KimonoOutputArguments kimono;
};

void runEmotion(const EmotionArgs& args)
{
    requireTakeOutput(args.output);
    requireKimonoOutput(args.kimono, args.output);
    refuseOutputOverInputs(args.output, OutputKind::File, {args.chain.corpus, args.chain.parameters});
    const ChainOutcome chain = decomposeChain(args.chain);
    // The workbench's weighted take: the same function on the same stage result.
    const Take take = aboutCorpus(args.chain.corpus, [&] {
        return unwrap(pipeline::weightedTake(*chain.decomposed, args.function, args.emotion, args.weight));
    });
    // One body: the file holds the weighted skeleton's motion; --per-channel writes the thesis's
    // x = y + a z channel by channel instead (no skeleton).
    Take written = take;
    if (args.perChannel) written.skeleton = nullptr;
    writeTakeOutput(written, args.output, args.kimono.parameters());
    nlohmann::json summary = chainSummary(chain);
    summary["corpus"] = args.chain.corpus;
    summary["motion"] = args.perChannel || !take.skeleton ? "per-channel" : "body";
    summary["function"] = args.function;
    summary["emotion"] = args.emotion;
    summary["weight"] = args.weight;
    summary["frames"] = take.frameCount();
    summary["channels"] = take.channels.size();
    summary["rate_hz"] = take.rateHz;
    summary["output"] = args.output;
    report(args.json, summary, [&] {
        std::cout << "wrote " << args.output << ": " << args.function << "/" << args.emotion << " with emotion weight a = " << args.weight
                  << " (" << take.frameCount() << " frames; " << summary["input"].get<std::string>() << " takes, "
                  << summary["method"].get<std::string>();
        if (summary.contains("M")) std::cout << ", M = " << summary["M"].get<int>();
        std::cout << ")\n";
        if (summary["method"] != summary["method_requested"]) std::cout << summary["method_note"].get<std::string>() << "\n";
        if (!written.skeleton) std::cout << args.output << " holds the per-channel result on the puppet's parts (no skeleton)\n";
    });
}

struct ExperimentArgs {
    Km2oExperimentOptions options; ///< T, the seeds and K bound to it directly
    std::string range = "3:20";
    double noise = 0.0;
    int firstOffset = -1;
    std::string initialTimes = "full";
    std::string noiseSharing = "per-cell";
    bool json = false;
};

void runExperiment(const ExperimentArgs& args)
{
    Km2oExperimentOptions options = args.options;
    // FIRST:LAST or one M, the whole text read ("3x:20" is refused, not read as 3:20).
    std::istringstream range(args.range);
    char colon = 0;
    bool read = bool(range >> options.firstM);
    options.lastM = options.firstM;
    if (read && !range.eof()) read = range >> colon >> options.lastM && colon == ':';
    if (!read || !range.eof())
        throw CliError("--M expects FIRST:LAST (e.g. 3:20), got '" + args.range + "'");
    if (args.noise > 0.0) options.noiseScale = args.noise;
    if (args.firstOffset >= 0) options.reading.firstWindowOffset = args.firstOffset;
    options.reading.initialTimes = args.initialTimes == "thesis" ? InitialTimeRange::Thesis : InitialTimeRange::Full;
    options.noise = args.noiseSharing == "shared" ? NoiseSharing::SharedAcrossCells : NoiseSharing::PerCell;
    const auto result = unwrap(runKm2oExperiment(options));
    report(args.json, report::km2oExperimentJson(result, options),
           [&] { std::cout << report::km2oExperimentText(result, options); });
}

/// The options of the chain up to chapter 4 (`decompose`, `emotion`).
void addChainOptions(CLI::App* command, ChainArgs& args)
{
    command->add_option("corpus", args.corpus, "Corpus folder (corpus.json), or 'demo' for the embedded demo corpus")->required();
    command->add_option("--parameters", args.parameters,
                        "JSON file of the chain's parameters (docs/FORMATS.md, as `bunraku analyse`), or a project file; "
                        "default the thesis's, but for normalisation's optimal path")
        ->type_name("FILE");
    command->add_option("--input", args.input,
                        "Takes decomposed: normalised (thesis 4.1: after 2.2 and chapter 3, default) or preprocessed (2.2 only)")
        ->check(namedParameterCheck<pipeline::DecomposeInput>());
    std::vector<std::string> methods = pipeline::parameterNameList<pipeline::DecomposeMethod>();
    methods.push_back("ls"); // the short name kept
    command->add_option("--method", args.method, "km2o (KM2O-Langevin, 4.4.4; default) or least-squares (4.3.1; also 'ls')")
        ->check(CLI::IsMember(methods));
    command->add_option("--M", args.correlationLength,
                        "KM2O correlation length M, at most M_max = floor(3 sqrt(T + 1)) - 1 for takes of T + 1 frames; "
                        "0 or not given: chosen by P (4.4.4)")
        ->transform(parameterCheck("decompose.M"));
    command->add_flag("--no-preprocess", args.noPreprocess,
                      "Skip thesis 2.2's padding and alignments (angles are still unwrapped), as `bunraku normalise "
                      "--no-preprocess`");
    command->add_flag("--pad", args.pad,
                      "Pad takes to the longest by repeating the last frame (thesis 2.2 step 1): part of the default "
                      "preprocessing; with --no-preprocess, the one step kept");
}

} // namespace

void addDecompositionCommands(CommandSet& commands)
{
    auto [dec, decomposeArgs] = addCommand(commands.root, "decompose", runDecompose);
    addChainOptions(dec, decomposeArgs.chain);
    dec->add_option("-o,--output", decomposeArgs.output, "Output folder")->required()->type_name("DIR");
    dec->add_option("--truth", decomposeArgs.truth,
                    "Ground-truth folder of a synthetic corpus (default: CORPUS/truth when it exists)");
    dec->add_option("--arma-search", decomposeArgs.armaSearch, "ARMA orders tried per take: equal ((n,n)) or all ((p,q))")
        ->check(CLI::IsMember({"equal", "all"}));
    dec->add_option("--arma-max-order", decomposeArgs.armaMaxOrder, "Largest ARMA order for FPE selection")
        ->check(CLI::Range(0, analysis::pipeline::kMaxArmaOrder));
    dec->add_option("--arma-table", decomposeArgs.armaTableOrder,
                    "ARMA(p,q) averaged per cell (Table 4.1), each 0..4; default the parameters' (2 2), as `bunraku analyse`")
        ->expected(2)
        ->transform(parameterCheck("fluctuations.armaP"));

    auto [emo, emotionArgs] = addCommand(commands.root, "emotion", runEmotion);
    addChainOptions(emo, emotionArgs.chain);
    emo->add_option("--function", emotionArgs.function, "Function label, e.g. greeting")->required();
    emo->add_option("--emotion", emotionArgs.emotion, "Emotion label, e.g. friendly")->required();
    emo->add_option("--weight", emotionArgs.weight, "Emotion weight a (1 = as performed)")
        ->transform(parameterCheck("design.emotionWeight"))
        ->required();
    emo->add_option("-o,--output", emotionArgs.output, "Output take (.bvh, .glb or .csv): the weighted body's motion")
        ->required()
        ->type_name("FILE");
    emo->add_flag("--per-channel", emotionArgs.perChannel,
                  "Write the thesis's per-channel x = y + a z (each channel on its own, the puppet's parts, no skeleton) instead of "
                  "the weighted body's motion");
    addKimonoOutputOptions(emo, emotionArgs.kimono);

    auto [exp, experimentArgs] = addCommand(commands.experiment, "km2o", runExperiment);
    exp->add_option("--T", experimentArgs.options.finalTime, "Final time T: 300 (Table 4.2) or 1000 (Table 4.3)")
        ->check(CLI::IsMember({300, 1000}));
    exp->add_option("--M", experimentArgs.range, "Correlation lengths FIRST:LAST (default 3:20)");
    exp->add_option("--seeds", experimentArgs.options.seeds, "Simulations averaged (default 5)")->check(CLI::PositiveNumber);
    exp->add_option("--seed", experimentArgs.options.firstSeed, "First seed");
    exp->add_option("--noise", experimentArgs.noise, "Noise scale c (default: the table's)");
    exp->add_option("--first-offset", experimentArgs.firstOffset,
                    "Window offsets below this are used only where nothing else reaches (default 1; see docs/KM2O.md)")
        ->check(CLI::Range(0, 100));
    exp->add_option("--initial-times", experimentArgs.initialTimes, "T0 range: full (0..T-M) or thesis (0..T-M-1)")
        ->check(CLI::IsMember({"full", "thesis"}));
    exp->add_option("--noise-sharing", experimentArgs.noiseSharing,
                    "per-cell (an independent w_k(t) per cell, default) or shared (one w_k(t) for all six cells: eq. "
                    "4.39 puts no i, j on w)")
        ->check(CLI::IsMember({"per-cell", "shared"}));
    exp->add_option("--takes", experimentArgs.options.takes, "K, takes per cell (default 5, as the thesis)")->check(CLI::Range(2, 1000));
}

} // namespace bunraku::app::cli
