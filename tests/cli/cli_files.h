#pragma once
/// Small file helpers of the CLI tests: read a text file or a numeric CSV written by `bunraku`
/// (header line, then comma-separated numbers); writeText comes from the io tests' support.
#include "tests/analysis/io/io_test_support.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bunraku::test {

inline std::string readTextFile(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

/// Header fields and rows of numbers of a comma-separated file.
struct NumericCsv {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
};

inline NumericCsv readNumericCsv(const std::filesystem::path& file)
{
    NumericCsv csv;
    std::istringstream in(readTextFile(file));
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::istringstream fields(line);
        std::string field;
        std::vector<double> row;
        while (std::getline(fields, field, ',')) {
            if (first) csv.header.push_back(field);
            else row.push_back(std::stod(field));
        }
        if (!first) csv.rows.push_back(std::move(row));
        first = false;
    }
    return csv;
}

/// The one-line-error contract of every subcommand: non-zero exit, exactly one line on standard
/// error starting "bunraku: error:".
inline bool isOneLineError(int exitCode, const std::string& err)
{
    std::size_t lines = 0;
    for (char c : err) lines += c == '\n' ? 1 : 0;
    return exitCode > 0 && lines == 1 && err.rfind("bunraku: error:", 0) == 0;
}

} // namespace bunraku::test
