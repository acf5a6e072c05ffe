// Subcommands: decompose, emotion, experiment km2o.
#include "app/cli/commands.h"
#include "app/cli/take_output.h"
#include "app/cli/output_guard.h"

#include "analysis/decompose/arma.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/km2o_experiment.h"
#include "analysis/decompose/least_squares.h"
#include "analysis/decompose/spectrum.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/stages.h"
#include "analysis/report/analysis_files.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/synth/demo_corpus.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;
using namespace bunraku::analysis;

struct CorpusInput {
    std::string path;
    bool pad = false;
};

/// Reads the corpus; pads every take to the longest (thesis 2.2 step 1) when asked, else
/// decomposition reports unequal lengths.
Corpus loadCorpus(const CorpusInput& input)
{
    Corpus corpus = unwrap(io::readCorpus(input.path));
    Eigen::Index longest = 0;
    for (const auto& take : corpus.takes) longest = std::max(longest, take.frameCount());
    for (auto& take : corpus.takes) {
        if (take.frameCount() == longest) continue;
        if (!input.pad)
            throw CliError(input.path + ": take " + take.displayName() + " has " + std::to_string(take.frameCount()) + " frames, the longest " +
                           std::to_string(longest) + ": pad with --pad (thesis 2.2) or time-normalise the corpus first");
        preprocess::padToLength(take, longest);
    }
    return corpus;
}

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

enum class Method { LeastSquares, Km2o };

struct DecomposeSettings {
    Method method = Method::LeastSquares;
    int correlationLength = 0;
};

struct Outcome {
    Decomposition components;
    std::optional<Km2oDecomposition> km2o; ///< with --method km2o
};

/// The pipeline's decompose stage (analysis/pipeline), as the workbench runs it, on the corpus
/// as given (already preprocessed or normalised by the user).
Outcome decompose(const Corpus& corpus, const DecomposeSettings& settings)
{
    if (settings.method == Method::LeastSquares && settings.correlationLength != 0)
        throw CliError("--M applies to --method km2o only");
    pipeline::DecomposeParameters parameters;
    parameters.input = pipeline::DecomposeInput::Preprocessed;
    parameters.method = settings.method == Method::Km2o ? pipeline::DecomposeMethod::Km2o : pipeline::DecomposeMethod::LeastSquares;
    parameters.correlationLength = settings.correlationLength;
    pipeline::DecomposeOutput output = unwrap(pipeline::runDecompose(corpus, parameters));
    return {std::move(output.components), std::move(output.km2o)};
}

/// Table 4.5 layout: one row per channel, one P^{ij} [%] column per cell.
std::string km2oErrorCsv(const Km2oDecomposition& km2o)
{
    const Decomposition& d = km2o.components;
    std::ostringstream out;
    out << std::setprecision(4) << std::fixed << "channel";
    for (const auto& z : d.emotions) out << ",P_" << z.function << "/" << z.emotion;
    out << '\n';
    for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
        out << d.channels[ch].name();
        for (Eigen::Index c = 0; c < km2o.cellErrorPercent.cols(); ++c) out << ',' << km2o.cellErrorPercent(Eigen::Index(ch), c);
        out << '\n';
    }
    return out.str();
}

Take asTake(const Decomposition& d, const Eigen::MatrixXd& values, TakeLabels labels)
{
    Take take;
    take.values = values;
    take.rateHz = d.rateHz;
    take.channels = d.channels;
    take.labels = std::move(labels);
    return take;
}

std::string spectraCsv(const Decomposition& d, bool useWelch)
{
    std::ostringstream out;
    out << std::setprecision(10) << "function,emotion,take,channel,frequency_hz,power\n";
    for (const auto& eta : d.fluctuations) {
        if (cellTakeCount(d, eta.labels.function, eta.labels.emotion) < 2) continue; // one take: no fluctuation (eq. 4.24)
        for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
            const Eigen::VectorXd x = eta.values.col(Eigen::Index(ch));
            WelchOptions welchOptions;
            welchOptions.segmentLength = std::min<int>(32, int(x.size()));
            const Spectrum s = unwrap(useWelch ? welch(x, d.rateHz, welchOptions) : periodogram(x, d.rateHz));
            for (Eigen::Index k = 0; k < s.power.size(); ++k)
                out << eta.labels.function << ',' << eta.labels.emotion << ',' << eta.labels.takeIndex << ','
                    << d.channels[ch].name() << ',' << s.frequencyHz(k) << ',' << s.power(k) << '\n';
        }
    }
    return out.str();
}

