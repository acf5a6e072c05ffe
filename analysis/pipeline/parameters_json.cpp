#include "analysis/pipeline/parameters_json.h"

#include "analysis/decompose/emotion_weight.h"
#include "analysis/io/text_format.h"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace bunraku::analysis::pipeline {
namespace {

using nlohmann::json;

/// What a JSON value holds, for messages ("the number 2e+09", "a string"): a number as it reads
/// back exactly (200.0000001 is not "200").
std::string describe(const json& value)
{
    if (value.is_number()) return "the number " + io::shortestNumber(value.get<double>());
    if (value.is_string()) return "the string \"" + value.get<std::string>().substr(0, 40) + "\"";
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_null()) return "null";
    if (value.is_array()) return "an array";
    return "an object";
}

/// Reads one JSON object field by field; the first problem is kept and reported.
class Reader {
public:
    Reader(const json& object, std::string path, std::string where)
        : m_object(object), m_path(std::move(path)), m_where(std::move(where))
    {
    }

    bool isObject()
    {
        if (m_object.is_object()) return true;
        fail(m_path, "expected an object, got " + describe(m_object));
        return false;
    }

    /// Refuses keys not in `known` (a typo would otherwise be ignored silently).
    void onlyKeys(std::initializer_list<const char*> known)
    {
        if (!ok() || !m_object.is_object()) return;
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            bool found = false;
            for (const char* key : known) found = found || it.key() == key;
            if (!found) {
                std::string list;
                for (const char* key : known) list += (list.empty() ? "" : ", ") + std::string(key);
                fail(m_path + "." + it.key(), "unknown parameter (known: " + list + ")");
                return;
            }
        }
    }

    void integer(const char* key, int& out, int low, int high)
    {
        const json* value = find(key);
        if (!value) return;
        const double number = value->is_number() ? value->get<double>() : std::numeric_limits<double>::quiet_NaN();
        if (!value->is_number() || !std::isfinite(number) || number != std::floor(number) || number < low || number > high) {
            fail(m_path + "." + key, "expected an integer in " + std::to_string(low) + ".." + std::to_string(high) + ", got " +
                                         describe(*value));
            return;
        }
        out = int(number);
    }

    void real(const char* key, double& out, double low, double high)
    {
        const json* value = find(key);
        if (!value) return;
        if (!value->is_number() || !std::isfinite(value->get<double>()) || value->get<double>() < low || value->get<double>() > high) {
            std::ostringstream range;
            range << "[" << low << ", " << high << "]";
            fail(m_path + "." + key, "expected a number in " + range.str() + ", got " + describe(*value));
            return;
        }
        out = value->get<double>();
    }

    /// A numeric parameter with its range from the one table (stage_parameters.h).
    template <class Number> void number(const char* key, Number& out)
    {
        const json* value = find(key);
        if (!value) return;
        const std::string path = m_path.substr(m_path.find('.') + 1) + "." + key; // "parameters.normalise" -> "normalise.tau"
        const ParameterRange& range = parameterRange(path);
        if (!value->is_number() || !range.contains(value->get<double>())) {
            fail(m_path + "." + key, rangeProblem(range, *value));
            return;
        }
        out = Number(value->get<double>());
    }

    void boolean(const char* key, bool& out)
    {
        const json* value = find(key);
        if (!value) return;
        if (!value->is_boolean()) {
            fail(m_path + "." + key, "expected true or false, got " + describe(*value));
            return;
        }
        out = value->get<bool>();
    }

    template <class Enum> void choice(const char* key, Enum& out, const std::map<std::string, Enum>& names)
    {
        const json* value = find(key);
        if (!value) return;
        std::string list;
        for (const auto& [name, unused] : names) list += (list.empty() ? "" : ", ") + name;
        if (!value->is_string() || !names.count(value->get<std::string>())) {
            fail(m_path + "." + key, "expected one of " + list + ", got " + describe(*value));
            return;
        }
        out = names.at(value->get<std::string>());
    }

    void text(const char* key, std::string& out, std::size_t maxLength)
    {
        const json* value = find(key);
        if (!value) return;
        if (!value->is_string() || value->get<std::string>().empty() || value->get<std::string>().size() > maxLength) {
            fail(m_path + "." + key, "expected a non-empty string of at most " + std::to_string(maxLength) + " characters, got " +
                                         describe(*value));
            return;
        }
        out = value->get<std::string>();
    }

    const json* find(const char* key)
    {
        if (!ok() || !m_object.is_object()) return nullptr;
        const auto found = m_object.find(key);
        return found == m_object.end() ? nullptr : &*found;
    }

    void fail(const std::string& path, const std::string& what)
    {
        if (ok()) m_error = makeError(ErrorCode::Parse, m_where + ": " + path + ": " + what);
    }
    bool ok() const { return !m_error.has_value(); }
    const Error& error() const { return *m_error; }
    const std::string& path() const { return m_path; }
    const std::string& where() const { return m_where; }
    /// Takes over the first error of a nested reader.
    void absorb(const Reader& inner)
    {
        if (!inner.ok() && ok()) m_error = inner.error();
    }

    /// A reader of the nested object `key` sharing this one's error (nothing when absent).
    template <class Read> void nested(const char* key, Read&& read)
    {
        const json* value = find(key);
        if (!value) return;
        Reader inner(*value, m_path + "." + key, m_where);
        if (inner.isObject()) read(inner);
        absorb(inner);
    }

