#pragma once
/// The chain's parameters as the command line takes them: `--parameters FILE` (a JSON file of
/// analysis/pipeline/parameters_json.h, or a project file, whose "parameters" are read), shared by
/// `analyse`, `decompose` and `emotion` so each runs the stages with the workbench's typed
/// parameters and defaults (docs/FORMATS.md).

#include "analysis/normalise/wavelet_matching.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/pipeline/stage_parameters.h"
#include "app/cli/cli.h"

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace bunraku::app::cli {

/// The defaults (the thesis's, but for normalisation's optimal path) for an empty name; else the file's parameters (strictly validated).
/// Throws CliError naming the file and what was expected.
analysis::pipeline::ChainParameters readChainParameters(const std::string& file);

/// What a chain's error is about: "CORPUS", or "CORPUS with the parameters of FILE" when a
/// parameters file was given (a value in its range may still fail at run time: a search band
/// longer than the takes), so the message names the file to change.
std::string chainSubject(const std::string& corpus, const std::string& parametersFile);

/// The check of an option naming an enumerated parameter: the names of the parameter files
/// (analysis::pipeline::parameterNames), one table for both.
template <class Enum>
CLI::IsMember namedParameterCheck()
{
    return CLI::IsMember(analysis::pipeline::parameterNameList<Enum>());
}

/// The value an option (checked by namedParameterCheck) names.
template <class Enum>
Enum namedParameter(const std::string& name)
{
    if (auto value = analysis::pipeline::parameterValue<Enum>(name)) return *value;
    throw CliError("'" + name + "' is not one of the names the parameter files use");
}

/// An option naming an enumerated parameter, bound onto the typed `value`: checked against the
/// names of the parameter files' tables (namedParameterCheck), one spelling for both.
template <class Enum>
CLI::Option* addNamedParameter(CLI::App* command, const std::string& name, Enum& value, const std::string& help)
{
    const auto set = [&value](const std::string& text) { value = namedParameter<Enum>(text); };
    return command->add_option_function<std::string>(name, set, help)->check(namedParameterCheck<Enum>());
}

/// The check of an option bound to the numeric parameter `path` ("normalise.tau"): the range of
/// the one table (analysis::pipeline::parameterRange) and the parameter files' message for a value
/// outside it ("--tau: expected an integer in 0..200, got the number 500"). --help shows the range.
/// Bound with `transform`: a value the files read as an integer ("1e2") reaches the option as one.
CLI::Validator parameterCheck(std::string_view path);

/// The wavelet matching's options as every command that matches takes them - `normalise` and
/// `experiment truth` (thesis 3.5), `phase` and `experiment design` (5.3): one spelling, one check
/// and one help line per option, the ranges of the analysis's table of limits
/// (stage_parameters.h) and the names of the parameter files' tables, bound onto the typed
/// options. The defaults are the command's stage's (matchingDefaults).
struct MatchingArguments {
    std::string section; ///< "normalise" or "axis": whose parameters the options are (their ranges)
    analysis::MatchOptions options; ///< the scales are each command's: --scales or --max-scale
};
/// The defaults of the normalise stage or of the axis stage (`bunraku analyse`'s).
MatchingArguments matchingDefaults(const analysis::pipeline::NormaliseParameters& parameters);
MatchingArguments matchingDefaults(const analysis::pipeline::AxisParameters& parameters);
/// --tau, --tcmp, --approximation-weight, --path, --weighting, --level, and --time-scale when
/// `timeScale` (the scales are each command's: --scales or --max-scale).
void addMatchingOptions(CLI::App* command, MatchingArguments& arguments, bool timeScale);

} // namespace bunraku::app::cli
