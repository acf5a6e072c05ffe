// Subcommand: experiment approximation - the per-scale approximation error of thesis 5.4.1
// (eq. 5.18, Fig. 5.16) for every emotional cell of a corpus, through the pipeline's stages.
#include "app/cli/commands.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/io/atomic_file.h"
#include "analysis/pipeline/chain.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace bunraku::app::cli {
namespace {

namespace an = bunraku::analysis;
namespace pl = bunraku::analysis::pipeline;

struct ApproximationArguments {
    std::string corpus;
    int maxScale = 16;
    std::string csv;
    bool json = false;
};

/// Figure 5.16 is printed as a plot only: no value of it is legible in the text.
constexpr const char* kThesisFigure = "Fig. 5.16 (no emotion vs friendly, per axis DOF): plotted only, no values printed";

std::string approximationCsv(const pl::AxisOutput& axes, const std::vector<std::string>& dofs)
{
    std::ostringstream out;
    out << std::setprecision(10) << "function,emotion,scale,dof,relative_error,thesis\n";
    for (const auto& cell : axes.cells)
        for (std::size_t c = 0; c < cell.approximation.scales.size(); ++c) {
            for (std::size_t q = 0; q < dofs.size(); ++q) {
                const double value = cell.approximation.relativeError(Eigen::Index(c), Eigen::Index(q));
                out << cell.function << ',' << cell.emotion << ',' << cell.approximation.scales[c] << ',' << dofs[q] << ',';
                if (std::isfinite(value)) out << value;
                out << ",\n"; // thesis: not legible (kThesisFigure)
            }
            const double mean = cell.approximation.meanRelativeError(Eigen::Index(c));
            out << cell.function << ',' << cell.emotion << ',' << cell.approximation.scales[c] << ",mean,";
            if (std::isfinite(mean)) out << mean;
            out << ",\n";
        }
    return out.str();
}

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
    std::vector<std::string> dofs;
    for (const auto& channel : an::axisCoordinateChannels()) dofs.push_back(channel.name());
    if (!arguments.csv.empty()) unwrap(an::io::writeFileAtomically(arguments.csv, approximationCsv(*axes, dofs)));
    if (arguments.json) {
        nlohmann::json cells = nlohmann::json::array();
        for (const auto& cell : axes->cells) {
            nlohmann::json perDof = nlohmann::json::object();
            for (std::size_t q = 0; q < dofs.size(); ++q) {
                nlohmann::json column = nlohmann::json::array();
                for (Eigen::Index c = 0; c < cell.approximation.relativeError.rows(); ++c) {
                    const double value = cell.approximation.relativeError(c, Eigen::Index(q));
                    column.push_back(std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr));
                }
                perDof[dofs[q]] = column;
            }
            nlohmann::json mean = nlohmann::json::array();
            for (Eigen::Index c = 0; c < cell.approximation.meanRelativeError.size(); ++c) {
                const double value = cell.approximation.meanRelativeError(c);
                mean.push_back(std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr));
            }
            nlohmann::json entry;
            entry["function"] = cell.function;
            entry["emotion"] = cell.emotion;
            entry["scales"] = cell.approximation.scales;
            entry["relative_error"] = perDof;
            entry["mean_relative_error"] = mean;
            entry["thesis"] = nullptr; // kThesisFigure
            cells.push_back(entry);
        }
        nlohmann::json summary{{"corpus", arguments.corpus},
                               {"equation", "5.18: sqrt(sum |A_e - A_f|^2) / sqrt(sum |X_f|^2), scales 1..c"},
                               {"thesis_figure", kThesisFigure},
                               {"cells", cells}};
        if (!arguments.csv.empty()) summary["csv"] = arguments.csv;
        printJson(summary);
        return;
    }
    std::cout << "thesis 5.4.1, eq. 5.18: approximation error of the phase-adjusted emotional axis against the functional "
                 "axis, scales 1..c\n"
              << kThesisFigure << "\n";
    for (const auto& cell : axes->cells) {
        std::cout << cell.function << " / " << cell.emotion << "\n     c";
        for (const auto& dof : dofs) std::cout << std::setw(13) << dof;
        std::cout << std::setw(13) << "mean" << "\n";
        for (Eigen::Index c = 0; c < cell.approximation.relativeError.rows(); ++c) {
            std::cout << std::setw(6) << cell.approximation.scales[std::size_t(c)] << std::fixed << std::setprecision(4);
            for (Eigen::Index q = 0; q < cell.approximation.relativeError.cols(); ++q)
                std::cout << std::setw(13) << cell.approximation.relativeError(c, q);
            std::cout << std::setw(13) << cell.approximation.meanRelativeError(c) << "\n";
        }
    }
    if (!arguments.csv.empty()) std::cout << "wrote " << arguments.csv << "\n";
}

} // namespace

void addApproximationCommands(CommandSet& commands)
{
    auto arguments = std::make_shared<ApproximationArguments>();
    CLI::App* command = addCommand(commands.experiment, "approximation",
        "Thesis 5.4.1 (eq. 5.18, Fig. 5.16): per largest scale c, the error between the wavelet "
        "approximations of the functional axis and of the phase-adjusted emotional axis, per axis DOF",
        arguments, runApproximation);
    command->add_option("CORPUS", arguments->corpus, "Corpus folder (corpus.json), or 'demo' for the embedded synthetic corpus")
        ->required();
    command->add_option("--max-scale", arguments->maxScale, "Largest scale c (default 16, the phase's scales 1..16)")
        ->check(CLI::Range(1, 64));
    command->add_option("--csv", arguments->csv, "Also write the table as CSV (function,emotion,scale,dof,relative_error,thesis)")
        ->type_name("FILE");
}

} // namespace bunraku::app::cli
