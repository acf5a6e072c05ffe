// Subcommand: experiment approximation - the per-scale approximation error of thesis 5.4.1
// (eq. 5.18, Fig. 5.16) for every emotional cell of a corpus, through the pipeline's stages.
#include "app/cli/commands.h"
#include "app/cli/chain_parameters.h"

#include "analysis/io/atomic_file.h"
#include "analysis/pipeline/chain.h"
#include "analysis/report/approximation_table.h"

#include <iostream>
#include <string>

namespace bunraku::app::cli {
namespace {

struct ApproximationArguments {
    std::string corpus;
    int maxScale = 16;
    std::string csv;
    bool json = false;
};

void runApproximation(const ApproximationArguments& arguments)
{
    pl::ChainParameters parameters;
    parameters.normalise.path = an::PathMethod::Greedy; // the thesis's scan (3.5.3), not the workbench's default
    parameters.axis.maxScale = arguments.maxScale;
    // The workbench's own stages: preprocess (2.2), normalise with average takes (3.7), axes,
    // phase and gains (5.2-5.4) - the approximation error is computed by the axis stage.
    pl::ChainOptions options;
    options.decomposition = options.fluctuations = false;
    const pl::ChainResult chain = unwrap(pl::runChain(unwrap(pl::importCorpus(arguments.corpus)), parameters, nullptr, options));
    const pl::AxisOutput* axes = chain.axes.get();
    if (!axes->unavailable.empty()) throw CliError(arguments.corpus + ": " + axes->unavailable);
    if (!arguments.csv.empty()) unwrap(an::io::writeFileAtomically(arguments.csv, rp::approximationCsv(*axes)));
    nlohmann::json summary{{"corpus", arguments.corpus},
                           {"equation", "5.18: sqrt(sum |A_e - A_f|^2) / sqrt(sum |X_f|^2), scales 1..c"},
                           {"thesis_figure", rp::kApproximationThesisFigure},
                           {"cells", rp::approximationJson(*axes)}};
    if (!arguments.csv.empty()) summary["csv"] = arguments.csv;
    report(arguments.json, summary, [&] {
        std::cout << rp::approximationText(*axes);
        if (!arguments.csv.empty()) std::cout << "wrote " << arguments.csv << "\n";
    });
}
} // namespace

void addApproximationCommands(CommandSet& commands)
{
    auto [command, arguments] = addCommand(commands.experiment, "approximation", runApproximation);
    command->add_option("CORPUS", arguments.corpus, "Corpus folder (corpus.json), or 'demo' for the embedded synthetic corpus")
        ->required();
    command->add_option("--max-scale", arguments.maxScale, "Largest scale c (default 16, the phase's scales 1..16)")
        ->transform(parameterCheck("axis.maxScale"));
    command->add_option("--csv", arguments.csv, "Also write the table as CSV (function,emotion,scale,dof,relative_error,thesis)")
        ->type_name("FILE");
}

} // namespace bunraku::app::cli
