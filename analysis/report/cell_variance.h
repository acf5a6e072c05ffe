#pragma once
/// Thesis 3.8's variance of a normalised cell per take and DOF family (cm² apart from deg²), as
/// the Normalisation panel shows them, with the thesis's total over all channels (Tables 3.4/3.5)
/// beside (`bunraku normalise`'s summary and table).

#include "analysis/core/take.h"
#include "analysis/pipeline/stages.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace bunraku::analysis::report {

/// Per take (cell order): take, cost, variance_raw, variance_normalised, families [{family, unit,
/// raw, normalised}] and outlier (3.6.1). `channels`: the cell's takes' channels.
nlohmann::json cellVarianceJson(const pipeline::CellNormalisation& cell, const std::vector<Channel>& channels);
/// The same as a table: a line per take and family with the change in %, "worse" where the
/// normalised take is further from the reference than the raw one; then which takes those are,
/// followed by `worseHint` (what to try instead).
std::string cellVarianceText(const pipeline::CellNormalisation& cell, const std::vector<Channel>& channels,
                             const std::string& worseHint);

} // namespace bunraku::analysis::report
