// bunraku experiment kimono: the kimono simulated over every take of a corpus and measured
// (analysis/cloth/kimono_cloth.h; docs/KIMONO.md): per take and per emotion, the sleeves' and
// the hem's own swing and the sleeve's lag behind the hand.
#include "app/cli/commands.h"
#include "app/cli/output_guard.h"

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/io/atomic_file.h"
#include "analysis/pipeline/stages.h"
#include "analysis/report/svg_plot.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace bunraku::app::cli {
namespace {

namespace an = bunraku::analysis;
namespace pl = bunraku::analysis::pipeline;

struct KimonoArguments {
    std::string corpus;
    bool json = false;
    std::string figure; ///< an SVG file: the measures per take, coloured by emotion
    an::ClothParameters cloth;
};

struct Row {
    std::string take, function, emotion;
    an::KimonoMeasures measures;
};

/// Two scatter plots side by side, one dot per take coloured by its function and emotion: the
/// right sleeve's own swing against the hand's (the line where they are equal drawn dashed), and
/// the sleeve's lag behind the hand against the hand's swing. Written atomically.
void writeKimonoFigure(const std::string& file, const std::vector<Row>& rows)
{
    std::vector<std::pair<std::string, std::string>> cells;
    for (const Row& row : rows)
        if (std::find(cells.begin(), cells.end(), std::make_pair(row.function, row.emotion)) == cells.end())
            cells.emplace_back(row.function, row.emotion);
    an::report::SvgPlot swing, lag;
    swing.title = "sleeve's own swing against the hand's (one dot per take)";
    swing.xLabel = "hand swing (cm RMS about its 0.5 s mean)";
    swing.yLabel = "right sleeve's own swing (cm)";
    lag.title = "the sleeve's lag behind the hand";
    lag.xLabel = "hand swing (cm)";
    lag.yLabel = "lag of the sleeve tip's velocity (s)";
    double largest = 0.0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        std::vector<double> hand, sleeve, delay;
        for (const Row& row : rows)
            if (row.function == cells[c].first && row.emotion == cells[c].second) {
                hand.push_back(row.measures.handSwingCm);
                sleeve.push_back(row.measures.sleeveSwingCm[0]);
                delay.push_back(row.measures.sleeveLagSeconds);
                largest = std::max({largest, row.measures.handSwingCm, row.measures.sleeveSwingCm[0]});
            }
        const std::string label = cells.size() > 3 ? cells[c].first + " " + cells[c].second : cells[c].second;
        an::report::SvgSeries series;
        series.label = label;
        series.colour = an::report::paletteColour(c);
        series.markers = true;
        series.x = Eigen::Map<const Eigen::VectorXd>(hand.data(), Eigen::Index(hand.size()));
        series.y = Eigen::Map<const Eigen::VectorXd>(sleeve.data(), Eigen::Index(sleeve.size()));
        swing.series.push_back(series);
        series.y = Eigen::Map<const Eigen::VectorXd>(delay.data(), Eigen::Index(delay.size()));
        lag.series.push_back(series);
    }
    an::report::SvgSeries equal;
    equal.x = Eigen::Vector2d(0.0, largest);
    equal.y = equal.x;
    equal.colour = "#888888";
    equal.dashed = true;
    equal.width = 1.0;
    swing.series.push_back(equal);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << swing.width + lag.width << "\" height=\"" << swing.height << "\">"
        << "<g>" << an::report::renderSvg(swing) << "</g><g transform=\"translate(" << swing.width << ",0)\">"
        << an::report::renderSvg(lag) << "</g></svg>\n";
    if (auto status = an::io::writeFileAtomically(file, svg.str()); !status) throw CliError(status.error().message);
}

