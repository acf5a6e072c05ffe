#pragma once
/// Function and emotion components of a corpus from the KM2O-Langevin equation with exogenous
/// inputs and varying initial time (thesis 4.4.4, Table 4.5): per channel and function,
/// estimateExogenousInputs over the function's cells; y^i, z^{ij} from eqs. 4.42/4.43; eta the
/// rest. The correlation length M is given or chosen by the reconstruction error: the
/// relative error P^{ij} (eq. 4.40) of y^i + z^{ij} against the cell mean x_mean^{ij}, averaged
/// over channels and cells, is minimised over M = 1..M_max (the thesis found M = 2 on its data).
/// Cells with one take (docs/KM2O.md, "Cells with one take"): gamma_+ and V_+ pooled from the
/// diff series of the function's cells with K >= 2 (eq. 4.39: the dynamics a^i are the
/// function's); a function without such a cell is not estimable by KM2O and keeps its
/// least-squares y^i, z^{ij} (eq. 4.8), said per cell and in `notes`.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/decompose/exogenous.h"
#include "analysis/decompose/least_squares.h"

#include <Eigen/Core>

#include <string>
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

/// How the KM2O-Langevin data gamma_+, V_+ of a cell were obtained.
enum class Km2oCellSource {
    OwnTakes,     ///< from the cell's own K >= 2 diff series (eqs. 4.24-4.35)
    Pooled,       ///< one take: from the pooled diff series of its function's cells with K >= 2
    LeastSquares, ///< no cell of its function has 2 takes: not estimable, y, z by least squares (eq. 4.8)
};

/// "own takes", "pooled", "least squares" (the analysis files' and reports' word).
const char* km2oCellSourceName(Km2oCellSource source);

struct Km2oCellEstimate {
    std::string function;
    std::string emotion;
    int takes = 0; ///< K of the cell
    Km2oCellSource source = Km2oCellSource::OwnTakes;
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
    /// Per cell (Decomposition::emotions order): K and where its gamma_+, V_+ came from.
    /// cellErrorPercent is NaN for least-squares cells (no KM2O estimate to measure); means are
    /// over the KM2O cells; with no KM2O cell at all M = 0, no candidates, mean P NaN.
    std::vector<Km2oCellEstimate> cells;
    /// One sentence per pooled cell and per function not estimable, naming the cells and what
    /// is needed; empty when every cell has K >= 2.
    std::vector<std::string> notes;

    /// Whether any cell was estimated by KM2O (own or pooled gamma).
    bool estimable() const;
    /// One line: "KM2O for all 6 cells", "KM2O for 4 cells (2 with pooled gamma), least squares
    /// for 3 cells of 1 function", "KM2O not estimable (no cell has 2 takes): least squares".
    std::string outcome() const;
};

/// Errors: as checkDecomposable, M outside 1..M_max (the message names M_max and T),
/// cancellation between candidate lengths. One-take cells are no error (see above).
Result<Km2oDecomposition> decomposeKm2o(const Corpus& corpus, const Km2oDecompositionOptions& options = {},
                                        const RunControl& control = {});

} // namespace bunraku::analysis