private:
    const json& m_object;
    std::string m_path;
    std::string m_where;
    std::optional<Error> m_error;
};

const std::map<std::string, PathMethod> kPaths{{"greedy", PathMethod::Greedy}, {"optimal", PathMethod::Optimal}};
const std::map<std::string, DecomposeMethod> kMethods{{"km2o", DecomposeMethod::Km2o},
                                                      {"least-squares", DecomposeMethod::LeastSquares}};
const std::map<std::string, DecomposeInput> kInputs{{"normalised", DecomposeInput::Normalised},
                                                    {"preprocessed", DecomposeInput::Preprocessed}};
const std::map<std::string, ChannelWeighting> kWeightings{{"none", ChannelWeighting::None},
                                                          {"standardise", ChannelWeighting::Standardise}};
const std::map<std::string, LevelAlignment> kLevels{{"first-frame", LevelAlignment::FirstFrame}, {"none", LevelAlignment::None}};
const std::map<std::string, preprocess::PositionAlignment> kPositionAlignments{
    {"rigid", preprocess::PositionAlignment::Rigid}, {"per-part", preprocess::PositionAlignment::PerPart}};
const std::map<std::string, FrontBackAxis> kFrontBack{{"shoulder", FrontBackAxis::ShoulderForward},
                                                      {"principal", FrontBackAxis::Principal}};
const std::map<std::string, MassSource> kMassSources{{"model", MassSource::Model}, {"primitives", MassSource::Primitives}};
const std::map<std::string, SegmentTable> kSegmentTables{{"male", SegmentTable::DeLevaMale}, {"female", SegmentTable::DeLevaFemale}};

json referenceJson(const ReferenceChoice& choice)
{
    if (choice.kind == ReferenceKind::Take) return choice.takeIndex;
    return choice.kind == ReferenceKind::Average ? "average" : "suggested";
}

void readReference(Reader& reader, const json& value, const std::string& path, ReferenceChoice& out)
{
    if (value.is_string() && value.get<std::string>() == "suggested") {
        out = {ReferenceKind::Suggested, 0};
    } else if (value.is_string() && value.get<std::string>() == "average") {
        out = {ReferenceKind::Average, 0};
    } else if (value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() == std::floor(value.get<double>()) &&
               value.get<double>() >= 1 && value.get<double>() <= kMaxTakeIndex) {
        out = {ReferenceKind::Take, int(value.get<double>())};
    } else {
        reader.fail(path, "expected \"suggested\", \"average\" or a take index 1.." + std::to_string(kMaxTakeIndex) + ", got " +
                              describe(value));
    }
}

