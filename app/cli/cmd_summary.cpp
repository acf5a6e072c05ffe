// Subcommand: summary - one table and one HTML index over folders written by `bunraku analyse`
// (a library analysed corpus by corpus, workflows/Snakefile).
#include "app/cli/commands.h"
#include "app/cli/output_guard.h"

#include "analysis/io/atomic_file.h"
#include "analysis/report/analysed_corpora.h"

#include <filesystem>
#include <iostream>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;

struct SummaryArguments {
    std::vector<std::string> analyses;
    std::string table;
    std::string index;
    bool json = false;
};

void runSummary(const SummaryArguments& arguments)
{
    if (arguments.table.empty() && arguments.index.empty()) throw CliError("nothing to write: give --table FILE and/or --index FILE", kExitUsage);
    std::vector<std::string> inputs;
    for (const auto& folder : arguments.analyses) inputs.push_back((fs::path(folder) / "summary.json").string());
    refuseOutputOverInputs(arguments.table, OutputKind::File, inputs, "--table");
    refuseOutputOverInputs(arguments.index, OutputKind::File, inputs, "--index");
    std::vector<rp::AnalysedCorpus> rows;
    for (const auto& folder : arguments.analyses) rows.push_back(unwrap(rp::readAnalysedCorpus(folder)));
    auto folderOf = [](const std::string& file) { return fs::absolute(file).parent_path(); };
    if (!arguments.table.empty())
        unwrap(analysis::io::writeFileAtomically(arguments.table, rp::analysedCorporaCsv(rows, folderOf(arguments.table))));
    if (!arguments.index.empty())
        unwrap(analysis::io::writeFileAtomically(arguments.index, rp::analysedCorporaHtml(rows, folderOf(arguments.index))));
    std::size_t takes = 0;
    for (const auto& row : rows) takes += row.takes;
    const nlohmann::json summary{{"corpora", rows.size()}, {"takes", takes}, {"table", arguments.table}, {"index", arguments.index}};
    report(arguments.json, summary, [&] {
        std::cout << "summarised " << rows.size() << " analysed corpora (" << takes << " takes)";
        if (!arguments.table.empty()) std::cout << " -> " << arguments.table;
        if (!arguments.index.empty()) std::cout << " -> " << arguments.index;
        std::cout << "\n";
    });
}

} // namespace

void addSummaryCommands(CommandSet& commands)
{
    auto [command, arguments] = addCommand(commands.root, "summary", runSummary);
    command->add_option("ANALYSES", arguments.analyses, "Folders written by 'bunraku analyse -o', in the order of the rows")->required();
    command->add_option("--table", arguments.table, "CSV table to write (one row per folder)")->type_name("FILE");
    command->add_option("--index", arguments.index, "HTML index to write, linking each report.html relative to it")->type_name("FILE");
}

} // namespace bunraku::app::cli
