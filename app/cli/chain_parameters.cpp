#include "app/cli/chain_parameters.h"

#include "app/cli/cli.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/pipeline/parameters_json.h"

#include <nlohmann/json.hpp>

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

} // namespace bunraku::app::cli