void readNormalise(Reader& r, NormaliseParameters& p)
{
    r.onlyKeys({"tau", "searchBand", "maxScale", "coupling", "path", "reference", "cellReferences", "averageExcludesOutliers",
                "averageBase", "averageExcluded", "scales", "weighting", "level", "approximationWeight"});
    r.choice("weighting", p.weighting, kWeightings);
    r.choice("level", p.level, kLevels);
    r.number("approximationWeight", p.approximationWeight);
    if (const json* scales = r.find("scales")) {
        if (!scales->is_array() || scales->size() > std::size_t(kMaxScale)) {
            r.fail(r.path() + ".scales", "expected an array of at most 256 scales, got " + describe(*scales));
            return;
        }
        for (std::size_t i = 0; i < scales->size(); ++i) {
            const json& scale = (*scales)[i];
            if (!scale.is_number() || !(scale.get<double>() > 0.0) || scale.get<double>() > kMaxScale) {
                r.fail(r.path() + ".scales[" + std::to_string(i) + "]", "expected a scale in (0, 256], got " + describe(scale));
                return;
            }
            p.scales.push_back(scale.get<double>());
        }
    }
    r.number("averageBase", p.averageBase);
    if (const json* excluded = r.find("averageExcluded")) {
        if (!excluded->is_array() || excluded->size() > 10000) {
            r.fail(r.path() + ".averageExcluded", "expected an array of take indices, got " + describe(*excluded));
            return;
        }
        const ParameterRange& range = parameterRange("normalise.averageExcluded");
        for (std::size_t i = 0; i < excluded->size(); ++i) {
            const json& take = (*excluded)[i];
            if (!take.is_number() || !range.contains(take.get<double>())) {
                r.fail(r.path() + ".averageExcluded[" + std::to_string(i) + "]", rangeProblem(range, take));
                return;
            }
            p.averageExcluded.push_back(int(take.get<double>()));
        }
    }
    r.number("tau", p.tau);
    r.number("searchBand", p.searchBand);
    r.number("maxScale", p.maxScale);
    r.text("coupling", p.coupling, 4096);
    r.choice("path", p.path, kPaths);
    if (const json* reference = r.find("reference")) readReference(r, *reference, r.path() + ".reference", p.reference);
    r.boolean("averageExcludesOutliers", p.averageExcludesOutliers);
    if (const json* cells = r.find("cellReferences")) {
        if (!cells->is_object()) {
            r.fail(r.path() + ".cellReferences", "expected an object {\"function/emotion\": reference}, got " + describe(*cells));
            return;
        }
        if (cells->size() > 10000) {
            r.fail(r.path() + ".cellReferences", "more than 10000 cells");
            return;
        }
        for (auto it = cells->begin(); it != cells->end() && r.ok(); ++it) {
            ReferenceChoice choice;
            readReference(r, it.value(), r.path() + ".cellReferences." + it.key(), choice);
            if (it.key().find('/') == std::string::npos || it.key().size() > 1000)
                r.fail(r.path() + ".cellReferences." + it.key(), "expected a cell named \"function/emotion\"");
            p.cellReferences[it.key()] = choice;
        }
    }
}

