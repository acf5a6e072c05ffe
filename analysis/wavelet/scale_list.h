#pragma once
/// Wavelet scales written as text, as the command line takes them (`--scales`): "1:16",
/// "2:2:16" (first:step:last) or a comma list "1,2,4,8".

#include "analysis/core/result.h"

#include <string>
#include <vector>

namespace bunraku::analysis {

/// The scales `text` lists; a Parse error says what was expected (the text, or the field, quoted).
Result<std::vector<double>> parseScaleList(const std::string& text);

} // namespace bunraku::analysis
