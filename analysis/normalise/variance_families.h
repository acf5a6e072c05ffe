#pragma once
/// The variance table (thesis 3.8) per DOF family, never adding centimetres to degrees: per take,
/// one row per family (position in cm^2, rotation in deg^2: the channels' units, squared) with
/// the sum over parts, then one row per part. What the Normalisation panel's tree and
/// `bunraku normalise` show; the thesis's own total over all 24 channels stays in VarianceTable.

#include "analysis/core/take.h"
#include "analysis/normalise/variance_evaluation.h"

#include <string>
#include <vector>

namespace bunraku::analysis {

/// One row: a DOF family of a take, or a part within it.
struct VarianceRow {
    std::string take;   ///< VarianceTable::takeNames
    std::string family; ///< "position", "rotation", or the unit when it is neither
    std::string unit;   ///< the channels' unit, squared: "cm²", "deg²"
    std::string part;   ///< empty: the family's sum over parts
    double before = 0.0;
    double after = 0.0;
    /// The reference take against itself gives exactly 0 before and after (normaliseTake keeps
    /// a take's own numbers when every frame maps to itself).
    bool worse() const { return after > before; }
};

/// "position" for cm, mm and m; "rotation" for deg and rad; else the unit ("unitless" if none).
std::string varianceFamily(const std::string& unit);

/// Every row of `table` (takes x channels, `channels` its columns in order): per take, per
/// family (in order of first appearance), the family's sum, then each part's.
std::vector<VarianceRow> varianceRows(const VarianceTable& table, const std::vector<Channel>& channels);

} // namespace bunraku::analysis