void readDesign(Reader& r, DesignEdits& d)
{
    r.onlyKeys({"emotionWeight", "warp", "gains", "boundaries"});
    r.number("emotionWeight", d.emotionWeight);
    if (const json* warp = r.find("warp"); warp && !warp->is_null()) {
        if (!warp->is_array() || warp->size() < 2 || warp->size() > kMaxWarpPoints) {
            r.fail(r.path() + ".warp", "expected null or 2.." + std::to_string(kMaxWarpPoints) +
                                           " control points [output frame, source frame], got " +
                                           (warp->is_array() ? std::to_string(warp->size()) + " points" : describe(*warp)));
            return;
        }
        WarpCurve curve;
        curve.points.reserve(warp->size());
        for (std::size_t i = 0; i < warp->size(); ++i) {
            const json& point = (*warp)[i];
            const std::string path = r.path() + ".warp[" + std::to_string(i) + "]";
            if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) {
                r.fail(path, "expected [output frame, source frame], got " + describe(point));
                return;
            }
            const double output = point[0].get<double>(), source = point[1].get<double>();
            if (!std::isfinite(output) || !std::isfinite(source) || output < 0 || source < 0 || output > kMaxWarpFrame ||
                source > kMaxWarpFrame) {
                r.fail(path, "expected frames in [0, 1e8]");
                return;
            }
            curve.points.push_back({output, source});
        }
        curve.outputFrames = Eigen::Index(std::floor(curve.points.back().output)) + 1;
        if (auto valid = validateWarpCurve(curve); !valid) {
            r.fail(r.path() + ".warp", valid.error().message);
            return;
        }
        d.warp = std::move(curve);
    }
    if (const json* gains = r.find("gains")) {
        if (!gains->is_array() || gains->size() > kMaxGainEdits) {
            r.fail(r.path() + ".gains", "expected an array of at most " + std::to_string(kMaxGainEdits) + " gains, got " + describe(*gains));
            return;
        }
        for (std::size_t i = 0; i < gains->size() && r.ok(); ++i) {
            Reader gain((*gains)[i], r.path() + ".gains[" + std::to_string(i) + "]", r.where());
            GainEdit edit;
            if (gain.isObject()) {
                gain.onlyKeys({"phrase", "dof", "g0", "g1"});
                gain.integer("phrase", edit.phrase, 0, int(kMaxPhraseBoundaries));
                gain.integer("dof", edit.dof, 0, 1000);
                gain.real("g0", edit.g0, -kMaxGain, kMaxGain);
                gain.real("g1", edit.g1, -kMaxGain, kMaxGain);
            }
            r.absorb(gain);
            if (!r.ok()) return;
            if (d.gain(edit.phrase, edit.dof)) {
                r.fail(r.path() + ".gains[" + std::to_string(i) + "]", "phrase " + std::to_string(edit.phrase) + ", DOF " +
                                                                        std::to_string(edit.dof) + " is given twice");
                return;
            }
            d.setGain(edit);
        }
    }
    if (const json* boundaries = r.find("boundaries")) {
        if (boundaries->is_string() && boundaries->get<std::string>() == "suggested") {
            d.boundaries = {};
        } else if (boundaries->is_array() && boundaries->size() <= kMaxPhraseBoundaries) {
            PhraseBoundaries edited{false, {}};
            edited.inner.reserve(boundaries->size());
            for (std::size_t i = 0; i < boundaries->size(); ++i) {
                const json& frame = (*boundaries)[i];
                const double value = frame.is_number() ? frame.get<double>() : -1.0;
                if (!frame.is_number() || !std::isfinite(value) || value != std::floor(value) || value < 1 || value > kMaxWarpFrame ||
                    (i > 0 && value <= double(edited.inner.back()))) {
                    r.fail(r.path() + ".boundaries[" + std::to_string(i) + "]",
                           "expected increasing whole frames in 1..1e8 (the inner phrase boundaries), got " + describe(frame));
                    return;
                }
                edited.inner.push_back(Eigen::Index(value));
            }
            d.boundaries = std::move(edited);
        } else {
            r.fail(r.path() + ".boundaries", "expected \"suggested\" or an array of at most " + std::to_string(kMaxPhraseBoundaries) +
                                                 " inner boundaries, got " + describe(*boundaries));
        }
    }
}

} // namespace

