#pragma once
/// The whole chain, stage after stage, each through the cache (stage_cache.h): what
/// `bunraku analyse` runs, what a report is made of, and - one stage per background job - what
/// the workbench's scheduler runs. The per-stage functions below are the only entry points;
/// both front ends call them with the same typed parameters, so they compute the same bits.

#include "analysis/pipeline/stage_cache.h"
#include "analysis/pipeline/stages.h"

#include <functional>
#include <stop_token>

namespace bunraku::analysis::pipeline {

/// The keys of every stage for a corpus and parameters (computed without running anything).
struct ChainKeys {
    StageKey import, preprocess, normalise, decompose, fluctuations, axes;
    StageKey of(Stage stage) const;
};
ChainKeys chainKeys(StageKey corpus, const ChainParameters& parameters);

// One stage each, looked up in `cache` first (null: always computed); progress and
// cancellation through `control`.
Result<Shared<PreprocessOutput>> preprocessStage(const CorpusInput& corpus, const PreprocessParameters& parameters,
                                                 StageCache* cache, const RunControl& control = {});
Result<Shared<NormaliseOutput>> normaliseStage(StageKey preprocessedKey, const PreprocessOutput& preprocessed,
                                               const NormaliseParameters& parameters, StageCache* cache,
                                               const RunControl& control = {});
/// `input`: the normalised corpus or the preprocessed one, as parameters.input says.
Result<Shared<DecomposeOutput>> decomposeStage(StageKey inputKey, const Corpus& input, const DecomposeParameters& parameters,
                                               StageCache* cache, const RunControl& control = {});
Result<Shared<FluctuationOutput>> fluctuationStage(StageKey decomposedKey, const DecomposeOutput& decomposed,
                                                   const FluctuationParameters& parameters, StageCache* cache,
                                                   const RunControl& control = {});
Result<Shared<AxisOutput>> axisStage(StageKey normalisedKey, const NormaliseOutput& normalised, const std::string& neutralEmotion,
                                     const AxisParameters& parameters, StageCache* cache, const RunControl& control = {});

struct ChainResult {
    CorpusInput corpus;
    ChainKeys keys;
    Shared<PreprocessOutput> preprocessed;
    Shared<NormaliseOutput> normalised;     ///< null when not asked for nor read (ChainOptions)
    Shared<DecomposeOutput> decomposed;     ///< null when not asked for nor read
    Shared<FluctuationOutput> fluctuations; ///< null when not asked for
    Shared<AxisOutput> axes;                ///< null when not asked for
};

/// The results wanted: a stage runs when its result is wanted or a wanted stage reads it (the
/// axes read the normalisation; the fluctuations the decomposition, which reads the
/// normalisation when DecomposeParameters::input says so). By default every stage runs.
struct ChainOptions {
    bool normalisation = true;
    bool decomposition = true;
    bool fluctuations = true;
    bool axes = true;
    std::stop_token stop;
    /// (stage, fraction of that stage done), from a computing thread, one call at a time.
    std::function<void(Stage, double)> progress;
    /// Threads for the stages that split into cells or channels (RunControl::threads); the
    /// results are the same for any count.
    int threads = 1;
};

/// Runs every stage in order; the first error stops the chain (its message names the stage).
Result<ChainResult> runChain(const CorpusInput& corpus, const ChainParameters& parameters, StageCache* cache,
                             const ChainOptions& options = {});

} // namespace bunraku::analysis::pipeline
