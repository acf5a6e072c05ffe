#pragma once
/// Function and emotion components of a corpus from the KM2O-Langevin equation with exogenous
/// inputs and varying initial time (thesis 4.4.4, Table 4.5): per channel and function,
/// estimateExogenousInputs over the function's cells; y^i, z^{ij} from eqs. 4.42/4.43; eta the
/// rest. The correlation length M is given or chosen by the reconstruction error: the
/// relative error P^{ij} (eq. 4.40) of y^i + z^{ij} against the cell mean x_mean^{ij}, averaged
/// over channels and cells, is minimised over M = 1..M_max (the thesis found M = 2 on its data).

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/decompose/exogenous.h"
#include "analysis/decompose/least_squares.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

struct Km2oDecompositionOptions {
    /// M; 0 chooses it by reconstruction error over 1..lastCandidateLength.
    int correlationLength = 0;
    /// Largest M tried when choosing; 0 = M_max = floor(3 sqrt(T+1)) - 1.
    int lastCandidateLength = 0;
    /// The reading of the window averaging (docs/KM2O.md); correlationLength is overwritten.
    ExogenousOptions reading = {2, 1, InitialTimeRange::Full, WindowAverage::Uniform};
};

struct Km2oDecomposition {
    /// y^i, z^{ij} (eqs. 4.42/4.43), eta = x - y - z, cell means; same layout as least squares.
    Decomposition components;
    int correlationLength = 0;                ///< the M used
    std::vector<int> candidateLengths;        ///< M values tried (just M when given)
    std::vector<double> meanErrorPercent;     ///< mean P^{ij} [%] per candidate
    /// channels x cells (Decomposition::emotions order): P^{ij} [%] at the chosen M (Table 4.5).
    Eigen::MatrixXd cellErrorPercent;
    double meanCellErrorPercent = 0.0;        ///< mean of cellErrorPercent (thesis: 2.32 %)
};

/// Errors: as checkDecomposable, cells with fewer than 2 takes, M outside 1..M_max (the
/// message names M_max and T), cancellation between candidate lengths.
Result<Km2oDecomposition> decomposeKm2o(const Corpus& corpus, const Km2oDecompositionOptions& options = {},
                                        const RunControl& control = {});

} // namespace bunraku::analysis
