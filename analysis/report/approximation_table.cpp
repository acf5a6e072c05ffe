#include "analysis/report/approximation_table.h"

#include "analysis/axis/axis_channels.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace bunraku::analysis::report {
namespace {

std::vector<std::string> dofNames()
{
    std::vector<std::string> dofs;
    for (const auto& channel : axisCoordinateChannels()) dofs.push_back(channel.name());
    return dofs;
}

nlohmann::json finiteOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

} // namespace

std::string approximationCsv(const pipeline::AxisOutput& axes)
{
    const std::vector<std::string> dofs = dofNames();
    std::ostringstream out;
    out << std::setprecision(10) << "function,emotion,scale,dof,relative_error,thesis\n";
    for (const auto& cell : axes.cells)
        for (std::size_t c = 0; c < cell.approximation.scales.size(); ++c) {
            for (std::size_t q = 0; q < dofs.size(); ++q) {
                const double value = cell.approximation.relativeError(Eigen::Index(c), Eigen::Index(q));
                out << cell.function << ',' << cell.emotion << ',' << cell.approximation.scales[c] << ',' << dofs[q] << ',';
                if (std::isfinite(value)) out << value;
                out << ",\n"; // thesis: not legible (kApproximationThesisFigure)
            }
            const double mean = cell.approximation.meanRelativeError(Eigen::Index(c));
            out << cell.function << ',' << cell.emotion << ',' << cell.approximation.scales[c] << ",mean,";
            if (std::isfinite(mean)) out << mean;
            out << ",\n";
        }
    return out.str();
}

nlohmann::json approximationJson(const pipeline::AxisOutput& axes)
{
    const std::vector<std::string> dofs = dofNames();
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& cell : axes.cells) {
        nlohmann::json perDof = nlohmann::json::object();
        for (std::size_t q = 0; q < dofs.size(); ++q) {
            nlohmann::json column = nlohmann::json::array();
            for (Eigen::Index c = 0; c < cell.approximation.relativeError.rows(); ++c)
                column.push_back(finiteOrNull(cell.approximation.relativeError(c, Eigen::Index(q))));
            perDof[dofs[q]] = column;
        }
        nlohmann::json mean = nlohmann::json::array();
        for (Eigen::Index c = 0; c < cell.approximation.meanRelativeError.size(); ++c)
            mean.push_back(finiteOrNull(cell.approximation.meanRelativeError(c)));
        cells.push_back({{"function", cell.function},
                         {"emotion", cell.emotion},
                         {"scales", cell.approximation.scales},
                         {"relative_error", perDof},
                         {"mean_relative_error", mean},
                         {"thesis", nullptr}}); // kApproximationThesisFigure
    }
    return cells;
}

std::string approximationText(const pipeline::AxisOutput& axes)
{
    std::ostringstream out;
    out << "thesis 5.4.1, eq. 5.18: approximation error of the phase-adjusted emotional axis against the functional "
           "axis, scales 1..c\n"
        << kApproximationThesisFigure << "\n";
    for (const auto& cell : axes.cells) {
        out << cell.function << " / " << cell.emotion << "\n     c";
        for (const std::string& dof : dofNames()) out << std::setw(13) << dof;
        out << std::setw(13) << "mean" << "\n";
        for (Eigen::Index c = 0; c < cell.approximation.relativeError.rows(); ++c) {
            out << std::setw(6) << cell.approximation.scales[std::size_t(c)] << std::fixed << std::setprecision(4);
            for (Eigen::Index q = 0; q < cell.approximation.relativeError.cols(); ++q)
                out << std::setw(13) << cell.approximation.relativeError(c, q);
            out << std::setw(13) << cell.approximation.meanRelativeError(c) << "\n";
        }
    }
    return out.str();
}

} // namespace bunraku::analysis::report
