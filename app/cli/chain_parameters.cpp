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

template <class Parameters>
MatchingArguments defaultsOf(const Parameters& p, std::string section)
{
    MatchingArguments arguments;
    arguments.section = std::move(section);
    arguments.tau = p.tau;
    arguments.searchBand = p.searchBand;
    arguments.approximationWeight = p.approximationWeight;
    arguments.path = pl::parameterName(p.path);
    arguments.weighting = pl::parameterName(an::ChannelWeighting::None);
    arguments.level = pl::parameterName(p.level);
    return arguments;
}

const std::vector<std::string> kTimeScalings{"auto", "global", "none"};

} // namespace

MatchingArguments matchingDefaults(const pl::NormaliseParameters& parameters)
{
    MatchingArguments arguments = defaultsOf(parameters, "normalise");
    arguments.weighting = pl::parameterName(parameters.weighting);
    return arguments;
}

MatchingArguments matchingDefaults(const pl::AxisParameters& parameters) { return defaultsOf(parameters, "axis"); }

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
    command->add_option("--tau", arguments.tau, "Half window tau, frames (thesis 3.5.2)")
        ->transform(parameterCheck(arguments.section + ".tau"))
        ->capture_default_str();
    command->add_option("--tcmp", arguments.searchBand, "Search band T_cmp, frames (thesis 3.5.1)")
        ->transform(parameterCheck(arguments.section + ".searchBand"))
        ->capture_default_str();
    command->add_option("--approximation-weight", arguments.approximationWeight,
                        "Weight M of the approximation term (thesis eq. 5.17; 0 = off)")
        ->transform(parameterCheck(arguments.section + ".approximationWeight"))
        ->capture_default_str();
    command->add_option("--path", arguments.path,
                        "Correspondence path: optimal (the least-cost monotone path) or greedy (the thesis's scan, 3.5.3)")
        ->check(namedParameterCheck<an::PathMethod>())
        ->capture_default_str();
    command->add_option("--weighting", arguments.weighting, "Channel weighting: none (the thesis) or standardise")
        ->check(namedParameterCheck<an::ChannelWeighting>())
        ->capture_default_str();
    command->add_option("--level", arguments.level,
                        "Level of each channel before the transform: first-frame (minus its first frame) or none "
                        "(eq. 5.16 read literally)")
        ->check(namedParameterCheck<an::LevelAlignment>())
        ->capture_default_str();
    if (timeScale)
        command->add_option("--time-scale", arguments.timeScale,
                            "Takes of other lengths: auto (a global time scale first when the lengths differ by more "
                            "than half of T_cmp), global (always) or none (the thesis: the band alone)")
            ->check(CLI::IsMember(kTimeScalings))
            ->capture_default_str();
}

an::MatchOptions matchOptions(const MatchingArguments& arguments, std::vector<double> scales)
{
    an::MatchOptions options;
    options.scales = std::move(scales);
    options.tau = arguments.tau;
    options.searchBand = arguments.searchBand;
    options.approximationWeight = arguments.approximationWeight;
    options.path = namedParameter<an::PathMethod>(arguments.path);
    options.weighting = namedParameter<an::ChannelWeighting>(arguments.weighting);
    options.level = namedParameter<an::LevelAlignment>(arguments.level);
    options.timeScaling = arguments.timeScale == "global" ? an::TimeScaling::Global
                          : arguments.timeScale == "none" ? an::TimeScaling::None
                                                          : an::TimeScaling::Auto;
    return options;
}

} // namespace bunraku::app::cli
