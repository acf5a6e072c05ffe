// Every parameter a stage reads is in its key: a stage's key hashes its section of the parameter
// file (parametersText), so these tests walk the file's sections field by field - a field added
// to a parameter struct and its JSON is checked without editing them - and change each one to
// another value the reader accepts.
#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/parameters_json.h"

#include <catch2/catch.hpp>

#include <set>

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;
using nlohmann::json;

namespace {

/// Values to try in place of `value`: the other boolean, nearby numbers, every enumerated name
/// the files know, a few arrays and cells. The first one the reader accepts and that reads back
/// different is the change.
std::vector<json> candidates(const json& value)
{
    std::vector<json> out;
    if (value.is_boolean()) out.push_back(!value.get<bool>());
    if (value.is_number_integer()) {
        const auto v = value.get<std::int64_t>();
        out.insert(out.end(), {v + 1, v - 1, v + 2});
    }
    if (value.is_number_float()) {
        const double v = value.get<double>();
        out.insert(out.end(), {v * 1.5 + 0.25, v + 1.0, v / 2.0});
    }
    if (value.is_string()) {
        auto addNames = [&](const auto& table) {
            for (const auto& entry : table) out.push_back(entry.first);
        };
        addNames(parameterNames<PathMethod>());
        addNames(parameterNames<DecomposeMethod>());
        addNames(parameterNames<DecomposeInput>());
        addNames(parameterNames<ChannelWeighting>());
        addNames(parameterNames<LevelAlignment>());
        addNames(parameterNames<FrontBackAxis>());
        addNames(parameterNames<MassSource>());
        addNames(parameterNames<SegmentTable>());
        out.insert(out.end(), {"rigid", "per-part", "suggested", "average", "none", 1});
    }
    if (value.is_array()) out.insert(out.end(), {json::array({1}), json::array({1.0, 2.0, 4.0})});
    if (value.is_object()) out.push_back(json{{"greeting/joy", "average"}});
    return out;
}

/// `defaults` with `section.field` changed to a value the reader accepts and keeps, or nullopt.
std::optional<ChainParameters> changed(const json& defaults, const std::string& section, const std::string& field)
{
    for (const json& candidate : candidates(defaults[section][field])) {
        json edited = defaults;
        edited[section][field] = candidate;
        auto read = chainParametersFromJson(edited, "edited.json");
        if (!read) continue;
        if (toJson(*read)[section][field] != defaults[section][field]) return *read;
    }
    return std::nullopt;
}

} // namespace

TEST_CASE("changing any field of the parameters of a stage changes that stage's key and none above it",
          "[pipeline][parameters][keys]")
{
    const ChainParameters base;
    const json defaults = toJson(base);
    const StageKey corpus = KeyBuilder("a corpus").key();
    const ChainKeys before = chainKeys(corpus, base);
    // The section of each stage, and the stages above it whose keys must stay.
    const std::vector<std::pair<std::string, std::pair<Stage, std::vector<Stage>>>> sections{
        {"preprocess", {Stage::Preprocess, {Stage::Import}}},
        {"normalise", {Stage::Normalise, {Stage::Import, Stage::Preprocess}}},
        {"decompose", {Stage::Decompose, {Stage::Import, Stage::Preprocess, Stage::Normalise}}},
        {"fluctuations", {Stage::Fluctuations, {Stage::Import, Stage::Preprocess, Stage::Normalise, Stage::Decompose}}},
        {"axis", {Stage::Axes, {Stage::Import, Stage::Preprocess, Stage::Normalise, Stage::Decompose, Stage::Fluctuations}}}};
    int fields = 0;
    for (const auto& [section, stages] : sections) {
        REQUIRE(defaults[section].is_object());
        for (const auto& [field, value] : defaults[section].items()) {
            INFO(section + "." + field + " = " + value.dump());
            const auto edited = changed(defaults, section, field);
            // A field no candidate can change: give candidates() a value for it.
            REQUIRE(edited);
            const ChainKeys after = chainKeys(corpus, *edited);
            CHECK_FALSE(after.of(stages.first) == before.of(stages.first));
            for (Stage above : stages.second) CHECK(after.of(above) == before.of(above));
            ++fields;
        }
    }
    // Every section of the file but the design's (the design runs on the GUI thread, no stage).
    std::set<std::string> walked;
    for (const auto& entry : sections) walked.insert(entry.first);
    for (const auto& [section, value] : defaults.items())
        if (section != "design") CHECK(walked.count(section) == 1);
    CHECK(fields == int(defaults["preprocess"].size() + defaults["normalise"].size() + defaults["decompose"].size() +
                        defaults["fluctuations"].size() + defaults["axis"].size()));
    CHECK(fields >= 39);
}

TEST_CASE("a take's motion axis is keyed on the axis parameters of its body and on no other",
          "[pipeline][parameters][keys]")
{
    const ChainParameters base;
    const json defaults = toJson(base);
    const StageKey take = KeyBuilder("a take").key();
    const StageKey before = takeAxisKey(take, base.axis);
    const std::set<std::string> used(kTakeAxisParameters.begin(), kTakeAxisParameters.end());
    for (const auto& [field, value] : defaults["axis"].items()) {
        INFO("axis." + field + " = " + value.dump());
        const auto edited = changed(defaults, "axis", field);
        REQUIRE(edited);
        // The matching and design parameters are the corpus axes' (axisKey), not a take's.
        if (used.count(field))
            CHECK_FALSE(takeAxisKey(take, edited->axis) == before);
        else
            CHECK(takeAxisKey(take, edited->axis) == before);
    }
    for (const std::string& name : used) CHECK(defaults["axis"].contains(name));
}

TEST_CASE("changing any cloth parameter changes a kimono's key", "[pipeline][parameters][keys][cloth]")
{
    const StageKey take = KeyBuilder("a take").key();
    const BodyDescription body;
    const ClothParameters base;
    const StageKey before = kimonoKey(take, body, base);
    // Every member of the struct is in the table (they are all doubles).
    REQUIRE(clothParameterLimits().size() * sizeof(double) == sizeof(ClothParameters));
    for (const ClothParameterLimit& limit : clothParameterLimits()) {
        INFO(limit.name);
        ClothParameters edited = base;
        edited.*limit.member = base.*limit.member == limit.high ? limit.low : std::min(limit.high, base.*limit.member * 1.5 + 1e-3);
        REQUIRE(validate(edited).ok());
        CHECK_FALSE(kimonoKey(take, body, edited) == before);
    }
}
