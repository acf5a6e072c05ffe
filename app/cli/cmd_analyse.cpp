// Subcommand: analyse - the thesis's whole chain (analysis/pipeline) with data files and the
// HTML report (analysis/report).
#include "app/cli/commands.h"
#include "app/cli/chain_parameters.h"
#include "app/cli/output_guard.h"

#include "analysis/core/parallel.h"

#include "analysis/pipeline/chain.h"
#include "analysis/report/analysis_files.h"
#include "analysis/report/html_report.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace bunraku::app::cli {
namespace {

namespace pl = bunraku::analysis::pipeline;
namespace rp = bunraku::analysis::report;

struct AnalyseArguments {
    std::string corpus;
    std::string output;
    std::string parameters;
    bool json = false;
    int threads = 0;
};

/// One line per stage on a terminal, redrawn in place: "[#####.....] Normalisation (3)  40 %".
class ProgressBar {
public:
    void update(pl::Stage stage, double fraction)
    {
        const int filled = int(fraction * 30.0 + 0.5);
        std::fprintf(stderr, "\r%-36s [%s%s] %3d %%", pl::stageTitle(stage), std::string(std::size_t(filled), '#').c_str(),
                     std::string(std::size_t(30 - filled), '.').c_str(), int(fraction * 100.0 + 0.5));
        if (fraction >= 1.0) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }
};

void runAnalyse(const AnalyseArguments& arguments)
{
    refuseOutputOverInputs(arguments.output, OutputKind::Folder, {arguments.corpus, arguments.parameters});
    const pl::ChainParameters parameters = readChainParameters(arguments.parameters);
    const pl::CorpusInput corpus = unwrap(pl::importCorpus(arguments.corpus));
    const bool terminal = ::isatty(STDERR_FILENO) == 1;
    ProgressBar bar;
    pl::ChainOptions options;
    options.threads = analysis::resolveThreads(arguments.threads);
    const auto started = std::chrono::steady_clock::now();
    options.progress = [&](pl::Stage stage, double fraction) {
        if (arguments.json) {
            std::cout << nlohmann::json{{"stage", pl::stageName(stage)}, {"title", pl::stageTitle(stage)}, {"fraction", fraction}}.dump()
                      << std::endl;
        } else if (terminal) {
            bar.update(stage, fraction);
        }
    };
    auto chain = pl::runChain(corpus, parameters, nullptr, options);
    if (!chain) throw CliError(chainSubject(arguments.corpus, arguments.parameters) + ": " + chain.error().message);
    std::vector<rp::OutputFile> files = unwrap(rp::analysisDataFiles(*chain, parameters));
    rp::ReportOptions report;
    report.title = "Bunraku motion analysis: " + (corpus.corpus->name.empty() ? arguments.corpus : corpus.corpus->name);
    report.corpusSource = arguments.corpus;
    report.generator = std::string("bunraku analyse ") + BUNRAKU_VERSION;
    files.push_back({"report.html", unwrap(rp::htmlReport(*chain, parameters, report))});
    unwrap(rp::writeOutputFiles(arguments.output, files));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    nlohmann::json summary{{"done", true},
                           {"output", arguments.output},
                           {"report", (std::filesystem::path(arguments.output) / "report.html").string()},
                           {"files", files.size()},
                           {"cells", chain->normalised->cells.size()},
                           {"takes", corpus.corpus->takes.size()},
                           {"threads", options.threads},
                           {"seconds", seconds}};
    if (chain->axes && !chain->axes->unavailable.empty()) summary["skipped"] = {chain->axes->unavailable};
    if (const auto& km2o = chain->decomposed->km2o) {
        summary["km2o"] = rp::km2oOutcomeJson(*km2o);
        if (km2o->estimable()) {
            summary["M"] = km2o->correlationLength;
            summary["mean_P_percent"] = km2o->meanCellErrorPercent;
        }
    }
    if (arguments.json) {
        std::cout << summary.dump() << std::endl;
        return;
    }
    std::cout << "analysed " << corpus.corpus->takes.size() << " takes in " << chain->normalised->cells.size() << " cells";
    if (const auto& km2o = chain->decomposed->km2o; km2o && km2o->estimable())
        std::cout << " (KM2O M = " << km2o->correlationLength << ", mean P = " << km2o->meanCellErrorPercent << " %)";
    std::cout << ": " << files.size() << " files and the report " << summary["report"].get<std::string>() << "\n";
    if (chain->axes && !chain->axes->unavailable.empty()) std::cout << chain->axes->unavailable << "\n";
    if (const auto& km2o = chain->decomposed->km2o; km2o && !km2o->notes.empty()) {
        std::cout << km2o->outcome() << "\n";
        for (const auto& note : km2o->notes) std::cout << "  " << note << "\n";
    }
}

} // namespace

void addAnalyseCommands(CommandSet& commands)
{
    auto arguments = std::make_shared<AnalyseArguments>();
    CLI::App* command = addCommand(commands.root, "analyse",
        "The thesis's whole chain: preprocess (2.2), normalise every cell (3), decompose (4: KM2O with M chosen by "
        "P), spectra and ARMA (4.3.2), motion axes, phase and gains (5); writes the data files and report.html. A corpus of a "
        "skeleton's joints (--all-joints) is normalised with the chains coupling; the motion axes need the puppet's 4 "
        "parts and are skipped with a note",
        arguments, runAnalyse, "Progress and the summary as JSON lines on standard output");
    command->add_option("CORPUS", arguments->corpus, "Corpus folder (corpus.json), or 'demo' for the embedded demo corpus")->required();
    command->add_option("-o,--output", arguments->output, "Output folder")->required()->type_name("DIR");
    command->add_option("--parameters", arguments->parameters,
                        "JSON file of the chain's parameters (docs/FORMATS.md), or a project file; default the thesis's, but "
                        "for normalisation's optimal path")
        ->type_name("FILE");
    command->add_option("--threads", arguments->threads,
                        "Threads for the stages that split into cells and channels, 0 = one per hardware thread; the results are "
                        "the same for any count")
        ->check(CLI::Range(0, analysis::kMaxThreads))
        ->capture_default_str();
}

} // namespace bunraku::app::cli