template <> const std::map<std::string, PathMethod>& parameterNames<PathMethod>() { return kPaths; }
template <> const std::map<std::string, DecomposeMethod>& parameterNames<DecomposeMethod>() { return kMethods; }
template <> const std::map<std::string, DecomposeInput>& parameterNames<DecomposeInput>() { return kInputs; }
template <> const std::map<std::string, ChannelWeighting>& parameterNames<ChannelWeighting>() { return kWeightings; }
template <> const std::map<std::string, LevelAlignment>& parameterNames<LevelAlignment>() { return kLevels; }
template <> const std::map<std::string, FrontBackAxis>& parameterNames<FrontBackAxis>() { return kFrontBack; }
template <> const std::map<std::string, MassSource>& parameterNames<MassSource>() { return kMassSources; }
template <> const std::map<std::string, SegmentTable>& parameterNames<SegmentTable>() { return kSegmentTables; }
template <> const std::map<std::string, preprocess::PositionAlignment>& parameterNames<preprocess::PositionAlignment>()
{
    return kPositionAlignments;
}

std::string rangeProblem(const ParameterRange& range, const json& value)
{
    return "expected " + range.expected() + ", got " + describe(value);
}

std::string pathName(PathMethod path) { return parameterName(path); }

std::string referenceName(const ReferenceChoice& choice)
{
    if (choice.kind == ReferenceKind::Take) return std::to_string(choice.takeIndex);
    return choice.kind == ReferenceKind::Average ? "average" : "suggested";
}

std::string methodName(DecomposeMethod method) { return parameterName(method); }

std::string inputName(DecomposeInput input) { return parameterName(input); }

json toJson(const PreprocessParameters& p)
{
    return {{"pad", p.pad},
            {"unwrap", p.unwrap},
            {"alignStart", p.alignStart},
            {"alignHeading", p.alignHeading},
            {"alignPosition", p.alignPosition},
            {"positionAlignment", preprocess::positionAlignmentName(p.positionAlignment)},
            {"referenceTake", p.referenceTakeIndex}};
}

json toJson(const NormaliseParameters& p)
{
    json cells = json::object();
    for (const auto& [cell, choice] : p.cellReferences) cells[cell] = referenceJson(choice);
    return {{"tau", p.tau},
            {"searchBand", p.searchBand},
            {"maxScale", p.maxScale},
            {"coupling", p.coupling},
            {"path", pathName(p.path)},
            {"reference", referenceJson(p.reference)},
            {"cellReferences", cells},
            {"averageExcludesOutliers", p.averageExcludesOutliers},
            {"averageBase", p.averageBase},
            {"averageExcluded", p.averageExcluded},
            {"scales", p.scales},
            {"weighting", parameterName(p.weighting)},
            {"level", parameterName(p.level)},
            {"approximationWeight", p.approximationWeight}};
}

json toJson(const DecomposeParameters& p)
{
    return {{"input", inputName(p.input)}, {"method", methodName(p.method)}, {"M", p.correlationLength}};
}

json toJson(const FluctuationParameters& p)
{
    return {{"armaP", p.armaP}, {"armaQ", p.armaQ}, {"welchSegment", p.welchSegment}};
}

json toJson(const AxisParameters& p)
{
    return {{"frontBack", parameterName(p.frontBack)},
            {"massSpacing", p.massSpacing},
            {"masses", parameterName(p.masses)},
            {"segments", parameterName(p.segments)},
            {"tau", p.tau},
            {"searchBand", p.searchBand},
            {"maxScale", p.maxScale},
            {"approximationWeight", p.approximationWeight},
            {"level", parameterName(p.level)},
            {"path", pathName(p.path)},
            {"controlSpacing", p.controlSpacing},
            {"refinementPasses", p.refinementPasses}};
}