void runKimonoExperiment(const KimonoArguments& arguments)
{
    const pl::CorpusInput input = unwrap(pl::importCorpus(arguments.corpus));
    if (!arguments.figure.empty()) refuseOutputOverInputs(arguments.figure, OutputKind::File, {arguments.corpus}, "--figure");
    std::vector<Row> rows;
    for (const an::Take& take : input.corpus->takes) {
        const auto simulation = an::simulateKimono(take, arguments.cloth);
        if (!simulation) throw CliError(take.displayName() + ": " + simulation.error().message);
        const auto measures = an::measureKimono(take, *simulation);
        if (!measures) throw CliError(take.displayName() + ": " + measures.error().message);
        rows.push_back({take.displayName(), take.labels.function, take.labels.emotion, *measures});
    }
    // Means per function and emotion, in the corpus's order.
    struct Mean {
        int takes = 0;
        double swingRight = 0.0, swingLeft = 0.0, lag = 0.0, hem = 0.0, hand = 0.0;
    };
    std::vector<std::pair<std::string, std::string>> cells;
    std::map<std::pair<std::string, std::string>, Mean> means;
    for (const Row& row : rows) {
        const auto cell = std::make_pair(row.function, row.emotion);
        if (!means.count(cell)) cells.push_back(cell);
        Mean& m = means[cell];
        ++m.takes;
        m.swingRight += row.measures.sleeveSwingCm[0];
        m.swingLeft += row.measures.sleeveSwingCm[1];
        m.lag += row.measures.sleeveLagSeconds;
        m.hem += row.measures.hemSwingCm;
        m.hand += row.measures.handSwingCm;
    }
    if (!arguments.figure.empty()) writeKimonoFigure(arguments.figure, rows);
    if (arguments.json) {
        nlohmann::json takes = nlohmann::json::array(), summary = nlohmann::json::array();
        for (const Row& row : rows)
            takes.push_back({{"take", row.take}, {"function", row.function}, {"emotion", row.emotion},
                             {"sleeve_swing_right_cm", row.measures.sleeveSwingCm[0]}, {"sleeve_swing_left_cm", row.measures.sleeveSwingCm[1]},
                             {"sleeve_lag_s", row.measures.sleeveLagSeconds}, {"hem_swing_cm", row.measures.hemSwingCm},
                             {"hand_swing_cm", row.measures.handSwingCm}});
        for (const auto& cell : cells) {
            const Mean& m = means[cell];
            const double n = double(m.takes);
            summary.push_back({{"function", cell.first}, {"emotion", cell.second}, {"takes", m.takes},
                               {"sleeve_swing_right_cm", m.swingRight / n}, {"sleeve_swing_left_cm", m.swingLeft / n},
                               {"sleeve_lag_s", m.lag / n}, {"hem_swing_cm", m.hem / n}, {"hand_swing_cm", m.hand / n},
                               {"sleeve_per_hand", m.hand > 0.0 ? m.swingRight / m.hand : 0.0}});
        }
        printJson({{"corpus", arguments.corpus}, {"takes", takes}, {"cells", summary}});
        return;
    }
    std::cout << "the kimono's own motion (beyond carrying by the parts), mean per cell:\n"
              << std::left << std::setw(18) << "function" << std::setw(12) << "emotion" << std::right << std::setw(6) << "takes"
              << std::setw(16) << "sleeve R (cm)" << std::setw(16) << "sleeve L (cm)" << std::setw(14) << "lag (s)" << std::setw(14)
              << "hem (cm)" << std::setw(14) << "hand (cm)" << std::setw(16) << "sleeve R/hand" << "\n";
    for (const auto& cell : cells) {
        const Mean& m = means[cell];
        const double n = double(m.takes);
        std::cout << std::left << std::setw(18) << cell.first << std::setw(12) << cell.second << std::right << std::setw(6) << m.takes
                  << std::fixed << std::setprecision(2) << std::setw(16) << m.swingRight / n << std::setw(16) << m.swingLeft / n
                  << std::setprecision(3) << std::setw(14) << m.lag / n << std::setprecision(2) << std::setw(14) << m.hem / n
                  << std::setw(14) << m.hand / n << std::setw(16) << (m.hand > 0.0 ? m.swingRight / m.hand : 0.0) << "\n";
    }
}

} // namespace

void addClothOptions(CLI::App* command, analysis::ClothParameters& cloth)
{
    // The option and its help per parameter; the range is analysis's one table
    // (clothParameterLimits), as the workbench's Cloth Settings use it.
    const std::map<std::string, std::pair<const char*, const char*>> options{
        {"massPerArea", {"--cloth-mass", "Kimono cloth: mass per area, g/cm^2 (default 0.015, silk crepe)"}},
        {"stretchCompliance", {"--cloth-stretch", "Kimono cloth: stretch compliance of its threads, cm/dyn (default 0: inextensible)"}},
        {"bendCompliance", {"--cloth-bend", "Kimono cloth: bending compliance, cm/dyn (default 2e-4)"}},
        {"damping", {"--cloth-damping", "Kimono cloth: damping towards the body's motion, 1/s (default 1.5)"}},
        {"drag", {"--cloth-drag", "Kimono cloth: air drag, 1/s (default 0.6)"}},
        {"substepRate", {"--cloth-substeps", "Kimono cloth: simulation substeps per second (default 240)"}},
        {"collisionMargin", {"--cloth-margin", "Kimono cloth: cm it keeps off the torso and arms (default 0.3)"}},
        {"settleSeconds", {"--cloth-settle", "Kimono cloth: s the first pose is held before frame 0 so it hangs at rest (default 0.5)"}},
    };
    for (const analysis::ClothParameterLimit& limit : analysis::clothParameterLimits()) {
        const auto& [name, help] = options.at(limit.name);
        command->add_option(name, cloth.*(limit.member), help)->check(CLI::Range(limit.low, limit.high));
    }
}

void addKimonoCommands(CommandSet& commands)
{
    auto arguments = std::make_shared<KimonoArguments>();
    CLI::App* command = addCommand(commands.experiment, "kimono",
        "The kimono simulated as cloth over every take of a corpus: per take and per emotion, each sleeve's and the hem's "
        "own swing (RMS cm beyond what the parts carry) and the sleeve's lag behind the hand (docs/KIMONO.md)",
        arguments, runKimonoExperiment, "Print JSON (every take and the means per cell)");
    command->add_option("CORPUS", arguments->corpus, "Corpus folder (corpus.json), or 'demo' for the embedded synthetic corpus")->required();
    command->add_option("--figure", arguments->figure,
                        "Also write an SVG figure: per take, the sleeve's own swing against the hand's and its lag behind the hand, "
                        "coloured by emotion");
    addClothOptions(command, arguments->cloth);
}

} // namespace bunraku::app::cli
