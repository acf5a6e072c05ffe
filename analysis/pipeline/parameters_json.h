#pragma once
/// The chain's parameters as JSON: the "parameters" object of a project file and the file of
/// `bunraku analyse --parameters`. Reading is strict: every key known, every value of its type
/// and inside its range (checked before anything is allocated from it), errors naming the file,
/// the parameter and what was expected. Missing keys keep their defaults - "normalise"."path" too,
/// which is "optimal" since the default changed (a version-1 project, which stored only what
/// differed from the defaults of its day, is upgraded to "greedy": app/project_file.cpp; every
/// toJson writes the key). Format: docs/FORMATS.md.
///
/// {"preprocess": {"pad", "unwrap", "alignStart", "alignHeading", "alignPosition", "positionAlignment", "referenceTake"},
///  "normalise": {"tau", "searchBand", "maxScale", "coupling", "path": "greedy"|"optimal",
///                "reference": "suggested"|"average"|K, "cellReferences": {"f/e": ...}, "averageExcludesOutliers"},
///  "decompose": {"input": "normalised"|"preprocessed", "method": "km2o"|"least-squares", "M"},
///  "fluctuations": {"armaP", "armaQ", "welchSegment"},
///  "axis": {"frontBack": "shoulder"|"principal", "massSpacing", "masses": "model"|"primitives", "tau", "searchBand", "maxScale",
///           "approximationWeight", "level": "first-frame"|"none", "path", "controlSpacing", "refinementPasses"},
///  "design": {"emotionWeight", "warp": [[output, source], ...] | null,
///             "gains": [{"phrase", "dof", "g0", "g1"}], "boundaries": "suggested" | [frame, ...]}}

#include "analysis/core/result.h"
#include "analysis/pipeline/stage_parameters.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bunraku::analysis::pipeline {

/// Every parameter, defaults included.
nlohmann::json toJson(const ChainParameters& parameters);

/// Parses and validates; `where` ("session.bunraku.json: parameters") starts every message.
Result<ChainParameters> chainParametersFromJson(const nlohmann::json& value, const std::string& where);

/// "greedy" / "optimal"; "suggested" / "average" / a take index; "km2o" / "least-squares" ...
std::string pathName(PathMethod path);
std::string referenceName(const ReferenceChoice& choice);
std::string methodName(DecomposeMethod method);
std::string inputName(DecomposeInput input);

} // namespace bunraku::analysis::pipeline