json toJson(const DesignEdits& d)
{
    json warp = nullptr;
    if (d.warp) {
        warp = json::array();
        for (const auto& point : d.warp->points) warp.push_back({point.output, point.source});
    }
    json gains = json::array();
    for (const auto& g : d.gains) gains.push_back({{"phrase", g.phrase}, {"dof", g.dof}, {"g0", g.g0}, {"g1", g.g1}});
    json boundaries = "suggested";
    if (!d.boundaries.suggested) {
        boundaries = json::array();
        for (const Eigen::Index frame : d.boundaries.inner) boundaries.push_back(std::int64_t(frame));
    }
    return {{"emotionWeight", d.emotionWeight}, {"warp", warp}, {"gains", gains}, {"boundaries", boundaries}};
}

json toJson(const ChainParameters& p)
{
    return {{"preprocess", toJson(p.preprocess)}, {"normalise", toJson(p.normalise)}, {"decompose", toJson(p.decompose)},
            {"fluctuations", toJson(p.fluctuations)}, {"axis", toJson(p.axis)}, {"design", toJson(p.design)}};
}

Result<ChainParameters> chainParametersFromJson(const json& value, const std::string& where)
{
    ChainParameters p;
    Reader root(value, "parameters", where);
    if (!root.isObject()) return root.error();
    root.onlyKeys({"preprocess", "normalise", "decompose", "fluctuations", "axis", "design"});
    root.nested("preprocess", [&](Reader& r) {
        r.onlyKeys({"pad", "unwrap", "alignStart", "alignHeading", "alignPosition", "positionAlignment", "referenceTake"});
        r.boolean("pad", p.preprocess.pad);
        r.boolean("unwrap", p.preprocess.unwrap);
        r.boolean("alignStart", p.preprocess.alignStart);
        r.boolean("alignHeading", p.preprocess.alignHeading);
        r.boolean("alignPosition", p.preprocess.alignPosition);
        r.choice("positionAlignment", p.preprocess.positionAlignment, kPositionAlignments);
        r.number("referenceTake", p.preprocess.referenceTakeIndex);
    });
    root.nested("normalise", [&](Reader& r) { readNormalise(r, p.normalise); });
    root.nested("decompose", [&](Reader& r) {
        r.onlyKeys({"input", "method", "M"});
        r.choice("input", p.decompose.input, kInputs);
        r.choice("method", p.decompose.method, kMethods);
        r.number("M", p.decompose.correlationLength);
    });
    root.nested("fluctuations", [&](Reader& r) {
        r.onlyKeys({"armaP", "armaQ", "welchSegment"});
        r.number("armaP", p.fluctuations.armaP);
        r.number("armaQ", p.fluctuations.armaQ);
        r.number("welchSegment", p.fluctuations.welchSegment);
    });
    root.nested("axis", [&](Reader& r) {
        r.onlyKeys({"frontBack", "massSpacing", "masses", "segments", "tau", "searchBand", "maxScale", "approximationWeight", "level", "path", "controlSpacing",
                    "refinementPasses"});
        r.choice("frontBack", p.axis.frontBack, kFrontBack);
        r.number("massSpacing", p.axis.massSpacing);
        r.choice("masses", p.axis.masses, kMassSources);
        r.choice("segments", p.axis.segments, kSegmentTables);
        r.number("tau", p.axis.tau);
        r.number("searchBand", p.axis.searchBand);
        r.number("maxScale", p.axis.maxScale);
        r.number("approximationWeight", p.axis.approximationWeight);
        r.choice("level", p.axis.level, kLevels);
        r.choice("path", p.axis.path, kPaths);
        r.number("controlSpacing", p.axis.controlSpacing);
        r.number("refinementPasses", p.axis.refinementPasses);
    });
    root.nested("design", [&](Reader& r) { readDesign(r, p.design); });
    if (!root.ok()) return root.error();
    if (auto status = validate(p); !status) return makeError(ErrorCode::Parse, where + ": " + status.error().message);
    return p;
}

} // namespace bunraku::analysis::pipeline
