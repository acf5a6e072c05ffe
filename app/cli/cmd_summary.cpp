// Subcommand: summary - one table and one HTML index over folders written by `bunraku analyse`
// (a library analysed corpus by corpus, workflows/Snakefile).
#include "app/cli/commands.h"
#include "app/cli/output_guard.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/io/text_format.h"
#include "analysis/report/svg_plot.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct SummaryArguments {
    std::vector<std::string> analyses;
    std::string table;
    std::string index;
    bool json = false;
};

/// One analysed corpus: the figures of its summary.json (docs/FORMATS.md, analyse).
struct Row {
    std::string folder;
    std::string corpus;
    std::size_t takes = 0;
    std::size_t cells = 0;
    std::size_t frames = 0;
    std::size_t channels = 0;
    std::string method;
    std::string M;             ///< empty when the decomposition is not KM2O
    std::string meanP;         ///< mean P (%) of the chosen M, same
    std::string designError;   ///< mean design relative error over the emotional cells, empty without any
};

/// Shortest round-trip digits, as the analysis's own files (a value read back is the double).
std::string number(const json& value) { return analysis::io::shortestNumber(value.get<double>()); }

/// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

Row readRow(const std::string& folder)
{
    const fs::path file = fs::path(folder) / "summary.json";
    const std::string text = unwrap(analysis::io::readTextFile(file, analysis::io::kDocumentLimitBytes));
    Row row;
    row.folder = folder;
    try {
        const json summary = unwrap(analysis::io::parseJsonText(text, file.string()));
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
        throw CliError(file.string() + ": expected the summary.json of `bunraku analyse`: " + analysis::io::jsonErrorReason(error));
    }
    if (row.corpus.empty()) row.corpus = fs::path(folder).lexically_normal().filename().string();
    return row;
}

std::string tableText(const std::vector<Row>& rows, const fs::path& tableFolder)
{
    std::string text = "corpus,takes,cells,frames,channels,method,M,mean_P_percent,mean_design_relative_error,report\n";
    for (const auto& row : rows) {
        const std::string report = (fs::absolute(row.folder) / "report.html").lexically_proximate(fs::absolute(tableFolder)).generic_string();
        text += csvField(row.corpus) + "," + std::to_string(row.takes) + "," + std::to_string(row.cells) + "," + std::to_string(row.frames) +
                "," + std::to_string(row.channels) + "," + csvField(row.method) + "," + row.M + "," + row.meanP + "," + row.designError + "," +
                csvField(report) + "\n";
    }
    return text;
}

std::string indexHtml(const std::vector<Row>& rows, const fs::path& indexFolder)
{
    using analysis::report::escapeXml;
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Bunraku motion analysis: " +
                       std::to_string(rows.size()) + " corpora</title>\n<style>body{font-family:sans-serif;margin:2em}"
                       "table{border-collapse:collapse}td,th{border:1px solid #999;padding:0.2em 0.6em;text-align:right}"
                       "td:first-child{text-align:left}</style>\n</head>\n<body>\n<h1>Bunraku motion analysis: " +
                       std::to_string(rows.size()) + " corpora</h1>\n<table>\n<tr><th>corpus</th><th>takes</th><th>cells</th>"
                       "<th>frames</th><th>channels</th><th>method</th><th>M</th><th>mean P (%)</th><th>mean design relative error</th></tr>\n";
    for (const auto& row : rows) {
        const std::string report = (fs::absolute(row.folder) / "report.html").lexically_proximate(fs::absolute(indexFolder)).generic_string();
        html += "<tr><td><a href=\"" + escapeXml(report) + "\">" + escapeXml(row.corpus) + "</a></td><td>" + std::to_string(row.takes) +
                "</td><td>" + std::to_string(row.cells) + "</td><td>" + std::to_string(row.frames) + "</td><td>" + std::to_string(row.channels) +
                "</td><td>" + escapeXml(row.method) + "</td><td>" + row.M + "</td><td>" + row.meanP + "</td><td>" + row.designError +
                "</td></tr>\n";
    }
    return html + "</table>\n</body>\n</html>\n";
}

void runSummary(const SummaryArguments& arguments)
{
    if (arguments.table.empty() && arguments.index.empty()) throw CliError("nothing to write: give --table FILE and/or --index FILE", kExitUsage);
    std::vector<std::string> inputs;
    for (const auto& folder : arguments.analyses) inputs.push_back((fs::path(folder) / "summary.json").string());
    refuseOutputOverInputs(arguments.table, OutputKind::File, inputs, "--table");
    refuseOutputOverInputs(arguments.index, OutputKind::File, inputs, "--index");
    std::vector<Row> rows;
    for (const auto& folder : arguments.analyses) rows.push_back(readRow(folder));
    auto folderOf = [](const std::string& file) { return fs::absolute(file).parent_path(); };
    if (!arguments.table.empty()) unwrap(analysis::io::writeFileAtomically(arguments.table, tableText(rows, folderOf(arguments.table))));
    if (!arguments.index.empty()) unwrap(analysis::io::writeFileAtomically(arguments.index, indexHtml(rows, folderOf(arguments.index))));
    std::size_t takes = 0;
    for (const auto& row : rows) takes += row.takes;
    if (arguments.json) {
        printJson({{"corpora", rows.size()}, {"takes", takes}, {"table", arguments.table}, {"index", arguments.index}});
        return;
    }
    std::cout << "summarised " << rows.size() << " analysed corpora (" << takes << " takes)";
    if (!arguments.table.empty()) std::cout << " -> " << arguments.table;
    if (!arguments.index.empty()) std::cout << " -> " << arguments.index;
    std::cout << "\n";
}

} // namespace

void addSummaryCommands(CommandSet& commands)
{
    auto arguments = std::make_shared<SummaryArguments>();
    CLI::App* command = addCommand(commands.root, "summary",
        "One table (CSV) and one HTML index over folders written by 'bunraku analyse': per corpus its takes, cells, "
        "KM2O M and mean P, mean design error, and the link to its report.html (workflows/Snakefile)",
        arguments, runSummary);
    command->add_option("ANALYSES", arguments->analyses, "Folders written by 'bunraku analyse -o', in the order of the rows")->required();
    command->add_option("--table", arguments->table, "CSV table to write (one row per folder)")->type_name("FILE");
    command->add_option("--index", arguments->index, "HTML index to write, linking each report.html relative to it")->type_name("FILE");
}

} // namespace bunraku::app::cli
