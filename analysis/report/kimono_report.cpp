#include "analysis/report/kimono_report.h"

#include "analysis/report/svg_plot.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <utility>

namespace bunraku::analysis::report {

Result<std::vector<KimonoTakeMeasures>> measureKimonos(const Corpus& corpus, const ClothParameters& cloth)
{
    std::vector<KimonoTakeMeasures> rows;
    for (const Take& take : corpus.takes) {
        const auto simulation = simulateKimono(take, cloth);
        if (!simulation) return makeError(simulation.error().code, take.displayName() + ": " + simulation.error().message);
        const auto measures = measureKimono(take, *simulation);
        if (!measures) return makeError(measures.error().code, take.displayName() + ": " + measures.error().message);
        rows.push_back({take.displayName(), take.labels.function, take.labels.emotion, *measures});
    }
    return rows;
}

std::vector<KimonoCellMeans> kimonoCellMeans(const std::vector<KimonoTakeMeasures>& takes)
{
    std::vector<KimonoCellMeans> cells;
    for (const KimonoTakeMeasures& row : takes) {
        auto cell = std::find_if(cells.begin(), cells.end(),
                                 [&](const KimonoCellMeans& c) { return c.function == row.function && c.emotion == row.emotion; });
        if (cell == cells.end()) cell = cells.insert(cells.end(), KimonoCellMeans{row.function, row.emotion});
        ++cell->takes;
        cell->swingRight += row.measures.sleeveSwingCm[0];
        cell->swingLeft += row.measures.sleeveSwingCm[1];
        cell->lag += row.measures.sleeveLagSeconds;
        cell->hem += row.measures.hemSwingCm;
        cell->hand += row.measures.handSwingCm;
    }
    return cells;
}

nlohmann::json kimonoMeasuresJson(const std::vector<KimonoTakeMeasures>& takes, const std::vector<KimonoCellMeans>& cells)
{
    nlohmann::json takeList = nlohmann::json::array(), cellList = nlohmann::json::array();
    for (const KimonoTakeMeasures& row : takes)
        takeList.push_back({{"take", row.take}, {"function", row.function}, {"emotion", row.emotion},
                            {"sleeve_swing_right_cm", row.measures.sleeveSwingCm[0]}, {"sleeve_swing_left_cm", row.measures.sleeveSwingCm[1]},
                            {"sleeve_lag_s", row.measures.sleeveLagSeconds}, {"hem_swing_cm", row.measures.hemSwingCm},
                            {"hand_swing_cm", row.measures.handSwingCm}});
    for (const KimonoCellMeans& m : cells)
        cellList.push_back({{"function", m.function}, {"emotion", m.emotion}, {"takes", m.takes},
                            {"sleeve_swing_right_cm", m.mean(m.swingRight)}, {"sleeve_swing_left_cm", m.mean(m.swingLeft)},
                            {"sleeve_lag_s", m.mean(m.lag)}, {"hem_swing_cm", m.mean(m.hem)}, {"hand_swing_cm", m.mean(m.hand)},
                            {"sleeve_per_hand", m.sleevePerHand()}});
    return {{"takes", takeList}, {"cells", cellList}};
}

std::string kimonoFigureSvg(const std::vector<KimonoTakeMeasures>& takes)
{
    std::vector<std::pair<std::string, std::string>> cells;
    for (const KimonoTakeMeasures& row : takes)
        if (std::find(cells.begin(), cells.end(), std::make_pair(row.function, row.emotion)) == cells.end())
            cells.emplace_back(row.function, row.emotion);
    SvgPlot swing, lag;
    swing.title = "sleeve's own swing against the hand's (one dot per take)";
    swing.xLabel = "hand swing (cm RMS about its 0.5 s mean)";
    swing.yLabel = "right sleeve's own swing (cm)";
    lag.title = "the sleeve's lag behind the hand";
    lag.xLabel = "hand swing (cm)";
    lag.yLabel = "lag of the sleeve tip's velocity (s)";
    double largest = 0.0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        std::vector<double> hand, sleeve, delay;
        for (const KimonoTakeMeasures& row : takes)
            if (row.function == cells[c].first && row.emotion == cells[c].second) {
                hand.push_back(row.measures.handSwingCm);
                sleeve.push_back(row.measures.sleeveSwingCm[0]);
                delay.push_back(row.measures.sleeveLagSeconds);
                largest = std::max({largest, row.measures.handSwingCm, row.measures.sleeveSwingCm[0]});
            }
        SvgSeries series;
        series.label = cells.size() > 3 ? cells[c].first + " " + cells[c].second : cells[c].second;
        series.colour = paletteColour(c);
        series.markers = true;
        series.x = Eigen::Map<const Eigen::VectorXd>(hand.data(), Eigen::Index(hand.size()));
        series.y = Eigen::Map<const Eigen::VectorXd>(sleeve.data(), Eigen::Index(sleeve.size()));
        swing.series.push_back(series);
        series.y = Eigen::Map<const Eigen::VectorXd>(delay.data(), Eigen::Index(delay.size()));
        lag.series.push_back(series);
    }
    SvgSeries equal;
    equal.x = Eigen::Vector2d(0.0, largest);
    equal.y = equal.x;
    equal.colour = "#888888";
    equal.dashed = true;
    equal.width = 1.0;
    swing.series.push_back(equal);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << swing.width + lag.width << "\" height=\"" << swing.height << "\">"
        << "<g>" << renderSvg(swing) << "</g><g transform=\"translate(" << swing.width << ",0)\">" << renderSvg(lag) << "</g></svg>\n";
    return svg.str();
}

std::string kimonoCellMeansText(const std::vector<KimonoCellMeans>& cells)
{
    std::ostringstream out;
    out << "the kimono's own motion (beyond carrying by the parts), mean per cell:\n"
        << std::left << std::setw(18) << "function" << std::setw(12) << "emotion" << std::right << std::setw(6) << "takes"
        << std::setw(16) << "sleeve R (cm)" << std::setw(16) << "sleeve L (cm)" << std::setw(14) << "lag (s)" << std::setw(14)
        << "hem (cm)" << std::setw(14) << "hand (cm)" << std::setw(16) << "sleeve R/hand" << "\n";
    for (const KimonoCellMeans& m : cells)
        out << std::left << std::setw(18) << m.function << std::setw(12) << m.emotion << std::right << std::setw(6) << m.takes
            << std::fixed << std::setprecision(2) << std::setw(16) << m.mean(m.swingRight) << std::setw(16) << m.mean(m.swingLeft)
            << std::setprecision(3) << std::setw(14) << m.mean(m.lag) << std::setprecision(2) << std::setw(14) << m.mean(m.hem)
            << std::setw(14) << m.mean(m.hand) << std::setw(16) << m.sleevePerHand() << "\n";
    return out.str();
}

} // namespace bunraku::analysis::report