std::string armaTakesCsv(const Decomposition& d, ArmaOrderSearch search, int maxOrder)
{
    std::ostringstream out;
    out << std::setprecision(8) << "function,emotion,take,channel,p,q,fpe,innovation_variance";
    for (int m = 1; m <= maxOrder; ++m) out << ",a" << m;
    for (int n = 0; n <= maxOrder; ++n) out << ",b" << n;
    for (int n = 0; n <= maxOrder; ++n) out << ",b" << n << "_thesis";
    out << '\n';
    ArmaOrderOptions options;
    options.maxOrder = maxOrder;
    options.search = search;
    for (const auto& eta : d.fluctuations) {
        if (cellTakeCount(d, eta.labels.function, eta.labels.emotion) < 2) continue; // one take: no fluctuation (eq. 4.24)
        for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
            const Eigen::VectorXd x = eta.values.col(Eigen::Index(ch));
            if (!(x.squaredNorm() > 0.0)) continue;
            auto selection = selectArmaOrder(x, options);
            if (!selection) continue; // too short for any order: nothing to report
            const ArmaModel& m = selection->best;
            out << eta.labels.function << ',' << eta.labels.emotion << ',' << eta.labels.takeIndex << ','
                << d.channels[ch].name() << ',' << m.p << ',' << m.q << ',' << m.fpe << ',' << m.innovationVariance;
            for (int i = 0; i < maxOrder; ++i) out << ',' << (i < m.p ? std::to_string(m.a(i)) : "");
            for (int i = 0; i <= maxOrder; ++i) out << ',' << (i <= m.q ? std::to_string(m.b(i)) : "");
            for (int i = 0; i <= maxOrder; ++i) out << ',' << (i <= m.q ? std::to_string(m.bThesis(i)) : "");
            out << '\n';
        }
    }
    return out.str();
}

std::string armaTableCsv(const Decomposition& d, int p, int q)
{
    std::ostringstream out;
    out << std::setprecision(6) << std::fixed << "channel,function,emotion,takes";
    for (int m = 1; m <= p; ++m) out << ",a" << m;
    for (int n = 0; n <= q; ++n) out << ",b" << n;
    for (int n = 0; n <= q; ++n) out << ",b" << n << "_thesis";
    out << ",innovation_variance,fpe\n";
    for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
        auto rows = armaCellTable(d, Eigen::Index(ch), p, q);
        if (!rows) continue;
        for (const auto& row : *rows) {
            if (row.takes == 0) continue;
            out << d.channels[ch].name() << ',' << row.function << ',' << row.emotion << ',' << row.takes;
            for (int m = 0; m < p; ++m) out << ',' << row.mean.a(m);
            for (int n = 0; n <= q; ++n) out << ',' << row.mean.b(n);
            for (int n = 0; n <= q; ++n) out << ',' << row.mean.bThesis(n);
            out << ',' << row.mean.innovationVariance << ',' << row.mean.fpe << '\n';
        }
    }
    return out.str();
}

/// Relative error (eq. 4.40 style, percent) of y^i and z^{ij} against the synthetic truth.
nlohmann::json truthErrors(const Decomposition& d, const synth::DemoGroundTruth& truth)
{
    nlohmann::json out = nlohmann::json::object();
    auto percent = [](const Eigen::MatrixXd& estimate, const Eigen::MatrixXd& reference) {
        const double den = reference.squaredNorm();
        return den > 0.0 ? 100.0 * (estimate - reference).squaredNorm() / den : 0.0;
    };
    auto rms = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
        return std::sqrt((a - b).squaredNorm() / double(std::max<Eigen::Index>(1, a.size())));
    };
    // y as a pose (Euler angles, compared modulo 360); z as rotation coordinates about the
    // function's chart on both sides (the truth's z is the difference of its cell motion and y).
    auto truthTake = [&](const Eigen::MatrixXd& values) {
        Take take;
        take.values = values;
        take.channels = d.channels;
        return take;
    };
    for (std::size_t i = 0; i < d.functions.size(); ++i) {
        const auto& f = d.functions[i];
        const auto* t = truth.function(f.function);
        if (!t || t->motion.rows() != f.values.rows() || t->motion.cols() != f.values.cols()) continue;
        Eigen::MatrixXd y = unwrap(functionComponentTake(d, f.function)).values;
        for (Eigen::Index c = 0; c < y.cols(); ++c)
            if (d.channels[std::size_t(c)].unit == "deg")
                for (Eigen::Index r = 0; r < y.rows(); ++r) y(r, c) = t->motion(r, c) + std::remainder(y(r, c) - t->motion(r, c), 360.0);
        out["y"][f.function] = {{"relative_error_percent", percent(y, t->motion)}, {"rms", rms(y, t->motion)}};
    }
    for (const auto& z : d.emotions) {
        const auto* t = truth.cell(z.function, z.emotion);
        const auto* y = truth.function(z.function);
        const int function = [&] {
            for (std::size_t i = 0; i < d.functions.size(); ++i)
                if (d.functions[i].function == z.function) return int(i);
            return -1;
        }();
        if (!t || !y || function < 0 || t->motion.rows() != z.values.rows() || t->motion.cols() != z.values.cols() ||
            y->motion.rows() != z.values.rows())
            continue;
        const RotationChart& chart = d.charts[std::size_t(function)];
        const Eigen::MatrixXd trueZ = rotationCoordinates(truthTake(t->motion), chart) - rotationCoordinates(truthTake(y->motion), chart);
        out["z"][z.function + "/" + z.emotion] = {{"rms", rms(z.values, trueZ)}};
    }
    return out;
}

