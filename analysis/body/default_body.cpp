#include "analysis/body/body_description.h"
#include "analysis/body/default_body_json.h" // generated from resources/puppet/bunraku_puppet.json

#include <cassert>

namespace bunraku::analysis {

const BodyDescription& defaultBodyDescription()
{
    static const BodyDescription body = [] {
        Result<BodyDescription> parsed = parseBodyDescription(kDefaultBodyJson, "resources/puppet/bunraku_puppet.json");
        assert(parsed.ok() && "the shipped body description must parse");
        return std::move(parsed).value();
    }();
    return body;
}

} // namespace bunraku::analysis
