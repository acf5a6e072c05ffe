// Subcommands: normalise, experiment noise, experiment truth (thesis chapter 3).
#include "app/cli/commands.h"
#include "app/cli/chain_parameters.h"
#include "app/cli/take_output.h"
#include "app/cli/output_guard.h"

#include "analysis/core/message_text.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/take_csv.h"
#include "analysis/report/analysis_files.h"
#include "analysis/report/cell_variance.h"
#include "analysis/report/experiment_tables.h"
#include "analysis/normalise/average_take.h"
#include "analysis/normalise/noise_experiment.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/normalise/truth_experiment.h"
#include "analysis/normalise/variance_evaluation.h"
#include "analysis/normalise/variance_families.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/pipeline/stages.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/synth/demo_corpus.h"
#include "analysis/synth/demo_corpus_io.h"
#include "analysis/wavelet/scale_list.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace bunraku::app::cli {
namespace {

/// The normalise stage's defaults (the optimal path; "greedy" = thesis 3.5.3).
struct MatchArguments {
    MatchingArguments matching = matchingDefaults(pl::NormaliseParameters{});
    std::string scales = "1:16";
    std::string coupling = an::kDefaultCoupling;
};

struct NormaliseArguments {
    std::string corpus;
    std::string function;
    std::string emotion;
    std::string reference;
    std::vector<int> exclude;
    int base = 0;
    std::string output;
    bool json = false;
    bool noPreprocess = false;
    MatchArguments match;
    KimonoOutputArguments kimono;
};

/// --scales as the scales it lists (analysis/wavelet/scale_list.h).
std::vector<double> parseScales(const std::string& text)
{
    auto scales = an::parseScaleList(text);
    if (!scales) throw CliError("--scales: " + scales.error().message);
    return std::move(scales).value();
}

an::NormaliseOptions normaliseOptions(const MatchArguments& arguments)
{
    an::NormaliseOptions options;
    options.coupling = arguments.coupling;
    options.match = arguments.matching.options;
    options.match.scales = parseScales(arguments.scales);
    return options;
}

void addMatchOptions(CLI::App* command, MatchArguments& arguments, bool timeScale)
{
    addMatchingOptions(command, arguments.matching, timeScale);
    command->add_option("--scales", arguments.scales, "Wavelet scales: FIRST:LAST, FIRST:STEP:LAST or a comma list")
        ->capture_default_str();
    command->add_option("--coupling", arguments.coupling,
                        "Channels sharing one correspondence: auto (method2 on the puppet's 4 parts, chains on a skeleton's "
                        "joints), method2 (head+shoulder and arm+hand per coordinate, eq. 3.29), method1 (arm+hand, eq. 3.28), "
                        "chains (per coordinate each chain of the skeleton: root, spine, left_arm, right_arm, left_leg, "
                        "right_leg), independent, per-part, per-coordinate, all, or sets like arm.x+hand.x;head.x+shoulder.x")
        ->capture_default_str();
}

/// The take's CSV for a staged output folder (validated like writeTakeCsv).
std::string takeCsv(const an::Take& take, const std::string& name)
{
    if (auto valid = an::validateTake(take); !valid) throw CliError(name + ": " + valid.error().message);
    return an::io::formatTakeCsv(take);
}

pl::NormaliseParameters normaliseParameters(const MatchArguments& arguments)
{
    const an::MatchOptions match = normaliseOptions(arguments).match;
    pl::NormaliseParameters parameters;
    parameters.coupling = arguments.coupling;
    parameters.tau = match.tau;
    parameters.searchBand = match.searchBand;
    parameters.scales = match.scales;
    parameters.approximationWeight = match.approximationWeight;
    parameters.path = match.path;
    parameters.weighting = match.weighting;
    parameters.level = match.level;
    if (auto valid = pl::validate(parameters); !valid) throw CliError(valid.error().message);
    return parameters;
}

void runNormalise(const NormaliseArguments& arguments)
{
    refuseOutputOverInputs(arguments.output, OutputKind::Folder, {arguments.corpus});
    if (arguments.kimono.kimono && !isTakeOutput(arguments.output))
        throw CliError(arguments.output + ": --kimono writes the simulated cloth into a take file (.glb or .csv), not a folder");
    requireKimonoOutput(arguments.kimono, arguments.output);
    an::Corpus corpus = unwrap(an::io::readCorpus(arguments.corpus));
    // Thesis 2.2 first (pad, unwrap, align start times and start positions) - the pipeline's
    // preprocess stage, as the workbench runs it - unless told not to (angles are unwrapped then too).
    pl::PreprocessParameters preprocessing;
    if (arguments.noPreprocess) skipPreprocessing(preprocessing);
    corpus = unwrap(pl::runPreprocess(corpus, preprocessing)).corpus;
    if (corpus.cell(arguments.function, arguments.emotion).empty()) {
        std::string cells;
        for (const auto& f : corpus.functions())
            for (const auto& e : corpus.emotions())
                if (!corpus.cell(f, e).empty())
                    cells += (cells.empty() ? "" : ", ") + an::shortenedForMessage(f) + "/" + an::shortenedForMessage(e);
        throw CliError("no takes for " + an::shortenedForMessage(arguments.function) + "/" + an::shortenedForMessage(arguments.emotion) +
                       " in " + arguments.corpus + " (cells: " + an::shortenedForMessage(cells, 400) + ")");
    }
    // The pipeline's normalise stage on this cell alone.
    an::Corpus cellCorpus = corpus;
    cellCorpus.takes.clear();
    for (const an::Take* take : corpus.cell(arguments.function, arguments.emotion)) cellCorpus.takes.push_back(*take);
    pl::NormaliseParameters parameters = normaliseParameters(arguments.match);
    if (!arguments.exclude.empty() && arguments.reference != "average") throw CliError("--exclude applies to --reference average");
    if (arguments.reference == "average") {
        parameters.reference = {pl::ReferenceKind::Average, 0};
        parameters.averageBase = arguments.base;
        parameters.averageExcluded = arguments.exclude;
        parameters.averageExcludesOutliers = false; // --reference average: every take unless --exclude
    } else if (!arguments.reference.empty()) {
        try {
            std::size_t used = 0;
            parameters.reference = {pl::ReferenceKind::Take, std::stoi(arguments.reference, &used)};
            if (used != arguments.reference.size()) throw std::invalid_argument(arguments.reference);
        } catch (const std::exception&) {
            throw CliError("--reference: expected a take index or 'average', got '" + arguments.reference + "'");
        }
    }
    const pl::NormaliseOutput output = unwrap(pl::runNormalise(cellCorpus, parameters));
    const pl::CellNormalisation& result = output.cells.front();
    std::vector<const an::Take*> cell = corpus.cell(arguments.function, arguments.emotion);
    const an::NormaliseOptions options = parameters.options();
    const an::ReferenceSuggestion& suggestion = result.suggestion;
    const an::Take& reference = result.referenceTake;
    const std::string& referenceName = result.referenceName;
    const std::vector<an::TakeNormalisation>& normalised = result.normalisations;
    const an::VarianceTable& table = result.variance;
    // The preset the coupling resolved to (auto: method2 or chains), else the sets as given.
    const std::string coupling =
        normalised.empty() || normalised.front().coupling.preset.empty() ? options.coupling : normalised.front().coupling.preset;

    if (isTakeOutput(arguments.output)) {
        // One take file: the reference the cell was normalised to (the average take with
        // --reference average, thesis 3.7), in any format a take is exported in.
        writeTakeOutput(reference, arguments.output, arguments.kimono.parameters());
        const nlohmann::json summary{{"reference", referenceName}, {"frames", reference.frameCount()}, {"output", arguments.output}};
        return report(arguments.json, summary, [&] {
            std::cout << "wrote the reference (" << referenceName << ", " << reference.frameCount() << " frames) to "
                      << arguments.output << "\n";
        });
    }
    FolderOutput folder(arguments.output);
    const auto addCsv = [&](const an::Take& take, const std::string& name) {
        folder.add(name, takeCsv(take, (std::filesystem::path(arguments.output) / name).string()));
    };
    addCsv(reference, "reference.csv");
    for (std::size_t k = 0; k < normalised.size(); ++k) {
        const std::string stem = rp::takeStem(cell[k]->labels);
        addCsv(normalised[k].normalised, stem + "_normalised.csv");
        // The tables `bunraku analyse` writes (correspondence_f_e_k.csv, variance_f_e.csv), by its writers.
        folder.add(stem + "_correspondence.csv", rp::correspondenceCsv(normalised[k], reference.frameCount()));
        // A take with a performer's skeleton (a BVH corpus): also on that skeleton (not the
        // puppet's fitted rig, which the CSV's channels already pose).
        if (normalised[k].normalised.skeleton && !analysis::isPuppetRig(*normalised[k].normalised.skeleton->skeleton))
            folder.addTake(normalised[k].normalised, stem + "_normalised.bvh");
    }
    folder.add("variance.csv", rp::varianceCsv(result));
    nlohmann::json summary{{"function", arguments.function},
                                 {"emotion", arguments.emotion},
                                 {"reference", referenceName},
                                 {"suggested_reference", cell[std::size_t(suggestion.takeIndex)]->labels.takeIndex},
                                 {"suggestion", suggestion.reason},
                                 {"coupling", coupling},
                                 {"path", pl::parameterName(options.match.path)},
                                 {"tau", options.match.tau},
                                 {"tcmp", options.match.searchBand},
                                 {"scales", options.match.scales},
                                 {"takes", rp::cellVarianceJson(result, cell.front()->channels)},
                                 {"variance_raw_total", table.totalBefore.sum()},
                                 {"variance_normalised_total", table.totalAfter.sum()}};
    folder.commit(summary);
    report(arguments.json, summary, [&] {
        std::cout << "normalised " << normalised.size() << " takes of " << arguments.function << "/" << arguments.emotion
                  << " to " << referenceName << " (" << coupling << ", " << pl::parameterName(options.match.path) << ")\n"
                  << rp::cellVarianceText(result, cell.front()->channels,
                                          options.match.path == an::PathMethod::Greedy
                                              ? " (--path optimal finds the least-cost correspondence)"
                                              : "");
        std::cout << "wrote " << folder.files().size() + 1 << " files to " << arguments.output << "\n";
    });
}

struct NoiseArguments {
    bool json = false;
};

void runNoise(const NoiseArguments& arguments)
{
    const rp::NoiseComparison comparison = unwrap(rp::runNoiseComparison());
    report(arguments.json, rp::noiseComparisonJson(comparison), [&] { std::cout << rp::noiseComparisonText(comparison); });
}

struct TruthArguments {
    std::string corpus;
    int reference = 0;
    bool json = false;
    MatchArguments match;
};

void runTruth(const TruthArguments& arguments)
{
    const an::Corpus corpus = unwrap(an::io::readCorpus(arguments.corpus));
    const an::synth::DemoGroundTruth truth = groundTruthOf(arguments.corpus);
    an::TruthExperimentOptions options;
    options.normalise = normaliseOptions(arguments.match);
    options.referenceTakeIndex = arguments.reference;
    const an::TruthExperimentResult result = unwrap(an::runTruthExperiment(corpus, truth, options));
    report(arguments.json, rp::truthExperimentJson(result, options),
           [&] { std::cout << rp::truthExperimentText(result, options); });
}

} // namespace