struct DecomposeArgs {
    CorpusInput corpus;
    std::string method = "km2o"; // thesis 4.4.4: KM2O, M chosen by P
    int correlationLength = 0;
    std::string output;
    std::string truth;
    std::string armaSearch = "equal";
    int armaMaxOrder = 4;
    std::vector<int> armaTableOrder{2, 2};
    bool json = false;
};

void runDecompose(const DecomposeArgs& args)
{
    if (args.armaTableOrder.size() != 2) throw CliError("--arma-table takes two orders: p q");
    refuseOutputOverInputs(args.output, OutputKind::Folder, {args.corpus.path, args.truth});
    const Corpus corpus = loadCorpus(args.corpus);
    DecomposeSettings settings;
    settings.method = args.method == "km2o" ? Method::Km2o : Method::LeastSquares;
    settings.correlationLength = args.correlationLength;
    nlohmann::json summary;
    summary["corpus"] = args.corpus.path;
    summary["method"] = args.method;
    const Outcome outcome = aboutCorpus(args.corpus.path, [&] { return decompose(corpus, settings); });
    const Decomposition& d = outcome.components;

    // Every output is computed before anything is written: bad input writes nothing.
    const fs::path out = args.output;
    std::vector<std::pair<std::string, std::string>> outputs; // file name, content
    auto addTake = [&](const Take& take, const std::string& name) {
        if (auto valid = validateTake(take); !valid) throw CliError(name + ": " + valid.error().message);
        outputs.emplace_back(name, io::formatTakeCsv(take));
    };
    aboutCorpus(args.corpus.path, [&] {
        // y as a pose (Euler angles); z and eta are differences: rotation coordinates (deg).
        for (const auto& f : d.functions) {
            Take y = unwrap(functionComponentTake(d, f.function));
            y.labels = {f.function, "", 0, "y"};
            addTake(y, "y_" + io::fileSafeLabel(f.function) + ".csv");
        }
        for (const auto& z : d.emotions)
            addTake(asTake(d, z.values, {z.function, z.emotion, 0, "z"}),
                    "z_" + io::fileSafeLabel(z.function) + "_" + io::fileSafeLabel(z.emotion) + ".csv");
        for (const auto& eta : d.fluctuations)
            addTake(asTake(d, eta.values, eta.labels), "eta_" + io::fileSafeLabel(eta.labels.function) + "_" +
                                                           io::fileSafeLabel(eta.labels.emotion) + "_" +
                                                           std::to_string(eta.labels.takeIndex) + ".csv");
        outputs.emplace_back("spectra_periodogram.csv", spectraCsv(d, false));
        outputs.emplace_back("spectra_welch.csv", spectraCsv(d, true));
        const ArmaOrderSearch search = args.armaSearch == "all" ? ArmaOrderSearch::AllPairs : ArmaOrderSearch::EqualOrders;
        outputs.emplace_back("arma_takes.csv", armaTakesCsv(d, search, args.armaMaxOrder));
        outputs.emplace_back("arma_table.csv", armaTableCsv(d, args.armaTableOrder[0], args.armaTableOrder[1]));
    });
    if (outcome.km2o) {
        const Km2oDecomposition& km2o = *outcome.km2o;
        outputs.emplace_back("km2o_errors.csv", km2oErrorCsv(km2o));
        std::ostringstream byM;
        byM << "M,mean_P_percent\n";
        for (std::size_t i = 0; i < km2o.candidateLengths.size(); ++i)
            byM << km2o.candidateLengths[i] << ',' << km2o.meanErrorPercent[i] << '\n';
        outputs.emplace_back("km2o_by_M.csv", byM.str());
        summary["km2o"] = analysis::report::km2oOutcomeJson(km2o);
        if (km2o.estimable()) { // else no M was chosen: y, z by least squares
            summary["M"] = km2o.correlationLength;
            summary["candidate_M"] = km2o.candidateLengths;
            summary["mean_P_percent_by_M"] = km2o.meanErrorPercent;
            summary["mean_P_percent"] = km2o.meanCellErrorPercent;
        }
    }

    fs::path truthFolder = args.truth;
    if (truthFolder.empty() && fs::exists(fs::path(args.corpus.path) / "truth" / "truth.json"))
        truthFolder = fs::path(args.corpus.path) / "truth";
    if (!truthFolder.empty()) {
        const auto truth = unwrap(synth::readGroundTruth(truthFolder));
        summary["truth"] = truthErrors(d, truth);
        summary["truth_folder"] = truthFolder.string();
    }
    std::vector<std::string> files;
    for (const auto& [name, content] : outputs) files.push_back(name);
    summary["functions"] = nlohmann::json::array();
    for (const auto& f : d.functions) summary["functions"].push_back(f.function);
    summary["cells"] = nlohmann::json::array();
    for (const auto& z : d.emotions) summary["cells"].push_back(z.function + "/" + z.emotion);
    summary["frames"] = d.frameCount();
    summary["channels"] = d.channels.size();
    summary["files"] = files;
    summary["output"] = out.string();
    outputs.emplace_back("summary.json", summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");

    // Built in a hidden folder and swapped in: the previous output stays whole until then.
    io::StagedFolder staged = unwrap(io::StagedFolder::begin(out));
    for (const auto& [name, content] : outputs) unwrap(staged.writeFile(name, content));
    unwrap(staged.commit());
    if (args.json) {
        printJson(summary);
    } else {
        std::cout << "decomposed " << corpus.takes.size() << " takes (" << args.method << ") into " << out.string() << ": "
                  << d.functions.size() << " y, " << d.emotions.size() << " z, " << d.fluctuations.size() << " eta\n";
        if (summary.contains("M"))
            std::cout << "KM2O correlation length M = " << summary["M"] << ", mean P = " << summary["mean_P_percent"] << " %\n";
        if (outcome.km2o && !outcome.km2o->notes.empty()) {
            std::cout << outcome.km2o->outcome() << "\n";
            for (const auto& note : outcome.km2o->notes) std::cout << "  " << note << "\n";
        }
        if (summary.contains("truth")) std::cout << "error against ground truth: " << summary["truth"].dump() << "\n";
    }
}

struct EmotionArgs {
    CorpusInput corpus;
    std::string function;
    std::string emotion;
    double weight = 1.0;
    std::string method = "km2o";
    int correlationLength = 0;
    std::string output;
};

void runEmotion(const EmotionArgs& args)
{
    requireTakeOutput(args.output);
    refuseOutputOverInputs(args.output, OutputKind::File, {args.corpus.path});
    const Corpus corpus = loadCorpus(args.corpus);
    DecomposeSettings settings;
    settings.method = args.method == "km2o" ? Method::Km2o : Method::LeastSquares;
    settings.correlationLength = args.correlationLength;
    const Outcome outcome = aboutCorpus(args.corpus.path, [&] { return decompose(corpus, settings); });
    const Decomposition& d = outcome.components;
    const Take take =
        aboutCorpus(args.corpus.path, [&] { return unwrap(weightEmotion(d, args.function, args.emotion, args.weight)); });
    writeTakeOutput(take, args.output);
    std::cout << "wrote " << args.output << ": " << args.function << "/" << args.emotion << " with emotion weight a = " << args.weight
              << " (" << take.frameCount() << " frames)\n";
}

struct ExperimentArgs {
    int finalTime = 300;
    std::string range = "3:20";
    int seeds = 5;
    std::uint64_t firstSeed = 1;
    double noise = 0.0;
    int firstOffset = -1;
    std::string initialTimes = "full";
    std::string noiseSharing = "per-cell";
    int takes = 5;
    bool json = false;
};

void runExperiment(const ExperimentArgs& args)
{
    Km2oExperimentOptions options;
    options.finalTime = args.finalTime;
    const auto colon = args.range.find(':');
    // The whole text of each part must be a number ("3x:20" is refused, not read as 3:20).
    const auto whole = [&](const std::string& text) {
        std::size_t used = 0;
        const int value = std::stoi(text, &used);
        if (used != text.size()) throw std::invalid_argument(text);
        return value;
    };
    try {
        if (colon == std::string::npos) {
            options.firstM = options.lastM = whole(args.range);
        } else {
            options.firstM = whole(args.range.substr(0, colon));
            options.lastM = whole(args.range.substr(colon + 1));
        }
    } catch (const std::exception&) {
        throw CliError("--M expects FIRST:LAST (e.g. 3:20), got '" + args.range + "'");
    }
    options.seeds = args.seeds;
    options.firstSeed = args.firstSeed;
    if (args.noise > 0.0) options.noiseScale = args.noise;
    if (args.firstOffset >= 0) options.reading.firstWindowOffset = args.firstOffset;
    options.reading.initialTimes = args.initialTimes == "thesis" ? InitialTimeRange::Thesis : InitialTimeRange::Full;
    options.noise = args.noiseSharing == "shared" ? NoiseSharing::SharedAcrossCells : NoiseSharing::PerCell;
    options.takes = args.takes;
    const auto result = unwrap(runKm2oExperiment(options));
    const auto printed = thesisTable44Printed(result.finalTime);
    // Table 4.4 as printed beside each M (T = 1000 in units of 0.1 %, so also "read as %").
    std::vector<double> asPrinted;
    for (int m : result.correlationLengths)
        asPrinted.push_back(m >= 3 && m <= 20 && !printed.empty() ? printed[std::size_t(m - 3)]
                                                                  : std::numeric_limits<double>::quiet_NaN());
    if (args.json) {
        auto clean = [](const std::vector<double>& v) {
            nlohmann::json a = nlohmann::json::array();
            for (double x : v) a.push_back(std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr));
            return a;
        };
        printJson({{"T", result.finalTime},
                   {"M", result.correlationLengths},
                   {"P_percent", clean(result.errorPercent)},
                   {"thesis_P_percent", clean(result.thesisErrorPercent)},
                   {"thesis_printed", clean(asPrinted)},
                   {"seeds", args.seeds},
                   {"takes", options.takes},
                   {"noise_sharing", args.noiseSharing},
                   {"first_window_offset", options.reading.firstWindowOffset},
                   {"initial_times", args.initialTimes}});
        return;
    }
    std::cout << "KM2O exogenous-input identification of the eq. 4.39 ARX series, T = " << result.finalTime << ", K = "
              << options.takes << ", " << args.seeds << " seed(s), noise " << args.noiseSharing
              << "; P = relative error (eq. 4.40) averaged over the six inputs\n";
    const bool tenths = result.finalTime == 1000;
    std::cout << "   M    P [%]   thesis Table 4.4 [%]" << (tenths ? "   (printed, read as %)" : "") << "\n";
    for (std::size_t i = 0; i < result.correlationLengths.size(); ++i) {
        std::cout << std::setw(4) << result.correlationLengths[i] << std::setw(9) << std::fixed << std::setprecision(3)
                  << result.errorPercent[i] << "   ";
        if (std::isfinite(result.thesisErrorPercent[i])) std::cout << std::setw(8) << result.thesisErrorPercent[i];
        else std::cout << "       -";
        if (tenths && std::isfinite(asPrinted[i])) std::cout << std::setw(25) << asPrinted[i];
        std::cout << "\n";
    }
}

} // namespace

