#pragma once
/// Small formatting helpers shared by every writer (CSV takes, BVH, the demo ground truth, the
/// decomposition output): shortest round-trip numbers and file-name-safe labels.

#include <string>
#include <string_view>

namespace bunraku::analysis::io {

/// Appends the shortest decimal text that reads back to exactly `value` (std::to_chars);
/// non-finite values append "nan", "inf" or "-inf".
void appendShortestNumber(std::string& out, double value);
/// The shortest round-trip text of `value` (see appendShortestNumber).
std::string shortestNumber(double value);
/// `label` with every character outside [A-Za-z0-9_-] replaced by '-' (may be empty).
std::string fileSafeLabel(std::string_view label);

} // namespace bunraku::analysis::io
