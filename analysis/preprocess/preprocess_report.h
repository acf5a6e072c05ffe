#pragma once
/// Thesis 2.2's preprocessing report per take as JSON and as a table (`bunraku preprocess`): the
/// frames padded, the angles unwrapped, the start shift, the references, the position offsets,
/// the branch turns and the heading offset.

#include "analysis/preprocess/preprocess.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::preprocess {

/// One entry per take (corpus order): take, frames_padded, angles_unwrapped, shift_frames,
/// time_reference, position_reference, position_offsets [{part, offset_cm}], branch_turns,
/// heading_offset_deg, heading_reference.
nlohmann::json preprocessReportJson(const PreprocessResult& result);
/// A header and a line per take: padded frames, unwraps, shift and the references it is.
std::string preprocessReportTable(const PreprocessReport& report);

} // namespace bunraku::analysis::preprocess
