// Subcommand: experiment approximation - the per-scale approximation error of thesis 5.4.1
// (eq. 5.18, Fig. 5.16) for every emotional cell of a corpus, through the pipeline's stages.
#include "app/cli/commands.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/io/atomic_file.h"
#include "analysis/pipeline/chain.h"
#include "analysis/report/approximation_table.h"

#include <iomanip>
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
    const pl::CorpusInput corpus = unwrap(pl::importCorpus(arguments.corpus));
    pl::ChainParameters parameters;
    parameters.normalise.path = an::PathMethod::Greedy; // the thesis's scan (3.5.3), not the workbench's default
    parameters.axis.maxScale = arguments.maxScale;
    unwrap(pl::validate(parameters.axis));
    // The workbench's own stages: preprocess (2.2), normalise with average takes (3.7), axes,
    // phase and gains (5.2-5.4) - the approximation error is computed by the axis stage.
    const auto preprocessed = unwrap(pl::preprocessStage(corpus, parameters.preprocess, nullptr));
    const pl::StageKey preprocessKey = pl::chainKeys(corpus.key, parameters).preprocess;
    const auto normalised = unwrap(pl::normaliseStage(preprocessKey, *preprocessed, parameters.normalise, nullptr));
    const auto axes = unwrap(pl::axisStage(pl::chainKeys(corpus.key, parameters).normalise, *normalised,
                                           corpus.corpus->neutralEmotion, parameters.axis, nullptr));
    if (!axes->unavailable.empty()) throw CliError(arguments.corpus + ": " + axes->unavailable);
    if (!arguments.csv.empty()) unwrap(an::io::writeFileAtomically(arguments.csv, rp::approximationCsv(*axes)));
    nlohmann::json summary{{"corpus", arguments.corpus},
                           {"equation", "5.18: sqrt(sum |A_e - A_f|^2) / sqrt(sum |X_f|^2), scales 1..c"},
                           {"thesis_figure", rp::kApproximationThesisFigure},
                           {"cells", rp::approximationJson(*axes)}};
    if (!arguments.csv.empty()) summary["csv"] = arguments.csv;
    report(arguments.json, summary, [&] {
        std::cout << "thesis 5.4.1, eq. 5.18: approximation error of the phase-adjusted emotional axis against the functional "
                     "axis, scales 1..c\n"
                  << rp::kApproximationThesisFigure << "\n";
        for (const auto& cell : axes->cells) {
            std::cout << cell.function << " / " << cell.emotion << "\n     c";
            for (const auto& channel : an::axisCoordinateChannels()) std::cout << std::setw(13) << channel.name();
            std::cout << std::setw(13) << "mean" << "\n";
            for (Eigen::Index c = 0; c < cell.approximation.relativeError.rows(); ++c) {
                std::cout << std::setw(6) << cell.approximation.scales[std::size_t(c)] << std::fixed << std::setprecision(4);
                for (Eigen::Index q = 0; q < cell.approximation.relativeError.cols(); ++q)
                    std::cout << std::setw(13) << cell.approximation.relativeError(c, q);
                std::cout << std::setw(13) << cell.approximation.meanRelativeError(c) << "\n";
            }
        }
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
        ->check(CLI::Range(1, 64));
    command->add_option("--csv", arguments.csv, "Also write the table as CSV (function,emotion,scale,dof,relative_error,thesis)")
        ->type_name("FILE");
}

} // namespace bunraku::app::cli
