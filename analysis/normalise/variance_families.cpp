#include "analysis/normalise/variance_families.h"

#include <algorithm>

namespace bunraku::analysis {

std::string varianceFamily(const std::string& unit)
{
    if (unit == "cm" || unit == "mm" || unit == "m") return "position";
    if (unit == "deg" || unit == "rad") return "rotation";
    return unit.empty() ? "unitless" : unit;
}

std::vector<VarianceRow> varianceRows(const VarianceTable& table, const std::vector<Channel>& channels)
{
    std::vector<VarianceRow> rows;
    const Eigen::Index count = std::min<Eigen::Index>(table.before.cols(), Eigen::Index(channels.size()));
    // Families and parts in order of first appearance among the channels.
    std::vector<std::string> families;
    std::vector<std::string> parts;
    for (Eigen::Index c = 0; c < count; ++c) {
        const std::string family = varianceFamily(channels[std::size_t(c)].unit);
        if (std::find(families.begin(), families.end(), family) == families.end()) families.push_back(family);
        if (std::find(parts.begin(), parts.end(), channels[std::size_t(c)].part) == parts.end())
            parts.push_back(channels[std::size_t(c)].part);
    }
    for (Eigen::Index k = 0; k < table.before.rows(); ++k) {
        for (const std::string& family : families) {
            VarianceRow total{table.takeNames.at(std::size_t(k)), family, {}, {}, 0.0, 0.0};
            std::vector<VarianceRow> perPart;
            for (const std::string& part : parts) {
                VarianceRow row{total.take, family, {}, part, 0.0, 0.0};
                bool any = false;
                for (Eigen::Index c = 0; c < count; ++c) {
                    const Channel& channel = channels[std::size_t(c)];
                    if (channel.part != part || varianceFamily(channel.unit) != family) continue;
                    row.unit = channel.unit.empty() ? std::string() : channel.unit + "\u00b2";
                    row.before += table.before(k, c);
                    row.after += table.after(k, c);
                    any = true;
                }
                if (!any) continue;
                total.unit = row.unit;
                total.before += row.before;
                total.after += row.after;
                perPart.push_back(row);
            }
            rows.push_back(total);
            rows.insert(rows.end(), perPart.begin(), perPart.end());
        }
    }
    return rows;
}

} // namespace bunraku::analysis
