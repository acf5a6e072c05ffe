#pragma once
/// Checks that every number a report shows (data-source, data-row, data-column, data-value)
/// equals the value in the named data file, to the last bit (both are shortest round-trip text).

#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace bunraku::test {

struct ReportNumber {
    std::string source, row, column, value;
};

inline std::vector<ReportNumber> reportNumbers(const std::string& html)
{
    static const std::regex cell(R"re(data-source="([^"]*)" data-row="([^"]*)" data-column="([^"]*)" data-value="([^"]*)")re");
    std::vector<ReportNumber> numbers;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), cell); it != std::sregex_iterator(); ++it)
        numbers.push_back({(*it)[1], (*it)[2], (*it)[3], (*it)[4]});
    return numbers;
}

/// CSV text as rows of fields.
inline std::vector<std::vector<std::string>> csvFields(const std::string& text)
{
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::vector<std::string> fields;
        std::istringstream parts(line);
        std::string field;
        while (std::getline(parts, field, ',')) fields.push_back(field);
        rows.push_back(std::move(fields));
    }
    return rows;
}

/// The field of `csv` in column `column` on the row whose first fields join (with ',') to
/// `row`; empty when absent.
inline std::string csvValue(const std::string& csv, const std::string& row, const std::string& column)
{
    const auto rows = csvFields(csv);
    if (rows.empty()) return {};
    const auto& header = rows.front();
    std::size_t keyFields = 1;
    for (char c : row) keyFields += c == ',' ? 1 : 0;
    std::size_t at = header.size();
    for (std::size_t c = 0; c < header.size(); ++c)
        if (header[c] == column) at = c;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        std::string key;
        for (std::size_t f = 0; f < keyFields && f < rows[r].size(); ++f) key += (f ? "," : "") + rows[r][f];
        if (key == row && at < rows[r].size()) return rows[r][at];
    }
    return {};
}

} // namespace bunraku::test
