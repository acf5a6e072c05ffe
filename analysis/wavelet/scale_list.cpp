#include "analysis/wavelet/scale_list.h"

#include <optional>
#include <sstream>
#include <stdexcept>

namespace bunraku::analysis {
namespace {

/// The whole text as a number ("3x" is not one).
std::optional<double> number(const std::string& text)
{
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

Error notANumber(const std::string& field)
{
    return makeError(ErrorCode::Parse, "'" + field + "' is not a number (expected FIRST:LAST, FIRST:STEP:LAST or a comma list)");
}

} // namespace

Result<std::vector<double>> parseScaleList(const std::string& text)
{
    const bool range = text.find(':') != std::string::npos;
    std::vector<double> fields;
    std::istringstream parts(text);
    for (std::string token; std::getline(parts, token, range ? ':' : ',');) {
        const auto value = number(token);
        if (!value) return notANumber(token);
        fields.push_back(*value);
    }
    if (!range) {
        if (fields.empty()) return makeError(ErrorCode::Parse, "no scales in '" + text + "'");
        return fields;
    }
    if (fields.size() < 2 || fields.size() > 3)
        return makeError(ErrorCode::Parse, "expected FIRST:LAST or FIRST:STEP:LAST, got '" + text + "'");
    const double first = fields[0];
    const double step = fields.size() == 3 ? fields[1] : 1.0;
    const double last = fields.back();
    if (!(step > 0) || last < first) return makeError(ErrorCode::Parse, "'" + text + "' is an empty range");
    std::vector<double> values;
    for (double s = first; s <= last + 1e-9; s += step) values.push_back(s);
    return values;
}

} // namespace bunraku::analysis
