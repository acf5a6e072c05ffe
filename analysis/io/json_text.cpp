#include "analysis/io/json_text.h"

#include <algorithm>

namespace bunraku::analysis::io {

namespace {

using nlohmann::json;

/// The library's DOM builder with the position of the first error kept (the DOM builder itself
/// forgets it, and a number overflow reaches the caller as out_of_range without a byte offset).
class PositionedDomParser {
public:
    explicit PositionedDomParser(json& result) : m_dom(result, false) {}

    bool null() { return m_dom.null(); }
    bool boolean(bool value) { return m_dom.boolean(value); }
    bool number_integer(json::number_integer_t value) { return m_dom.number_integer(value); }
    bool number_unsigned(json::number_unsigned_t value) { return m_dom.number_unsigned(value); }
    bool number_float(json::number_float_t value, const json::string_t& text) { return m_dom.number_float(value, text); }
    bool string(json::string_t& value) { return m_dom.string(value); }
    bool binary(json::binary_t& value) { return m_dom.binary(value); }
    bool start_object(std::size_t size) { return m_dom.start_object(size); }
    bool key(json::string_t& value) { return m_dom.key(value); }
    bool end_object() { return m_dom.end_object(); }
    bool start_array(std::size_t size) { return m_dom.start_array(size); }
    bool end_array() { return m_dom.end_array(); }
    bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::detail::exception& error)
    {
        if (!m_failed) {
            m_failed = true;
            m_position = position;
            m_reason = jsonErrorReason(error);
        }
        return m_dom.parse_error(position, lastToken, error);
    }

    bool failed() const { return m_failed; }
    std::size_t position() const { return m_position; }
    const std::string& reason() const { return m_reason; }

private:
    nlohmann::detail::json_sax_dom_parser<json> m_dom;
    bool m_failed = false;
    std::size_t m_position = 0;
    std::string m_reason;
};

} // namespace

std::string jsonErrorReason(const nlohmann::json::exception& error)
{
    std::string_view what = error.what();
    if (what.rfind("[json.exception.", 0) == 0) {
        const auto close = what.find("] ");
        if (close != std::string_view::npos) what.remove_prefix(close + 2);
    }
    if (what.rfind("parse error at line ", 0) == 0) {
        const auto colon = what.find(": ");
        if (colon != std::string_view::npos) what.remove_prefix(colon + 2);
    }
    static constexpr char hex[] = "0123456789abcdef";
    static constexpr std::size_t limit = 200;
    std::string out;
    for (const char c : what.substr(0, limit)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            out += c;
        } else {
            out += "\\x";
            out += hex[byte >> 4];
            out += hex[byte & 0xf];
        }
    }
    if (what.size() > limit) out += "...";
    return out;
}

Result<json> parseJsonText(std::string_view text, const std::string& sourceName, const std::string& expectation)
{
    json document;
    PositionedDomParser parser(document);
    try {
        json::sax_parse(text, &parser);
    } catch (const json::exception& error) { // the DOM builder's own limits (none known), reported the same way
        return parseError(sourceName, 0, expectation + ": " + jsonErrorReason(error));
    }
    if (!parser.failed()) return document;
    const std::size_t offset = std::min(parser.position(), text.size());
    const long line = 1 + long(std::count(text.begin(), text.begin() + std::ptrdiff_t(offset), '\n'));
    return parseError(sourceName, line, expectation + ": " + parser.reason());
}

} // namespace bunraku::analysis::io