void addNormalisationCommands(CommandSet& commands)
{
    {
        auto [command, arguments] = addCommand(commands.root, "normalise", runNormalise);
        command->add_option("CORPUS", arguments.corpus, "Corpus folder")->required()->check(CLI::ExistingDirectory);
        command->add_option("--function", arguments.function, "Function label, e.g. greeting")->required();
        command->add_option("--emotion", arguments.emotion, "Emotion label, e.g. none")->required();
        command->add_option("--reference", arguments.reference,
                            "Reference: a take index, or 'average' (thesis 3.7); default the suggested take (3.6.1)");
        command->add_option("--exclude", arguments.exclude, "Take index left out of the average (e.g. the outlier: 4ave)")
            ->transform(parameterCheck("normalise.averageExcluded"));
        command->add_option("--base", arguments.base, "Base take of the average (0, the default: the suggested reference)")
            ->transform(parameterCheck("normalise.averageBase"));
        command->add_option("-o,--output", arguments.output,
                            "Output folder; or a take file (.bvh, .glb, .csv): the reference alone (the average take with "
                            "--reference average)")
            ->required()
            ->type_name("DIR|FILE");
        command->add_flag("--no-preprocess", arguments.noPreprocess,
                          "Use the takes as stored (default: thesis 2.2 preprocessing first, as `bunraku preprocess`)");
        addMatchOptions(command, arguments.match, false);
        addKimonoOutputOptions(command, arguments.kimono);
    }
    addCommand(commands.experiment, "noise", runNoise);
    {
        auto [command, arguments] = addCommand(commands.experiment, "truth", runTruth);
        command->add_option("CORPUS", arguments.corpus, "Demo corpus folder (with truth/ from `bunraku demo`)")
            ->required()
            ->check(CLI::ExistingDirectory);
        command->add_option("--reference", arguments.reference, "Reference take index in every cell (default: suggested)");
        // The workbench and `normalise` use auto; the experiment compares the readings.
        addMatchOptions(command, arguments.match, true);
    }
}

} // namespace bunraku::app::cli
