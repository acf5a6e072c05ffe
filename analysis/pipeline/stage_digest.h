#pragma once
/// Digests of stage results: a 64-bit hash (stage_key.h's mixing) of every number, index and
/// label a stage's result holds, so that two computations of a stage - before and after a
/// change to how it is computed, on one thread or several - can be shown to give the same bits.
/// Equal results give equal digests; a single changed bit anywhere changes the digest.

#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/stage_key.h"
#include "analysis/pipeline/stages.h"

namespace bunraku::analysis::pipeline {

StageKey resultDigest(const PreprocessOutput& preprocessed);
StageKey resultDigest(const NormaliseOutput& normalised);
StageKey resultDigest(const DecomposeOutput& decomposed);
StageKey resultDigest(const FluctuationOutput& fluctuations);
StageKey resultDigest(const AxisOutput& axes);

/// The digests of every stage a chain computed (empty keys for stages it did not run).
struct ChainDigest {
    StageKey preprocess, normalise, decompose, fluctuations, axes;
    /// "preprocess=<hex> normalise=<hex> ...", the stages that ran.
    std::string text() const;
    bool operator==(const ChainDigest&) const = default;
};
ChainDigest chainDigest(const ChainResult& chain);

} // namespace bunraku::analysis::pipeline
