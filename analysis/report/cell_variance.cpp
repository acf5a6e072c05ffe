#include "analysis/report/cell_variance.h"

#include "analysis/normalise/variance_families.h"

#include <iomanip>
#include <sstream>

namespace bunraku::analysis::report {

nlohmann::json cellVarianceJson(const pipeline::CellNormalisation& cell, const std::vector<Channel>& channels)
{
    const VarianceTable& table = cell.variance;
    const std::vector<VarianceRow> rows = varianceRows(table, channels);
    nlohmann::json takes = nlohmann::json::array();
    for (std::size_t k = 0; k < cell.normalisations.size(); ++k) {
        nlohmann::json families = nlohmann::json::array();
        for (const VarianceRow& row : rows)
            if (row.take == table.takeNames[k] && row.part.empty())
                families.push_back({{"family", row.family}, {"unit", row.unit}, {"raw", row.before}, {"normalised", row.after}});
        takes.push_back({{"take", cell.takeIndices[k]},
                         {"cost", cell.normalisations[k].cost},
                         {"variance_raw", table.totalBefore[Eigen::Index(k)]},
                         {"variance_normalised", table.totalAfter[Eigen::Index(k)]},
                         {"families", families},
                         {"outlier", bool(cell.suggestion.outlier[k])}});
    }
    return takes;
}

std::string cellVarianceText(const pipeline::CellNormalisation& cell, const std::vector<Channel>& channels, const std::string& worseHint)
{
    const VarianceTable& table = cell.variance;
    const std::vector<VarianceRow> rows = varianceRows(table, channels);
    std::ostringstream out;
    out << "take  " << std::left << std::setw(27) << "variance to the reference" << std::right << std::setw(11) << "raw"
        << std::setw(13) << "normalised" << std::setw(8) << "change" << "\n";
    std::vector<int> worse;
    for (std::size_t k = 0; k < cell.normalisations.size(); ++k) {
        const int take = cell.takeIndices[k];
        for (const VarianceRow& row : rows) {
            if (row.take != table.takeNames[k] || !row.part.empty()) continue;
            std::ostringstream change;
            if (row.before > 0.0)
                change << std::showpos << std::fixed << std::setprecision(0) << 100.0 * (row.after - row.before) / row.before << " %";
            else
                change << "-";
            out << std::setw(4) << take << "  " << std::left << std::setw(27) << (row.family + " " + row.unit) << std::right << std::fixed
                << std::setprecision(1) << std::setw(11) << row.before << std::setw(13) << row.after << std::setw(8) << change.str()
                << (row.worse() ? "  worse" : "") << (cell.suggestion.outlier[k] ? "  (outlier)" : "") << "\n";
            if (row.worse() && (worse.empty() || worse.back() != take)) worse.push_back(take);
        }
    }
    if (!worse.empty()) {
        out << "take(s)";
        for (int take : worse) out << " " << take;
        out << ": normalised further from the reference than raw in some family" << worseHint << "\n";
    }
    return out.str();
}

} // namespace bunraku::analysis::report
