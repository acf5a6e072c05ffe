#pragma once
/// The table and HTML index over folders written by `bunraku analyse` (a library analysed corpus
/// by corpus, workflows/Snakefile; `bunraku summary`): one row per folder, read from its
/// summary.json (docs/FORMATS.md, analyse), each linking its report.html.

#include "analysis/core/result.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace bunraku::analysis::report {

/// One analysed corpus: the figures of its summary.json.
struct AnalysedCorpus {
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

/// FOLDER/summary.json read; an Io error names the file, a Parse error the file and the field
/// expected. Numbers as text with the shortest round-trip digits, as the analysis's own files.
Result<AnalysedCorpus> readAnalysedCorpus(const std::string& folder);

/// The CSV table, one row per corpus, each report.html linked relative to `tableFolder`.
std::string analysedCorporaCsv(const std::vector<AnalysedCorpus>& rows, const std::filesystem::path& tableFolder);
/// The HTML index of the same rows, each report.html linked relative to `indexFolder`.
std::string analysedCorporaHtml(const std::vector<AnalysedCorpus>& rows, const std::filesystem::path& indexFolder);

} // namespace bunraku::analysis::report
