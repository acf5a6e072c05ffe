#include "analysis/report/analysis_files.h"
#include "analysis/report/html_report.h"
#include "analysis/report/svg_plot.h"

#include "analysis/synth/demo_corpus.h"
#include "tests/analysis/report/report_numbers.h"

#include <catch2/catch.hpp>

#include <map>

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;

namespace {

struct DemoReport {
    std::string html;
    std::map<std::string, std::string> files;
};

const DemoReport& demoReport()
{
    static const DemoReport report = [] {
        auto corpus = makeCorpusInput(synth::generateDemoCorpus().corpus);
        REQUIRE(corpus.ok());
        const ChainParameters parameters;
        auto chain = runChain(*corpus, parameters, nullptr);
        REQUIRE(chain.ok());
        auto files = report::analysisDataFiles(*chain, parameters);
        REQUIRE(files.ok());
        auto html = report::htmlReport(*chain, parameters, {"Demo", "demo", "test"});
        REQUIRE(html.ok());
        DemoReport out{*html, {}};
        for (const auto& file : *files) out.files[file.name] = file.content;
        return out;
    }();
    return report;
}

} // namespace

TEST_CASE("the demo corpus report has every section, a figure in each figure section and no script", "[report]")
{
    const std::string& html = demoReport().html;
    for (const auto& id : report::reportSections()) {
        INFO(id);
        CHECK(html.find("<section id=\"" + id + "\">") != std::string::npos);
    }
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("http://") == html.find("http://www.w3.org/2000/svg")); // the SVG namespace is the only URL
    CHECK(html.find("https://") == std::string::npos);
    for (const std::string id : {"normalise", "average", "spectra", "km2o", "axes", "warps"}) {
        const auto begin = html.find("<section id=\"" + id + "\">");
        const auto end = html.find("</section>", begin);
        INFO(id);
        CHECK(html.substr(begin, end - begin).find("<svg") != std::string::npos);
    }
    CHECK(html.find("class=\"thesis\"") != std::string::npos); // the thesis's values beside ours
}

TEST_CASE("every number in the report equals the data file it names, bit for bit", "[report]")
{
    const auto& report = demoReport();
    const auto numbers = bunraku::test::reportNumbers(report.html);
    REQUIRE(numbers.size() > 200);
    std::map<std::string, int> perSource;
    for (const auto& number : numbers) {
        INFO(number.source << " row " << number.row << " column " << number.column);
        const auto file = report.files.find(number.source);
        REQUIRE(file != report.files.end());
        CHECK(bunraku::test::csvValue(file->second, number.row, number.column) == number.value);
        ++perSource[number.source.substr(0, number.source.find('_'))];
    }
    for (const std::string kind : {"variance", "arma", "km2o", "gains"}) {
        INFO(kind);
        CHECK(perSource[kind] > 0);
    }
}

TEST_CASE("an SVG chart escapes its labels and drops non-finite points", "[report]")
{
    report::SvgPlot plot;
    plot.title = "a < b & \"c\"";
    Eigen::VectorXd x(3), y(3);
    x << 0, 1, 2;
    y << 1, std::nan(""), 3;
    plot.series.push_back({"s", x, y, "#000"});
    const std::string svg = report::renderSvg(plot);
    CHECK(svg.find("a &lt; b &amp; &quot;c&quot;") != std::string::npos);
    CHECK(svg.find("nan") == std::string::npos);
    std::size_t lines = 0;
    for (std::size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++lines;
    CHECK(lines == 2); // the NaN breaks the line
}
