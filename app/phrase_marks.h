#pragma once
/// Phrase boundaries of a take, in seconds of the take, for the timeline's marks. Known for the
/// demo corpus from its ground truth: the cell's boundaries (cell frames u) mapped back through
/// the take's warp t -> u.

#include "analysis/core/take.h"
#include "analysis/synth/demo_corpus.h"

#include <vector>

namespace bunraku::app {

/// The inner phrase boundaries of `take` (seconds, increasing), or none when `truth` does not
/// describe the take.
std::vector<double> phraseBoundarySeconds(const analysis::synth::DemoGroundTruth& truth, const analysis::Take& take);

} // namespace bunraku::app
