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

#include <concepts>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis::pipeline {

/// Every parameter, defaults included.
nlohmann::json toJson(const ChainParameters& parameters);
/// One section of it ("preprocess", "normalise", ...): also what a stage's key hashes
/// (stageParametersText), so a parameter that reaches the file reaches the key.
nlohmann::json toJson(const PreprocessParameters& parameters);
nlohmann::json toJson(const NormaliseParameters& parameters);
nlohmann::json toJson(const DecomposeParameters& parameters);
nlohmann::json toJson(const FluctuationParameters& parameters);
nlohmann::json toJson(const AxisParameters& parameters);
nlohmann::json toJson(const DesignEdits& edits);
/// What a stage's key hashes of its parameters: the section's JSON, keys sorted and numbers
/// written to round trip, so every parameter the file holds changes the key. A stage section's
/// (its operator== defaulted: every field compared) equal to the one asked for last on this
/// thread gets that text again, not written anew: every stage's key is asked for at each change
/// of any parameter, and a drag changes one.
template <class Parameters>
    requires std::same_as<Parameters, PreprocessParameters> || std::same_as<Parameters, NormaliseParameters> ||
             std::same_as<Parameters, DecomposeParameters> || std::same_as<Parameters, FluctuationParameters> ||
             std::same_as<Parameters, AxisParameters>
std::string parametersText(const Parameters& parameters)
{
    thread_local std::optional<Parameters> last;
    thread_local std::string text;
    if (!last || !(*last == parameters)) {
        text = toJson(parameters).dump();
        last = parameters;
    }
    return text;
}

/// Parses and validates; `where` ("session.bunraku.json: parameters") starts every message.
Result<ChainParameters> chainParametersFromJson(const nlohmann::json& value, const std::string& where);

/// The names of an enumerated parameter, one table each, as the parameter files and the command
/// line spell them: specialised for PathMethod, DecomposeMethod, DecomposeInput,
/// ChannelWeighting, LevelAlignment, FrontBackAxis, MassSource, SegmentTable and
/// preprocess::PositionAlignment.
template <class Enum>
const std::map<std::string, Enum>& parameterNames();
template <> const std::map<std::string, PathMethod>& parameterNames<PathMethod>();
template <> const std::map<std::string, DecomposeMethod>& parameterNames<DecomposeMethod>();
template <> const std::map<std::string, DecomposeInput>& parameterNames<DecomposeInput>();
template <> const std::map<std::string, ChannelWeighting>& parameterNames<ChannelWeighting>();
template <> const std::map<std::string, LevelAlignment>& parameterNames<LevelAlignment>();
template <> const std::map<std::string, FrontBackAxis>& parameterNames<FrontBackAxis>();
template <> const std::map<std::string, MassSource>& parameterNames<MassSource>();
template <> const std::map<std::string, SegmentTable>& parameterNames<SegmentTable>();
template <> const std::map<std::string, preprocess::PositionAlignment>& parameterNames<preprocess::PositionAlignment>();

/// The value named `name`, nullopt for a name the table does not hold.
template <class Enum>
std::optional<Enum> parameterValue(const std::string& name)
{
    const auto& names = parameterNames<Enum>();
    const auto found = names.find(name);
    return found == names.end() ? std::nullopt : std::optional<Enum>(found->second);
}

/// The name of `value` in its table.
template <class Enum>
std::string parameterName(Enum value)
{
    for (const auto& [name, named] : parameterNames<Enum>())
        if (named == value) return name;
    return {};
}

/// Every name of the table (the command line's checks).
template <class Enum>
std::vector<std::string> parameterNameList()
{
    std::vector<std::string> list;
    for (const auto& entry : parameterNames<Enum>()) list.push_back(entry.first);
    return list;
}

/// What the parameter files say of a value outside a numeric parameter's range (parameterRange):
/// "expected an integer in 0..200, got the number 500". The command line's options bound to a
/// parameter say the same of their value.
std::string rangeProblem(const ParameterRange& range, const nlohmann::json& value);

/// "greedy" / "optimal"; "suggested" / "average" / a take index; "km2o" / "least-squares" ...
std::string pathName(PathMethod path);
std::string referenceName(const ReferenceChoice& choice);
std::string methodName(DecomposeMethod method);
std::string inputName(DecomposeInput input);

} // namespace bunraku::analysis::pipeline
