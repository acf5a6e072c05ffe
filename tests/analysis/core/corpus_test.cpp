#include "analysis/core/corpus.h"
#include "analysis/core/puppet_layout.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

namespace {
Take makeTake(std::string function, std::string emotion, int index)
{
    Take t;
    t.channels = puppetChannels();
    t.values = Eigen::MatrixXd::Constant(4, 24, index);
    t.labels = {std::move(function), std::move(emotion), index, ""};
    return t;
}
} // namespace

TEST_CASE("a corpus lists its labels and sorts a cell by take index", "[corpus]")
{
    Corpus corpus;
    corpus.takes = {makeTake("greeting", "friendly", 2), makeTake("greeting", "none", 1),
                    makeTake("greeting", "friendly", 1), makeTake("tea", "none", 1)};
    CHECK(corpus.functions() == std::vector<std::string>{"greeting", "tea"});
    CHECK(corpus.emotions() == std::vector<std::string>{"none", "friendly"});
    const auto cell = corpus.cell("greeting", "friendly");
    REQUIRE(cell.size() == 2);
    CHECK(cell[0]->labels.takeIndex == 1);
    CHECK(cell[1]->labels.takeIndex == 2);
    CHECK(corpus.find("tea", "none", 1) != nullptr);
    CHECK(corpus.find("tea", "none", 2) == nullptr);
    CHECK(validateCorpus(corpus).ok());
    corpus.takes.push_back(makeTake("tea", "none", 1));
    CHECK_FALSE(validateCorpus(corpus).ok());
}
