#include "widgets/graph_layout.h"

#include <algorithm>

namespace bunraku::widgets {
namespace {

bool hasPart(const std::vector<analysis::Channel>& channels, const std::string& part)
{
    return std::any_of(channels.begin(), channels.end(), [&](const auto& c) { return c.part == part; });
}

bool hasDof(const std::vector<analysis::Channel>& channels, const std::string& dof)
{
    return std::any_of(channels.begin(), channels.end(), [&](const auto& c) { return c.dof == dof; });
}

} // namespace

std::vector<GraphCell> layoutGraphs(const std::vector<analysis::Channel>& channels, const GraphLayoutOptions& options, int maxGraphs,
                                    int* wanted)
{
    if (wanted) *wanted = 0;
    if (channels.empty()) return {};
    const std::string part = hasPart(channels, options.selectedPart) ? options.selectedPart : channels.front().part;
    const std::string dof = hasDof(channels, options.selectedDof) ? options.selectedDof : channels.front().dof;

    std::vector<const analysis::Channel*> shown;
    for (const auto& channel : channels) {
        switch (options.layout) {
        case GraphLayout::AllChannels: shown.push_back(&channel); break;
        case GraphLayout::OnePart:
            if (channel.part == part) shown.push_back(&channel);
            break;
        case GraphLayout::OneDof:
            if (channel.dof == dof) shown.push_back(&channel);
            break;
        case GraphLayout::Single:
            if (channel.part == part && channel.dof == dof && shown.empty()) shown.push_back(&channel);
            break;
        }
    }
    if (shown.empty()) shown.push_back(&channels.front()); // Single with a part lacking that DOF

    const bool sideBySide = options.hasTakeB && options.twoTakeMode == TwoTakeMode::SideBySide;
    if (wanted) *wanted = int(shown.size()) * (sideBySide ? 2 : 1);
    // The limit: the first channels for A and, side by side, the same ones for B.
    if (maxGraphs > 0) {
        const std::size_t perTake = std::size_t(std::max(1, maxGraphs / (sideBySide ? 2 : 1)));
        if (shown.size() > perTake) shown.resize(perTake);
    }
    const int columnsPerTake = options.layout == GraphLayout::AllChannels && shown.size() > 1 ? 2 : 1;
    const int rows = (int(shown.size()) + columnsPerTake - 1) / columnsPerTake;
    const GraphTakes firstTakes = options.hasTakeB && !sideBySide ? GraphTakes::AAndB : GraphTakes::OnlyA;

    std::vector<GraphCell> cells;
    const int copies = sideBySide ? 2 : 1;
    for (int copy = 0; copy < copies; ++copy) {
        for (std::size_t i = 0; i < shown.size(); ++i) {
            GraphCell cell;
            cell.part = shown[i]->part;
            cell.dof = shown[i]->dof;
            cell.takes = copy == 0 ? firstTakes : GraphTakes::OnlyB;
            cell.row = int(i) % rows;
            cell.column = copy * columnsPerTake + int(i) / rows;
            cells.push_back(cell);
        }
    }
    return cells;
}

} // namespace bunraku::widgets
