#include "analysis/io/text_scan.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace bunraku::analysis::io::detail {

std::vector<TextLine> splitLines(std::string_view text)
{
    std::vector<TextLine> lines;
    long number = 1;
    std::size_t start = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; // a UTF-8 byte order mark (Excel writes one)
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        const bool last = end == std::string_view::npos;
        if (last) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (!(last && line.empty())) lines.push_back(TextLine{number, line});
        if (last) break;
        start = end + 1;
        ++number;
    }
    return lines;
}

std::string_view trim(std::string_view text)
{
    const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

std::vector<std::string_view> splitWhitespace(std::string_view text)
{
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r') ++i;
        if (i > start) tokens.push_back(text.substr(start, i - start));
    }
    return tokens;
}

std::vector<std::string_view> splitFields(std::string_view text, char separator)
{
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        if (end == std::string_view::npos) {
            fields.push_back(trim(text.substr(start)));
            break;
        }
        fields.push_back(trim(text.substr(start, end - start)));
        start = end + 1;
    }
    return fields;
}

ParsedNumber parseNumber(std::string_view token)
{
    if (token.empty()) return {};
    std::string_view body = token;
    if (body.front() == '+') body.remove_prefix(1);
    if (body.empty()) return {};
    double value = 0.0;
    const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
    if (end != body.data() + body.size()) return {};
    if (ec == std::errc::result_out_of_range) {
        // Underflow is a (tiny) number; overflow is not finite.
        const double approx = std::strtod(std::string(body).c_str(), nullptr);
        if (std::isfinite(approx) && std::fabs(approx) < 1.0) return ParsedNumber{NumberStatus::Ok, approx};
        return ParsedNumber{NumberStatus::NonFinite, approx};
    }
    if (ec != std::errc()) return {};
    if (!std::isfinite(value)) return ParsedNumber{NumberStatus::NonFinite, value};
    return ParsedNumber{NumberStatus::Ok, value};
}

std::optional<long> parseInteger(std::string_view token)
{
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (token.empty() || ec != std::errc() || end != token.data() + token.size()) return std::nullopt;
    return value;
}

bool isUtf8(std::string_view text)
{
    std::size_t i = 0;
    while (i < text.size()) {
        const auto lead = static_cast<unsigned char>(text[i]);
        std::size_t length = 0;
        unsigned char low = 0x80, high = 0xBF; // the allowed range of the second byte
        if (lead < 0x80) length = 1;
        else if (lead >= 0xC2 && lead <= 0xDF) length = 2;
        else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            if (lead == 0xE0) low = 0xA0;  // overlong
            if (lead == 0xED) high = 0x9F; // surrogates
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            if (lead == 0xF0) low = 0x90;  // overlong
            if (lead == 0xF4) high = 0x8F; // past U+10FFFF
        } else {
            return false;
        }
        if (text.size() - i < length) return false;
        for (std::size_t k = 1; k < length; ++k) {
            const auto byte = static_cast<unsigned char>(text[i + k]);
            if (byte < (k == 1 ? low : 0x80) || byte > (k == 1 ? high : 0xBF)) return false;
        }
        i += length;
    }
    return true;
}

std::string shortText(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

std::string quoted(std::string_view token)
{
    static constexpr char hex[] = "0123456789abcdef";
    std::string out = "'";
    for (const char c : token.substr(0, 40)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            out += c;
        } else {
            out += "\\x";
            out += hex[byte >> 4];
            out += hex[byte & 0xf];
        }
    }
    if (token.size() > 40) out += "...";
    out += '\'';
    return out;
}

} // namespace bunraku::analysis::io::detail
