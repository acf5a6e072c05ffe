#pragma once
/// Values quoted in error messages, bounded: a 1 MB label given on the command line or read from
/// a file must not make a 1 MB error line.

#include <string>
#include <string_view>

namespace bunraku::analysis {

/// `value` for a message: at most `limit` characters, cut with "..." (never inside a UTF-8
/// character).
inline std::string shortenedForMessage(std::string_view value, std::size_t limit = 80)
{
    if (value.size() <= limit) return std::string(value);
    std::size_t cut = limit > 3 ? limit - 3 : 0;
    while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;
    return std::string(value.substr(0, cut)) + "...";
}

} // namespace bunraku::analysis
