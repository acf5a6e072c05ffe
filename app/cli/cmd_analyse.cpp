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

namespace bunraku::app::cli {
namespace {

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
    addKm2oSummary(summary, *chain->decomposed);
    if (arguments.json) {
        std::cout << summary.dump() << std::endl;
        return;
    }
    std::cout << "analysed " << corpus.corpus->takes.size() << " takes in " << chain->normalised->cells.size() << " cells";
    if (const auto& km2o = chain->decomposed->km2o; km2o && km2o->estimable())
        std::cout << " (KM2O M = " << km2o->correlationLength << ", mean P = " << km2o->meanCellErrorPercent << " %)";
    std::cout << ": " << files.size() << " files and the report " << summary["report"].get<std::string>() << "\n";
    if (chain->axes && !chain->axes->unavailable.empty()) std::cout << chain->axes->unavailable << "\n";
    printKm2oNotes(*chain->decomposed);
}

} // namespace

void addAnalyseCommands(CommandSet& commands)
{
    auto [command, arguments] =
        addCommand(commands.root, "analyse", runAnalyse, "Progress and the summary as JSON lines on standard output");
    command->add_option("CORPUS", arguments.corpus, "Corpus folder (corpus.json), or 'demo' for the embedded demo corpus")->required();
    command->add_option("-o,--output", arguments.output, "Output folder")->required()->type_name("DIR");
    command->add_option("--parameters", arguments.parameters,
                        "JSON file of the chain's parameters (docs/FORMATS.md), or a project file; default the thesis's, but "
                        "for normalisation's optimal path")
        ->type_name("FILE");
    command->add_option("--threads", arguments.threads,
                        "Threads for the stages that split into cells and channels, 0 = one per hardware thread; the results are "
                        "the same for any count")
        ->check(CLI::Range(0, analysis::kMaxThreads))
        ->capture_default_str();
}

} // namespace bunraku::app::cli
