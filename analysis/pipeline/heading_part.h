#pragma once
/// The part whose start yaw is the whole-body heading in preprocessing (thesis 2.2, step 5):
/// the puppet's shoulder; on takes of a skeleton's joints, which have no part of that name, the
/// joint the arms branch from (the chest, the joint the automatic part map binds the shoulder
/// to; analysis/normalise/skeleton_chains.h).

#include "analysis/core/corpus.h"

#include <string>

namespace bunraku::analysis::pipeline {

/// `part` when the corpus's first take has `part`.yaw; else, for a take with a skeleton, the
/// parent joint of its arm chains when that joint is a part of the take; else `part`.
std::string headingPartFor(const Corpus& corpus, const std::string& part);

} // namespace bunraku::analysis::pipeline
