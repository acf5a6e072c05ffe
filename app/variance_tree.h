#pragma once
/// The Normalisation panel's variance table (thesis 3.8, Tables 3.4/3.5) as a tree that never
/// adds centimetres to degrees: per take, one row per DOF family (position in cm^2, rotation in
/// deg^2: the channels' units, squared) with the sum over parts, and under it one row per part.
/// Columns: Before, After (the squared difference to the reference summed over frames and the
/// row's channels) and Change. Every number has the same notation (fixed, one decimal, grouped
/// digits). A row whose normalised take is further from the reference than the raw take is
/// marked (red, "worse"), and so is its take's row.

#include "analysis/core/take.h"
#include "analysis/normalise/variance_evaluation.h"
#include "analysis/normalise/variance_families.h"

#include <QString>

#include <string>
#include <vector>

class QTreeWidget;
class QTreeWidgetItem;

namespace bunraku::app {

/// The tree's rows are analysis::varianceRows (analysis/normalise/variance_families.h).
using analysis::VarianceRow;
using analysis::varianceRows;

/// The notation of every number of the tree: "13,812.4".
QString varianceText(double value);

/// Fills `tree` (columns: Take / family / part, Before, After, Change) with `table`; takes and
/// families expanded, parts collapsed. `takeLabels` (one per take, e.g. "take 2"; empty: the
/// table's take names) is what the take rows show. Families read "pos. cm²" and "rot. deg²".
void fillVarianceTree(QTreeWidget* tree, const analysis::VarianceTable& table, const std::vector<analysis::Channel>& channels,
                      const std::vector<QString>& takeLabels = {});

/// Whether `item` is marked worse than before.
bool isMarkedWorse(const QTreeWidgetItem* item);

} // namespace bunraku::app
