#include "app/cli/chain_parameters.h"

#include "app/cli/cli.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/pipeline/parameters_json.h"

#include <nlohmann/json.hpp>

#include <cstdint>

namespace bunraku::app::cli {

analysis::pipeline::ChainParameters readChainParameters(const std::string& file)
{
    if (file.empty()) return {};
    const std::string text = unwrap(analysis::io::readTextFile(file, analysis::io::kDocumentLimitBytes));
    const nlohmann::json document = unwrap(analysis::io::parseJsonText(text, file));
    // A project file holds the parameters under "parameters"; a parameters file may too.
    const nlohmann::json& parameters = document.is_object() && document.contains("parameters") ? document["parameters"] : document;
    return unwrap(analysis::pipeline::chainParametersFromJson(parameters, file));
}

std::string chainSubject(const std::string& corpus, const std::string& parametersFile)
{
    return parametersFile.empty() ? corpus : corpus + " with the parameters of " + parametersFile;
}

namespace {

namespace an = analysis;
namespace pl = analysis::pipeline;

/// The option's text read as the parameter files read a value: a JSON number ("100", "1e2",
/// "2.5"; not "0x10" or "inf"), else the text itself.
nlohmann::json asJsonValue(const std::string& text)
{
    const nlohmann::json number = nlohmann::json::parse(text, nullptr, false);
    if (!number.is_discarded() && number.is_number()) return number;
    return text;
}

const std::vector<std::string> kTimeScalings{"auto", "global", "none"};

} // namespace

MatchingArguments matchingDefaults(const pl::NormaliseParameters& parameters) { return {"normalise", parameters.options().match}; }

MatchingArguments matchingDefaults(const pl::AxisParameters& parameters)
{
    return {"axis", parameters.extractionOptions().phase.match};
}

CLI::Validator parameterCheck(std::string_view path)
{
    const pl::ParameterRange& range = pl::parameterRange(path);
    // The description --help shows is CLI11's own ("INT in [0 - 200]"); the check and its message are the files'.
    CLI::Validator check = range.integer ? CLI::Validator(CLI::Range(std::int64_t(range.low), std::int64_t(range.high)))
                                         : CLI::Validator(CLI::Range(range.low, range.high));
    check.operation([&range](std::string& text) -> std::string {
        const nlohmann::json value = asJsonValue(text);
        if (!value.is_number() || !range.contains(value.get<double>())) return pl::rangeProblem(range, value);
        // An integer the files accept ("1e2") is given to the option as it converts it ("100").
        if (range.integer) text = std::to_string(std::int64_t(value.get<double>()));
        return {};
    });
    return check;
}

void addMatchingOptions(CLI::App* command, MatchingArguments& arguments, bool timeScale)
{
    an::MatchOptions& options = arguments.options;
    command->add_option("--tau", options.tau, "Half window tau, frames (thesis 3.5.2)")
        ->transform(parameterCheck(arguments.section + ".tau"))
        ->capture_default_str();
    command->add_option("--tcmp", options.searchBand, "Search band T_cmp, frames (thesis 3.5.1)")
        ->transform(parameterCheck(arguments.section + ".searchBand"))
        ->capture_default_str();
    command->add_option("--approximation-weight", options.approximationWeight,
                        "Weight M of the approximation term (thesis eq. 5.17; 0 = off)")
        ->transform(parameterCheck(arguments.section + ".approximationWeight"))
        ->capture_default_str();
    addNamedParameter(command, "--path", options.path,
                      "Correspondence path: optimal (the least-cost monotone path) or greedy (the thesis's scan, 3.5.3)")
        ->default_str(pl::parameterName(options.path));
    addNamedParameter(command, "--weighting", options.weighting, "Channel weighting: none (the thesis) or standardise")
        ->default_str(pl::parameterName(options.weighting));
    addNamedParameter(command, "--level", options.level,
                      "Level of each channel before the transform: first-frame (minus its first frame) or none "
                      "(eq. 5.16 read literally)")
        ->default_str(pl::parameterName(options.level));
    if (!timeScale) return;
    const auto setTimeScaling = [&options](const std::string& name) {
        options.timeScaling = name == "global" ? an::TimeScaling::Global : name == "none" ? an::TimeScaling::None : an::TimeScaling::Auto;
    };
    command->add_option_function<std::string>("--time-scale", setTimeScaling,
                                              "Takes of other lengths: auto (a global time scale first when the lengths differ by "
                                              "more than half of T_cmp), global (always) or none (the thesis: the band alone)")
        ->check(CLI::IsMember(kTimeScalings))
        ->default_str("auto");
}

} // namespace bunraku::app::cli
