#pragma once
/// The thesis's experiments as the command line shows them (`bunraku experiment noise|truth|km2o`):
/// each result as one JSON document and as the table printed beside the thesis's.

#include "analysis/core/result.h"
#include "analysis/decompose/km2o_experiment.h"
#include "analysis/design/design_corpus.h"
#include "analysis/normalise/noise_experiment.h"
#include "analysis/normalise/truth_experiment.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::report {

/// Thesis 3.4 with its own bands (ThesisNoiseBands), and the workbench's variant (scales 14..20
/// and 1..20 on the same signals), each as the thesis matched (single frames, no time
/// constraint) and with windows and the optimal monotone path.
struct NoiseComparison {
    NoiseExperimentOptions ours;
    NoiseExperimentResult thesis, thesisConstrained, workbench, workbenchConstrained;
};
Result<NoiseComparison> runNoiseComparison();
nlohmann::json noiseComparisonJson(const NoiseComparison& comparison);
std::string noiseComparisonText(const NoiseComparison& comparison);

/// The correspondences of every method against the ground truth (`options`: the coupling shown).
nlohmann::json truthExperimentJson(const TruthExperimentResult& result, const TruthExperimentOptions& options);
std::string truthExperimentText(const TruthExperimentResult& result, const TruthExperimentOptions& options);

/// P per M beside Table 4.4 (as percent and, for T = 1000, as printed).
nlohmann::json km2oExperimentJson(const Km2oExperimentResult& result, const Km2oExperimentOptions& options);
std::string km2oExperimentText(const Km2oExperimentResult& result, const Km2oExperimentOptions& options);

/// Thesis 5.5 on the synthetic corpus (`bunraku experiment design`), one cell: the design's
/// errors (evaluateDesignCell), the amplitude alone (the gains against the emotional axis
/// phase-adjusted by the true warp) and the means' errors against the truth.
struct DesignExperimentCell {
    DesignCellResult result;
    double amplitudeError = 0.0;
    double functionalMeanTruthError = 0.0, emotionalMeanTruthError = 0.0;
};
Result<DesignExperimentCell> runDesignExperimentCell(const AxisModel& model, const SyntheticDesignCell& cell,
                                                     const ExtractionOptions& options, const AxisOptions& axisOptions);
nlohmann::json designExperimentCellJson(const DesignExperimentCell& cell);
/// The table's header line, and a line per cell under it.
std::string designExperimentHeader();
std::string designExperimentCellText(const DesignExperimentCell& cell);

} // namespace bunraku::analysis::report
