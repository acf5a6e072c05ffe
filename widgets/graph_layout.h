#pragma once
/// Which graphs the graph grid shows and where: the thesis's layouts (digest section 6) of one
/// take - all channels in two columns (24 for the puppet), one part's 6 DOF, one DOF over the
/// parts, a single graph - and of two takes, overlaid in one set of graphs or side by side
/// (48 / 12 / 8 / 2 for the puppet). A pure function of the channel list, testable without Qt.

#include "analysis/core/take.h"

#include <string>
#include <vector>

namespace bunraku::widgets {

enum class GraphLayout {
    AllChannels, ///< every channel, two columns (the 24 graphs of the puppet)
    OnePart,     ///< the 6 DOF of the selected part, one column
    OneDof,      ///< the selected DOF of every part, one column
    Single,      ///< the selected part's selected DOF
};

enum class TwoTakeMode {
    Overlay,    ///< A and B drawn in the same graph in contrasting colours
    SideBySide, ///< B's graphs in columns to the right of A's
};

/// Which take a graph draws.
enum class GraphTakes {
    OnlyA,
    OnlyB,
    AAndB, ///< overlay
};

/// One graph of the grid: the channel it shows (by part and DOF name, so B is matched to A by
/// name) and its cell.
struct GraphCell {
    std::string part;
    std::string dof;
    GraphTakes takes = GraphTakes::OnlyA;
    int row = 0;
    int column = 0;
};

struct GraphLayoutOptions {
    GraphLayout layout = GraphLayout::AllChannels;
    TwoTakeMode twoTakeMode = TwoTakeMode::Overlay;
    bool hasTakeB = false;
    std::string selectedPart; ///< for OnePart and Single; the first part when empty or unknown
    std::string selectedDof;  ///< for OneDof and Single; the first DOF when empty or unknown
};

/// The graphs for the channels `channels` (take A's, in order): row-major cells, A's columns
/// first. With N channels AllChannels has ceil(N/2) rows in 2 columns (4 with side-by-side B).
/// `maxGraphs` > 0: at most that many graphs, the first channels of the layout for each take
/// shown (half each side by side), laid out as a layout of those channels; `wanted` (optional)
/// is told how many graphs the layout asks for without the limit.
std::vector<GraphCell> layoutGraphs(const std::vector<analysis::Channel>& channels, const GraphLayoutOptions& options,
                                    int maxGraphs = 0, int* wanted = nullptr);

} // namespace bunraku::widgets
