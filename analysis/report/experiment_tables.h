#pragma once
/// The thesis's experiments as the command line shows them (`bunraku experiment noise|truth|km2o`):
/// each result as one JSON document and as the table printed beside the thesis's.

#include "analysis/core/result.h"
#include "analysis/decompose/km2o_experiment.h"
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

} // namespace bunraku::analysis::report
