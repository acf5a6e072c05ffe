#include "analysis/io/import_options_json.h"

#include <cmath>
#include <optional>

/// std::optional as JSON: null when empty (nlohmann-json 3.11.2 has no serializer for it).
namespace nlohmann {
template <class T>
struct adl_serializer<std::optional<T>> {
    static void to_json(json& out, const std::optional<T>& value)
    {
        if (value) out = *value;
        else out = nullptr;
    }
    static void from_json(const json& in, std::optional<T>& value)
    {
        if (in.is_null()) value.reset();
        else value = in.get<T>();
    }
};
} // namespace nlohmann

namespace bunraku::analysis {

// Every field of every options struct, by name (a new field: add its name here).
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(TakeLabels, function, emotion, takeIndex, source)
NLOHMANN_JSON_SERIALIZE_ENUM(BodySide, {{BodySide::Right, "right"}, {BodySide::Left, "left"}})

namespace io {

NLOHMANN_JSON_SERIALIZE_ENUM(BvhUpAxis, {{BvhUpAxis::Auto, "auto"}, {BvhUpAxis::Y, "y"}, {BvhUpAxis::Z, "z"}})
NLOHMANN_JSON_SERIALIZE_ENUM(BvhPositionMode, {{BvhPositionMode::ReplaceOffset, "replace-offset"},
                                               {BvhPositionMode::AddToOffset, "add-to-offset"}})
NLOHMANN_JSON_SERIALIZE_ENUM(BvhTakeLayout, {{BvhTakeLayout::PuppetParts, "puppet-parts"}, {BvhTakeLayout::AllJoints, "all-joints"}})
NLOHMANN_JSON_SERIALIZE_ENUM(FastrakUnits, {{FastrakUnits::Centimetres, "cm"}, {FastrakUnits::Inches, "in"}})

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(JointMap, joints)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(BvhKinematicsOptions, positionMode)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(BvhImportOptions, jointMap, upAxis, unitScale, guessUnits, kinematics, labels, side,
                                                calibrationFrame)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(TakeCsvOptions, rateHz, timeMustMatchRate, timeTolerance, labels)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(FastrakOptions, rateHz, units, stations, labels)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SceneTakeOptions, animation, rateHz)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ImportOptions, csv, bvh, bvhLayout, fastrak, scene)

namespace {

/// An enum's text that NLOHMANN_JSON_SERIALIZE_ENUM does not know would silently become the
/// first value: refuse it instead.
template <class Enum>
bool knownEnumText(const nlohmann::json& value)
{
    if (!value.is_string()) return false;
    const Enum parsed = value.get<Enum>();
    return nlohmann::json(parsed) == value;
}

Status checkEnums(const nlohmann::json& json, const std::string& where)
{
    const auto check = [&](const nlohmann::json::json_pointer& pointer, bool (*known)(const nlohmann::json&)) -> Status {
        if (!json.contains(pointer) || known(json.at(pointer))) return okStatus();
        return parseError(where, 0, pointer.to_string() + ": unknown value " + json.at(pointer).dump().substr(0, 40));
    };
    using P = nlohmann::json::json_pointer;
    for (const auto& [pointer, known] :
         {std::pair{P("/bvh/upAxis"), &knownEnumText<BvhUpAxis>}, std::pair{P("/bvh/kinematics/positionMode"), &knownEnumText<BvhPositionMode>},
          std::pair{P("/bvhLayout"), &knownEnumText<BvhTakeLayout>}, std::pair{P("/bvh/side"), &knownEnumText<BodySide>}, std::pair{P("/fastrak/units"), &knownEnumText<FastrakUnits>}})
        if (auto ok = check(pointer, known); !ok) return ok;
    return okStatus();
}

/// Every number of the options is a rate, a scale, a tolerance, a station, a take or a frame
/// number: none needs more than 2^31 in magnitude, and nlohmann-json converts a larger floating
/// value to an int field with undefined behaviour - refuse it first, naming where it is.
Status checkNumbers(const nlohmann::json& json, const std::string& where, const std::string& path = {})
{
    if (json.is_number()) {
        const double value = json.get<double>();
        if (!std::isfinite(value) || std::fabs(value) > 2147483647.0)
            return parseError(where, 0, "import options: " + (path.empty() ? std::string("/") : path) + ": " + json.dump().substr(0, 40) +
                                            " is out of range");
        return okStatus();
    }
    if (json.is_array()) {
        for (std::size_t i = 0; i < json.size(); ++i)
            if (auto ok = checkNumbers(json[i], where, path + "/" + std::to_string(i)); !ok) return ok;
    } else if (json.is_object()) {
        for (const auto& [key, value] : json.items())
            if (auto ok = checkNumbers(value, where, path + "/" + key); !ok) return ok;
    }
    return okStatus();
}

} // namespace

nlohmann::json importOptionsToJson(const ImportOptions& options) { return options; }

Result<ImportOptions> importOptionsFromJson(const nlohmann::json& json, const std::string& where)
{
    if (!json.is_object()) return parseError(where, 0, "expected the import options as a JSON object");
    if (auto enums = checkEnums(json, where); !enums) return enums.error();
    if (auto numbers = checkNumbers(json, where); !numbers) return numbers.error();
    ImportOptions options;
    try {
        options = json.get<ImportOptions>();
    } catch (const nlohmann::json::exception& error) {
        return parseError(where, 0, std::string("import options: ") + error.what());
    }
    if (options.csv.rateHz && !plausibleRate(*options.csv.rateHz))
        return parseError(where, 0, "import options: csv.rateHz: " + rateExpectation());
    if (!plausibleRate(options.fastrak.rateHz)) return parseError(where, 0, "import options: fastrak.rateHz: " + rateExpectation());
    if (!plausibleRate(options.scene.rateHz)) return parseError(where, 0, "import options: scene.rateHz: " + rateExpectation());
    if (options.scene.animation.size() > 4096) return parseError(where, 0, "import options: scene.animation: expected a name of at most 4096 bytes");
    if (!(options.csv.timeTolerance >= 0.0 && options.csv.timeTolerance <= 0.5))
        return parseError(where, 0, "import options: csv.timeTolerance: expected a fraction in [0, 0.5]");
    if (!(std::isfinite(options.bvh.unitScale) && options.bvh.unitScale > 0.0 && options.bvh.unitScale <= 1e6))
        return parseError(where, 0, "import options: bvh.unitScale: expected centimetres per file unit in (0, 1e6]");
    if (options.bvh.calibrationFrame < 0 || options.bvh.calibrationFrame > Eigen::Index(1) << 40)
        return parseError(where, 0, "import options: bvh.calibrationFrame: expected a frame number from 0");
    for (const int station : options.fastrak.stations)
        if (station < 1 || station > 9) return parseError(where, 0, "import options: fastrak.stations: expected stations 1 to 9");
    return options;
}

} // namespace io
} // namespace bunraku::analysis
