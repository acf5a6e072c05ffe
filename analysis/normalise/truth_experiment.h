#pragma once
/// The ground-truth experiment on the synthetic corpus (issue 3, THESIS-DIGEST 3.5.3 "report
/// which recovers true warps better"): in every function x emotion cell, every take is
/// normalised to the cell's reference take and each channel's correspondence is compared with
/// the true one (synth::trueCorrespondence), for the thesis's greedy scan, the optimal path and
/// the amplitude baseline; and arm and hand are checked to stay together.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/synth/demo_corpus.h"

#include <string>
#include <vector>

namespace bunraku::analysis {

struct TruthExperimentOptions {
    /// Coupling, scales, tau, band (defaults: auto, the thesis's method2 on the puppet's parts;
    /// 1..16, 4, 20). The path is set per method.
    NormaliseOptions normalise;
    /// Take index of each cell's reference; 0 = suggestReference per cell (thesis 3.6.1).
    int referenceTakeIndex = 0;
    /// Also run the optimal wavelet path with every channel alone ("wavelet-optimal-independent"),
    /// which shows why the thesis couples arm and hand.
    bool includeIndependent = true;
};

struct TruthMethodResult {
    std::string name; ///< wavelet-greedy, wavelet-optimal, amplitude-dp, wavelet-optimal-independent
    double meanAbsErrorFrames = 0; ///< over cells, non-reference takes, reference frames, channels
    double maxAbsErrorFrames = 0;
    /// Fraction of normalised frames whose arm-hand receiver distance lies within the range the
    /// raw takes of the cell show (tolerance 0.5 cm): arm and hand "stay together".
    double armHandWithinRange = 0;
    /// Largest excess of the arm-hand distance beyond that range, cm.
    double armHandMaxExcessCm = 0;
};

struct TruthExperimentResult {
    std::vector<TruthMethodResult> methods;
    int cells = 0;
    int pairs = 0; ///< normalised (reference, take) pairs per method
};

/// Angles are unwrapped first (preprocess::unwrapAngles); frames are not shifted or padded, so
/// the truth applies unchanged. InvalidArgument when a take has no ground truth or the corpus
/// lacks the puppet layout; Cancelled via control.
Result<TruthExperimentResult> runTruthExperiment(const Corpus& corpus, const synth::DemoGroundTruth& truth,
                                                 const TruthExperimentOptions& options = {},
                                                 const RunControl& control = {});

} // namespace bunraku::analysis
