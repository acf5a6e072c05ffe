#pragma once
/// Atomic file writes: the content goes to a temporary file in the same folder, which is then
/// renamed over the destination. A failure leaves any previous file untouched.

#include "analysis/core/result.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace bunraku::analysis::io {

/// "." + leaf + marker + a suffix unique in this process and time: the name of a hidden
/// temporary sibling of `leaf` (a file or folder that is renamed over `leaf` when complete).
std::string temporarySiblingName(std::string_view leaf, std::string_view marker);
/// Writes `content` to `file` atomically (temp file in the same folder + rename).
Status writeFileAtomically(const std::filesystem::path& file, std::string_view content);
/// The whole file as text, or an Io error naming the file.
Result<std::string> readTextFile(const std::filesystem::path& file);

} // namespace bunraku::analysis::io
