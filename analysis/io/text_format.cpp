#include "analysis/io/text_format.h"

#include <charconv>
#include <system_error>

namespace bunraku::analysis::io {

void appendShortestNumber(std::string& out, double value)
{
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, ec == std::errc() ? end : buffer); // 64 characters always suffice
}

std::string shortestNumber(double value)
{
    std::string out;
    appendShortestNumber(out, value);
    return out;
}

std::string fileSafeLabel(std::string_view label)
{
    std::string out(label);
    for (char& c : out) {
        const bool keep = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
        if (!keep) c = '-';
    }
    return out;
}

} // namespace bunraku::analysis::io
