#include "analysis/report/analysed_corpora.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/io/text_format.h"
#include "analysis/report/svg_plot.h"

#include <nlohmann/json.hpp>

namespace bunraku::analysis::report {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// Shortest round-trip digits, as the analysis's own files (a value read back is the double).
std::string number(const json& value) { return io::shortestNumber(value.get<double>()); }

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

/// The corpus's report.html as a link from a file in `from`.
std::string reportLink(const AnalysedCorpus& row, const fs::path& from)
{
    return (fs::absolute(row.folder) / "report.html").lexically_proximate(fs::absolute(from)).generic_string();
}

} // namespace

Result<AnalysedCorpus> readAnalysedCorpus(const std::string& folder)
{
    const fs::path file = fs::path(folder) / "summary.json";
    auto text = io::readTextFile(file, io::kDocumentLimitBytes);
    if (!text) return text.error();
    auto parsed = io::parseJsonText(*text, file.string());
    if (!parsed) return parsed.error();
    AnalysedCorpus row;
    row.folder = folder;
    try {
        const json& summary = *parsed;
        row.corpus = summary.at("corpus").get<std::string>();
        row.takes = summary.at("takes").get<std::size_t>();
        row.cells = summary.at("cells").size();
        row.frames = summary.at("frames").get<std::size_t>();
        row.channels = summary.at("channels").get<std::size_t>();
        const json& decomposition = summary.at("decomposition");
        row.method = decomposition.at("method").get<std::string>();
        if (decomposition.contains("km2o") && !decomposition.at("km2o").at("estimable").get<bool>())
            row.method = "least-squares (KM2O not estimable)";
        if (decomposition.contains("M")) {
            row.M = std::to_string(decomposition.at("M").get<int>());
            row.meanP = number(decomposition.at("mean_P_percent"));
        }
        const json& axes = summary.at("axes");
        if (!axes.empty()) {
            double sum = 0.0;
            for (const auto& axis : axes) sum += axis.at("design_relative_error").get<double>();
            row.designError = number(json(sum / double(axes.size())));
        }
    } catch (const json::exception& error) {
        return makeError(ErrorCode::Parse,
                         file.string() + ": expected the summary.json of `bunraku analyse`: " + io::jsonErrorReason(error));
    }
    if (row.corpus.empty()) row.corpus = fs::path(folder).lexically_normal().filename().string();
    return row;
}

std::string analysedCorporaCsv(const std::vector<AnalysedCorpus>& rows, const fs::path& tableFolder)
{
    std::string text = "corpus,takes,cells,frames,channels,method,M,mean_P_percent,mean_design_relative_error,report\n";
    for (const auto& row : rows)
        text += csvField(row.corpus) + "," + std::to_string(row.takes) + "," + std::to_string(row.cells) + "," + std::to_string(row.frames) +
                "," + std::to_string(row.channels) + "," + csvField(row.method) + "," + row.M + "," + row.meanP + "," + row.designError + "," +
                csvField(reportLink(row, tableFolder)) + "\n";
    return text;
}

std::string analysedCorporaHtml(const std::vector<AnalysedCorpus>& rows, const fs::path& indexFolder)
{
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Bunraku motion analysis: " +
                       std::to_string(rows.size()) + " corpora</title>\n<style>body{font-family:sans-serif;margin:2em}"
                       "table{border-collapse:collapse}td,th{border:1px solid #999;padding:0.2em 0.6em;text-align:right}"
                       "td:first-child{text-align:left}</style>\n</head>\n<body>\n<h1>Bunraku motion analysis: " +
                       std::to_string(rows.size()) + " corpora</h1>\n<table>\n<tr><th>corpus</th><th>takes</th><th>cells</th>"
                       "<th>frames</th><th>channels</th><th>method</th><th>M</th><th>mean P (%)</th><th>mean design relative error</th></tr>\n";
    for (const auto& row : rows)
        html += "<tr><td><a href=\"" + escapeXml(reportLink(row, indexFolder)) + "\">" + escapeXml(row.corpus) + "</a></td><td>" +
                std::to_string(row.takes) + "</td><td>" + std::to_string(row.cells) + "</td><td>" + std::to_string(row.frames) +
                "</td><td>" + std::to_string(row.channels) + "</td><td>" + escapeXml(row.method) + "</td><td>" + row.M + "</td><td>" +
                row.meanP + "</td><td>" + row.designError + "</td></tr>\n";
    return html + "</table>\n</body>\n</html>\n";
}

} // namespace bunraku::analysis::report
