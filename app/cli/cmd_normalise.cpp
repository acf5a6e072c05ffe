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

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace bunraku::app::cli {
namespace {

namespace an = bunraku::analysis;
namespace pl = bunraku::analysis::pipeline;

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

// "1:16", "2:2:16" (first:step:last) or "1,2,4,8".
std::vector<double> parseScales(const std::string& text)
{
    std::vector<double> values;
    std::string token;
    std::istringstream parts(text);
    auto number = [&](const std::string& s) {
        try {
            std::size_t used = 0;
            const double value = std::stod(s, &used);
            if (used != s.size()) throw std::invalid_argument(s);
            return value;
        } catch (const std::exception&) {
            throw CliError("--scales: '" + s + "' is not a number (expected FIRST:LAST, FIRST:STEP:LAST or a comma list)");
        }
    };
    if (text.find(':') != std::string::npos) {
        std::vector<double> fields;
        while (std::getline(parts, token, ':')) fields.push_back(number(token));
        if (fields.size() < 2 || fields.size() > 3) throw CliError("--scales: expected FIRST:LAST or FIRST:STEP:LAST, got '" + text + "'");
        const double first = fields[0];
        const double step = fields.size() == 3 ? fields[1] : 1.0;
        const double last = fields.back();
        if (!(step > 0) || last < first) throw CliError("--scales: '" + text + "' is an empty range");
        for (double s = first; s <= last + 1e-9; s += step) values.push_back(s);
        return values;
    }
    while (std::getline(parts, token, ',')) values.push_back(number(token));
    if (values.empty()) throw CliError("--scales: no scales in '" + text + "'");
    return values;
}

an::NormaliseOptions normaliseOptions(const MatchArguments& arguments)
{
    an::NormaliseOptions options;
    options.coupling = arguments.coupling;
    options.match = matchOptions(arguments.matching, parseScales(arguments.scales));
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

std::string takeFileName(const an::Take& take)
{
    std::string name = take.labels.function + "_" + take.labels.emotion + "_" + std::to_string(take.labels.takeIndex);
    for (char& c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) c = '-';
    return name;
}

/// The take's CSV for a staged output folder (validated like writeTakeCsv).
std::string takeCsv(const an::Take& take, const std::string& name)
{
    if (auto valid = an::validateTake(take); !valid) throw CliError(name + ": " + valid.error().message);
    return an::io::formatTakeCsv(take);
}

pl::NormaliseParameters normaliseParameters(const MatchArguments& arguments)
{
    const an::MatchOptions match = matchOptions(arguments.matching, parseScales(arguments.scales));
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
    if (arguments.noPreprocess)
        preprocessing.pad = preprocessing.alignStart = preprocessing.alignHeading = preprocessing.alignPosition = false;
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
        if (arguments.json) {
            printJson({{"reference", referenceName}, {"frames", reference.frameCount()}, {"output", arguments.output}});
            return;
        }
        std::cout << "wrote the reference (" << referenceName << ", " << reference.frameCount() << " frames) to " << arguments.output
                  << "\n";
        return;
    }
    // Every output is built in a hidden folder and swapped in at the end: a killed run leaves
    // the previous output whole, never some files of each.
    const std::filesystem::path folder = arguments.output;
    an::io::StagedFolder staged = unwrap(an::io::StagedFolder::begin(folder));
    const auto writeText = [&](const std::string& name, const std::string& text) { unwrap(staged.writeFile(name, text)); };
    std::vector<std::string> files;
    writeText("reference.csv", takeCsv(reference, (folder / "reference.csv").string()));
    files.push_back("reference.csv");
    for (std::size_t k = 0; k < normalised.size(); ++k) {
        const std::string stem = takeFileName(*cell[k]);
        writeText(stem + "_normalised.csv", takeCsv(normalised[k].normalised, (folder / (stem + "_normalised.csv")).string()));
        // The tables `bunraku analyse` writes (correspondence_f_e_k.csv, variance_f_e.csv), by its writers.
        writeText(stem + "_correspondence.csv", an::report::correspondenceCsv(normalised[k], reference.frameCount()));
        files.push_back(stem + "_normalised.csv");
        files.push_back(stem + "_correspondence.csv");
        // A take with a performer's skeleton (a BVH corpus): also on that skeleton (not the
        // puppet's fitted rig, which the CSV's channels already pose).
        if (normalised[k].normalised.skeleton && !analysis::isPuppetRig(*normalised[k].normalised.skeleton->skeleton)) {
            writeTakeIntoFolder(normalised[k].normalised, staged, stem + "_normalised.bvh");
            files.push_back(stem + "_normalised.bvh");
        }
    }
    writeText("variance.csv", an::report::varianceCsv(result));
    files.push_back("variance.csv");

    // Per DOF family (cm² apart from deg²), as the Normalisation panel shows them; the thesis's
    // total over all channels (Tables 3.4/3.5) beside.
    const std::vector<an::VarianceRow> rows = an::varianceRows(table, cell.front()->channels);
    nlohmann::json takesJson = nlohmann::json::array();
    for (std::size_t k = 0; k < normalised.size(); ++k) {
        nlohmann::json families = nlohmann::json::array();
        for (const an::VarianceRow& row : rows)
            if (row.take == table.takeNames[k] && row.part.empty())
                families.push_back({{"family", row.family}, {"unit", row.unit}, {"raw", row.before}, {"normalised", row.after}});
        takesJson.push_back({{"take", cell[k]->labels.takeIndex},
                             {"cost", normalised[k].cost},
                             {"variance_raw", table.totalBefore[Eigen::Index(k)]},
                             {"variance_normalised", table.totalAfter[Eigen::Index(k)]},
                             {"families", families},
                             {"outlier", bool(suggestion.outlier[k])}});
    }
    const nlohmann::json summary{{"function", arguments.function},
                                 {"emotion", arguments.emotion},
                                 {"reference", referenceName},
                                 {"suggested_reference", cell[std::size_t(suggestion.takeIndex)]->labels.takeIndex},
                                 {"suggestion", suggestion.reason},
                                 {"coupling", coupling},
                                 {"path", arguments.match.matching.path},
                                 {"tau", options.match.tau},
                                 {"tcmp", options.match.searchBand},
                                 {"scales", options.match.scales},
                                 {"takes", takesJson},
                                 {"variance_raw_total", table.totalBefore.sum()},
                                 {"variance_normalised_total", table.totalAfter.sum()},
                                 {"output", folder.string()},
                                 {"files", files}};
    writeText("summary.json", summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    unwrap(staged.commit());
    report(arguments.json, summary, [&] {
        std::cout << "normalised " << normalised.size() << " takes of " << arguments.function << "/" << arguments.emotion
                  << " to " << referenceName << " (" << coupling << ", " << arguments.match.matching.path << ")\n"
                  << "take  " << std::left << std::setw(27) << "variance to the reference" << std::right << std::setw(11) << "raw"
                  << std::setw(13) << "normalised" << std::setw(8) << "change" << "\n";
        std::vector<int> worse;
        for (std::size_t k = 0; k < normalised.size(); ++k) {
            for (const an::VarianceRow& row : rows) {
                if (row.take != table.takeNames[k] || !row.part.empty()) continue;
                std::ostringstream change;
                if (row.before > 0.0) change << std::showpos << std::fixed << std::setprecision(0) << 100.0 * (row.after - row.before) / row.before << " %";
                else change << "-";
                std::cout << std::setw(4) << cell[k]->labels.takeIndex << "  " << std::left << std::setw(27) << (row.family + " " + row.unit)
                          << std::right << std::fixed << std::setprecision(1) << std::setw(11) << row.before << std::setw(13) << row.after
                          << std::setw(8) << change.str() << (row.worse() ? "  worse" : "") << (suggestion.outlier[k] ? "  (outlier)" : "") << "\n";
                if (row.worse() && (worse.empty() || worse.back() != cell[k]->labels.takeIndex)) worse.push_back(cell[k]->labels.takeIndex);
            }
        }
        std::cout.unsetf(std::ios::fixed);
        if (!worse.empty()) {
            std::cout << "take(s)";
            for (int take : worse) std::cout << " " << take;
            std::cout << ": normalised further from the reference than raw in some family"
                      << (arguments.match.matching.path == "greedy" ? " (--path optimal finds the least-cost correspondence)" : "") << "\n";
        }
        std::cout << "wrote " << files.size() + 1 << " files to " << folder.string() << "\n";
    });
}

nlohmann::json methodsJson(const std::vector<an::MethodError>& methods)
{
    nlohmann::json out = nlohmann::json::array();
    for (const auto& method : methods)
        out.push_back({{"name", method.name},
                       {"mean_abs_error_frames", method.meanAbsErrorFrames},
                       {"max_abs_error_frames", method.maxAbsErrorFrames},
                       {"shape_rms", method.shapeRms},
                       {"scales", method.scales}});
    return out;
}

/// "28..36" for consecutive scales, else the list.
std::string scaleText(const std::vector<double>& scales)
{
    if (scales.empty()) return "-";
    bool consecutive = true;
    for (std::size_t i = 1; i < scales.size(); ++i) consecutive = consecutive && scales[i] == scales[i - 1] + 1.0;
    std::ostringstream out;
    if (consecutive) {
        out << scales.front() << ".." << scales.back();
    } else {
        for (std::size_t i = 0; i < scales.size(); ++i) out << (i ? "," : "") << scales[i];
    }
    return out.str();
}

void printNoiseTable(const std::string& title, const an::NoiseExperimentResult& result)
{
    std::cout << title << "\n    method                     scales     mean |err|   max |err|   shape RMS\n";
    for (const auto& method : result.methods)
        std::cout << "    " << std::left << std::setw(27) << method.name << std::setw(9) << scaleText(method.scales) << std::right
                  << std::fixed << std::setprecision(3) << std::setw(12) << method.meanAbsErrorFrames << std::setw(12)
                  << method.maxAbsErrorFrames << std::setw(12) << method.shapeRms << "\n";
}

void runNoise(bool json)
{
    // Thesis 3.4 with its own bands (ThesisNoiseBands), and the workbench's variant (scales
    // 14..20 and 1..20 on the same signals), each as the thesis matched (single frames, no time
    // constraint) and with windows and the optimal monotone path.
    const an::NoiseExperimentOptions ours;
    const an::NoiseExperimentOptions thesis = an::thesisBandOptions(ours);
    auto constrainedOf = [](an::NoiseExperimentOptions options) {
        options.path = an::PathMethod::Optimal;
        options.tau = 4;
        return options;
    };
    const an::NoiseExperimentResult thesisResult = unwrap(an::runNoiseExperiment(thesis));
    const an::NoiseExperimentResult thesisConstrained = unwrap(an::runNoiseExperiment(constrainedOf(thesis)));
    const an::NoiseExperimentResult result = unwrap(an::runNoiseExperiment(ours));
    const an::NoiseExperimentResult modern = unwrap(an::runNoiseExperiment(constrainedOf(ours)));
    const an::ThesisNoiseBands bands;
    if (json) {
        printJson({{"thesis_bands",
                    {{"bands",
                      {{"below_noise_of_reference_frequency", {bands.lowestOfReference, bands.highestOfReference}},
                       {"with_noise_band_of_noise_frequency_max", bands.highestOfNoise}}},
                     {"methods", methodsJson(thesisResult.methods)},
                     {"with_time_constraint", {{"path", "optimal"}, {"tau", 4}, {"methods", methodsJson(thesisConstrained.methods)}}}}},
                   {"methods", methodsJson(result.methods)},
                   {"setup",
                    {{"frames", ours.frames},
                     {"reference_frequency", ours.referenceFrequency},
                     {"sample_frequency", ours.sampleFrequency},
                     {"phase_shift_rad", ours.phaseShiftRadians},
                     {"noise_amplitude", ours.noiseAmplitude},
                     {"noise_frequency", ours.noiseFrequency},
                     {"tau", ours.tau},
                     {"tcmp", ours.searchBand},
                     {"path", "independent (thesis 3.3/3.4 single-frame matching)"}}},
                   {"with_time_constraint", {{"path", "optimal"}, {"tau", 4}, {"methods", methodsJson(modern.methods)}}}});
        return;
    }
    std::cout << "thesis 3.4: sine 0.025 cycles/frame, 200 frames; sample 1.1x, phase -0.4 rad, + 0.4 sin at 4x as noise\n"
              << "error vs the true warp (frames) and RMS of the normalised noiseless sample vs the reference\n";
    printNoiseTable("thesis bands (0.894-1.151 x the signal's frequency; with noise: up to 2 x the noise's), single frames, "
                    "T_cmp 20:",
                    thesisResult);
    printNoiseTable("thesis bands, windows (tau 4) and the optimal monotone path:", thesisConstrained);
    printNoiseTable("workbench bands (14..20 below the noise; 1..20 with it), single frames, T_cmp 20:", result);
    printNoiseTable("workbench bands, windows (tau 4) and the optimal monotone path:", modern);
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
    const std::filesystem::path truthFolder = an::synth::groundTruthFolder(arguments.corpus);
    auto truth = an::synth::readGroundTruth(truthFolder);
    if (!truth.ok())
        throw CliError("no ground truth for " + arguments.corpus + " (expected " + truthFolder.string()
                       + ", written by `bunraku demo`): " + truth.error().message);
    an::TruthExperimentOptions options;
    options.normalise = normaliseOptions(arguments.match);
    options.referenceTakeIndex = arguments.reference;
    const an::TruthExperimentResult result = unwrap(an::runTruthExperiment(corpus, *truth, options));
    const an::TruthMethodResult* optimal = nullptr;
    for (const auto& method : result.methods)
        if (method.name == "wavelet-optimal") optimal = &method;
    if (arguments.json) {
        nlohmann::json methods = nlohmann::json::array();
        for (const auto& method : result.methods)
            methods.push_back({{"name", method.name},
                               {"mean_abs_error_frames", method.meanAbsErrorFrames},
                               {"max_abs_error_frames", method.maxAbsErrorFrames},
                               {"arm_hand_within_range", method.armHandWithinRange},
                               {"arm_hand_max_excess_cm", method.armHandMaxExcessCm}});
        printJson({{"methods", methods},
                   {"cells", result.cells},
                   {"pairs", result.pairs},
                   {"coupling", options.normalise.coupling},
                   {"arm_hand_together", optimal && optimal->armHandWithinRange >= 0.99}});
        return;
    }
    std::cout << result.cells << " cells, " << result.pairs << " take pairs per method (coupling "
              << options.normalise.coupling << ")\n"
              << "method                        mean |err|  max |err|  arm-hand in range\n";
    for (const auto& method : result.methods)
        std::cout << std::left << std::setw(30) << method.name << std::right << std::fixed << std::setprecision(3)
                  << std::setw(10) << method.meanAbsErrorFrames << std::setw(11) << method.maxAbsErrorFrames
                  << std::setw(18) << method.armHandWithinRange << "\n";
}

} // namespace

void addNormalisationCommands(CommandSet& commands)
{
    {
        auto arguments = std::make_shared<NormaliseArguments>();
        CLI::App* command = addCommand(commands.root, "normalise",
            "Normalise the takes of one function x emotion cell in time by wavelet matching (thesis ch. 3): "
            "writes the normalised takes, correspondences, the reference and the variance table",
            arguments, runNormalise);
        command->add_option("CORPUS", arguments->corpus, "Corpus folder")->required()->check(CLI::ExistingDirectory);
        command->add_option("--function", arguments->function, "Function label, e.g. greeting")->required();
        command->add_option("--emotion", arguments->emotion, "Emotion label, e.g. none")->required();
        command->add_option("--reference", arguments->reference,
                            "Reference: a take index, or 'average' (thesis 3.7); default the suggested take (3.6.1)");
        command->add_option("--exclude", arguments->exclude, "Take index left out of the average (e.g. the outlier: 4ave)")
            ->transform(parameterCheck("normalise.averageExcluded"));
        command->add_option("--base", arguments->base, "Base take of the average (0, the default: the suggested reference)")
            ->transform(parameterCheck("normalise.averageBase"));
        command->add_option("-o,--output", arguments->output,
                            "Output folder; or a take file (.bvh, .glb, .csv): the reference alone (the average take with "
                            "--reference average)")
            ->required()
            ->type_name("DIR|FILE");
        command->add_flag("--no-preprocess", arguments->noPreprocess,
                          "Use the takes as stored (default: thesis 2.2 preprocessing first, as `bunraku preprocess`)");
        addMatchOptions(command, arguments->match, false);
        addKimonoOutputOptions(command, arguments->kimono);
    }
    {
        auto json = std::make_shared<bool>(false);
        CLI::App* command = commands.experiment.add_subcommand(
            "noise", "Thesis 3.4: wavelet matching below the noise band vs with it vs amplitude matching");
        command->add_flag("--json", *json, "Print a machine-readable summary");
        command->callback([json] { runNoise(*json); });
    }
    {
        auto arguments = std::make_shared<TruthArguments>();
        CLI::App* command = addCommand(commands.experiment, "truth",
            "Normalise every take of the synthetic corpus to its cell's reference and compare the "
            "correspondences with the ground truth (greedy, optimal, amplitude DTW)",
            arguments, runTruth);
        command->add_option("CORPUS", arguments->corpus, "Demo corpus folder (with truth/ from `bunraku demo`)")
            ->required()
            ->check(CLI::ExistingDirectory);
        command->add_option("--reference", arguments->reference, "Reference take index in every cell (default: suggested)");
        // The workbench and `normalise` use auto; the experiment compares the readings.
        addMatchOptions(command, arguments->match, true);
    }
}

} // namespace bunraku::app::cli