void addDecompositionCommands(CommandSet& commands)
{
    auto decomposeArgs = std::make_shared<DecomposeArgs>();
    CLI::App* dec = commands.root.add_subcommand(
        "decompose", "Decompose a corpus into function y^i, emotion z^{ij} and fluctuation eta (thesis ch. 4); write "
                     "components, spectra and ARMA tables");
    dec->add_option("corpus", decomposeArgs->corpus.path, "Corpus folder (corpus.json)")->required();
    dec->add_option("--method", decomposeArgs->method, "km2o (KM2O-Langevin, 4.4.4; default) or ls (least squares, 4.3.1)")
        ->check(CLI::IsMember({"ls", "km2o"}));
    dec->add_option("--M", decomposeArgs->correlationLength,
                    "KM2O correlation length M (1..M_max); default: chosen by reconstruction error");
    dec->add_option("-o,--output", decomposeArgs->output, "Output folder")->required();
    dec->add_option("--truth", decomposeArgs->truth,
                    "Ground-truth folder of a synthetic corpus (default: CORPUS/truth when it exists)");
    dec->add_option("--arma-search", decomposeArgs->armaSearch, "ARMA orders tried per take: equal ((n,n)) or all ((p,q))")
        ->check(CLI::IsMember({"equal", "all"}));
    dec->add_option("--arma-max-order", decomposeArgs->armaMaxOrder, "Largest ARMA order for FPE selection")
        ->check(CLI::Range(0, 4));
    dec->add_option("--arma-table", decomposeArgs->armaTableOrder, "ARMA(p,q) averaged per cell (Table 4.1), each 0..4")
        ->expected(2)
        ->check(CLI::Range(0, 4));
    dec->add_flag("--pad", decomposeArgs->corpus.pad, "Pad takes to the longest by repeating the last frame");
    dec->add_flag("--json", decomposeArgs->json, "Print a JSON summary");
    dec->callback([decomposeArgs] { runDecompose(*decomposeArgs); });

    auto emotionArgs = std::make_shared<EmotionArgs>();
    CLI::App* emo = commands.root.add_subcommand(
        "emotion", "Design a motion with an emotion weight: x = y^i + a z^{ij} (thesis eq. 4.45)");
    emo->add_option("corpus", emotionArgs->corpus.path, "Corpus folder (corpus.json)")->required();
    emo->add_option("--function", emotionArgs->function, "Function label, e.g. greeting")->required();
    emo->add_option("--emotion", emotionArgs->emotion, "Emotion label, e.g. friendly")->required();
    emo->add_option("--weight", emotionArgs->weight, "Emotion weight a in [0, 3] (1 = as performed)")->required();
    emo->add_option("--method", emotionArgs->method, "km2o (default, M chosen by P unless --M) or ls")->check(CLI::IsMember({"ls", "km2o"}));
    emo->add_option("--M", emotionArgs->correlationLength, "KM2O correlation length");
    emo->add_option("-o,--output", emotionArgs->output, "Output take (.bvh, .glb or .csv)")->required();
    emo->add_flag("--pad", emotionArgs->corpus.pad, "Pad takes to the longest by repeating the last frame");
    emo->callback([emotionArgs] { runEmotion(*emotionArgs); });

    auto experimentArgs = std::make_shared<ExperimentArgs>();
    CLI::App* exp = commands.experiment.add_subcommand(
        "km2o", "Thesis 4.4.3: identify the exogenous inputs of simulated ARX series (eq. 4.39) for each M and compare "
                "the relative error P with Table 4.4");
    exp->add_option("--T", experimentArgs->finalTime, "Final time T: 300 (Table 4.2) or 1000 (Table 4.3)")
        ->check(CLI::IsMember({300, 1000}));
    exp->add_option("--M", experimentArgs->range, "Correlation lengths FIRST:LAST (default 3:20)");
    exp->add_option("--seeds", experimentArgs->seeds, "Simulations averaged (default 5)")->check(CLI::PositiveNumber);
    exp->add_option("--seed", experimentArgs->firstSeed, "First seed");
    exp->add_option("--noise", experimentArgs->noise, "Noise scale c (default: the table's)");
    exp->add_option("--first-offset", experimentArgs->firstOffset,
                    "Window offsets below this are used only where nothing else reaches (default 1; see docs/KM2O.md)")
        ->check(CLI::Range(0, 100));
    exp->add_option("--initial-times", experimentArgs->initialTimes, "T0 range: full (0..T-M) or thesis (0..T-M-1)")
        ->check(CLI::IsMember({"full", "thesis"}));
    exp->add_option("--noise-sharing", experimentArgs->noiseSharing,
                    "per-cell (an independent w_k(t) per cell, default) or shared (one w_k(t) for all six cells: eq. "
                    "4.39 puts no i, j on w)")
        ->check(CLI::IsMember({"per-cell", "shared"}));
    exp->add_option("--takes", experimentArgs->takes, "K, takes per cell (default 5, as the thesis)")->check(CLI::Range(2, 1000));
    exp->add_flag("--json", experimentArgs->json, "Print JSON");
    exp->callback([experimentArgs] { runExperiment(*experimentArgs); });
}

} // namespace bunraku::app::cli
