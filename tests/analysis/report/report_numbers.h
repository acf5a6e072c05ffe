#pragma once
/// Checks that every number a report shows (data-source, data-row, data-column, data-value)
/// equals the value in the named data file, to the last bit (both are shortest round-trip text).

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace bunraku::test {

struct ReportNumber {
    std::string source, row, column, value;
};

/// Every `data-source="..." data-row="..." data-column="..." data-value="..."` of the report,
/// in order. (Read by hand: GCC 12's std::regex does not compile warning-free at -O1 under the
/// sanitizers.)
inline std::vector<ReportNumber> reportNumbers(const std::string& html)
{
    std::vector<ReportNumber> numbers;
    // The quoted value of attribute `name` at `at` (name="value" followed by `after`), moving `at`
    // past it; false when the text there is not that.
    auto attribute = [&html](std::size_t& at, const std::string& name, std::string& value) {
        const std::string open = name + "=\"";
        if (html.compare(at, open.size(), open) != 0) return false;
        const std::size_t close = html.find('"', at + open.size());
        if (close == std::string::npos) return false;
        value = html.substr(at + open.size(), close - at - open.size());
        at = close + 1;
        return true;
    };
    for (std::size_t start = html.find("data-source=\""); start != std::string::npos;
         start = html.find("data-source=\"", start + 1)) {
        ReportNumber number;
        std::size_t at = start;
        auto space = [&] { return at < html.size() && html[at++] == ' '; };
        if (attribute(at, "data-source", number.source) && space() && attribute(at, "data-row", number.row) && space() &&
            attribute(at, "data-column", number.column) && space() && attribute(at, "data-value", number.value))
            numbers.push_back(std::move(number));
    }
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
