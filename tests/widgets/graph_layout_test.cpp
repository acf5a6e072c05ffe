#include "widgets/graph_layout.h"

#include "analysis/core/puppet_layout.h"

#include <catch2/catch.hpp>

#include <set>

using namespace bunraku;
using widgets::GraphLayout;
using widgets::TwoTakeMode;

namespace {

std::size_t count(GraphLayout layout, bool takeB, TwoTakeMode mode)
{
    widgets::GraphLayoutOptions options;
    options.layout = layout;
    options.hasTakeB = takeB;
    options.twoTakeMode = mode;
    options.selectedPart = "arm";
    options.selectedDof = "pitch";
    return widgets::layoutGraphs(analysis::puppetChannels(), options).size();
}

} // namespace

TEST_CASE("the puppet layouts have the thesis's graph counts", "[widgets][graph_layout]")
{
    const auto [layout, one, two] = GENERATE(table<GraphLayout, std::size_t, std::size_t>({
        {GraphLayout::AllChannels, 24, 48},
        {GraphLayout::OnePart, 6, 12},
        {GraphLayout::OneDof, 4, 8},
        {GraphLayout::Single, 1, 2},
    }));
    REQUIRE(count(layout, false, TwoTakeMode::Overlay) == one);
    REQUIRE(count(layout, true, TwoTakeMode::Overlay) == one);
    REQUIRE(count(layout, true, TwoTakeMode::SideBySide) == two);
}

TEST_CASE("all channels fill two columns of twelve, B's columns to the right", "[widgets][graph_layout]")
{
    widgets::GraphLayoutOptions options;
    options.hasTakeB = true;
    options.twoTakeMode = TwoTakeMode::SideBySide;
    const auto cells = widgets::layoutGraphs(analysis::puppetChannels(), options);
    std::set<std::pair<int, int>> positions;
    for (const auto& cell : cells) {
        positions.insert({cell.row, cell.column});
        REQUIRE(cell.row < 12);
        REQUIRE((cell.column < 2) == (cell.takes == widgets::GraphTakes::OnlyA));
    }
    REQUIRE(positions.size() == 48); // no two graphs share a cell
    REQUIRE(cells[0].part == "head");
    REQUIRE(cells[12].part == "arm"); // second column starts with the arm
    REQUIRE(cells[12].column == 1);
}

TEST_CASE("one part shows its six DOF and one DOF shows every part", "[widgets][graph_layout]")
{
    widgets::GraphLayoutOptions options;
    options.layout = GraphLayout::OnePart;
    options.selectedPart = "hand";
    for (const auto& cell : widgets::layoutGraphs(analysis::puppetChannels(), options)) REQUIRE(cell.part == "hand");
    options.layout = GraphLayout::OneDof;
    options.selectedDof = "roll";
    std::set<std::string> parts;
    for (const auto& cell : widgets::layoutGraphs(analysis::puppetChannels(), options)) {
        REQUIRE(cell.dof == "roll");
        parts.insert(cell.part);
    }
    REQUIRE(parts.size() == 4);
    options.layout = GraphLayout::Single;
    options.selectedPart = "shoulder";
    const auto single = widgets::layoutGraphs(analysis::puppetChannels(), options);
    REQUIRE(single.size() == 1);
    REQUIRE(single[0].part == "shoulder");
    REQUIRE(single[0].dof == "roll");
}
