#pragma once
/// Internal helpers of the text importers: lines with 1-based numbers (LF or CRLF), tokens, and
/// strict number parsing (the whole token, finite values only).

#include "analysis/core/result.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis::io::detail {

struct TextLine {
    long number = 0;        ///< 1-based
    std::string_view text;  ///< without the line end; trailing '\r' removed
};

/// Every line of `text` (a final line without '\n' included); a UTF-8 byte order mark at the
/// start is skipped.
std::vector<TextLine> splitLines(std::string_view text);
/// Without leading and trailing spaces, tabs and '\r'.
std::string_view trim(std::string_view text);
/// Tokens separated by runs of spaces/tabs.
std::vector<std::string_view> splitWhitespace(std::string_view text);
/// Fields separated by one separator character (empty fields kept), each trimmed.
std::vector<std::string_view> splitFields(std::string_view text, char separator);

enum class NumberStatus { Ok, NotANumber, NonFinite };
struct ParsedNumber {
    NumberStatus status = NumberStatus::NotANumber;
    double value = 0.0;
};
/// Parses the whole token as a double (decimal or scientific); "nan"/"inf" give NonFinite.
ParsedNumber parseNumber(std::string_view token);
/// Parses the whole token as an int.
std::optional<long> parseInteger(std::string_view token);

/// True when `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool isUtf8(std::string_view text);

/// A number for messages: 6 significant digits (%g).
std::string shortText(double value);
/// "'token'" with the token shortened to 40 characters, for messages; bytes outside printable
/// ASCII are written as \xNN so binary junk cannot garble the one-line message.
std::string quoted(std::string_view token);

} // namespace bunraku::analysis::io::detail
