#include "app/project_file.h"

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/pipeline/parameters_json.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/import_options_json.h"
#include "analysis/io/json_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <filesystem>
#include <optional>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace bunraku::app {
namespace {

using analysis::ErrorCode;
using analysis::makeError;
using analysis::parseError;
using nlohmann::json;

constexpr qint64 kMaxProjectBytes = 64 * 1024 * 1024;
constexpr int kMaxImported = 10000;
constexpr qsizetype kMaxWindowStateChars = 64 * 1024; ///< a window's dock layout is a few kB
/// The view values the main window stores, with their ranges (MainWindow::viewState).
struct ViewRange {
    const char* key;
    double low, high;
};
constexpr ViewRange kViewRanges[] = {{"graphLayout", 0, 3}, {"twoTakeMode", 0, 1}, {"valueScale", 0, 1}, {"angleDisplay", 0, 1}, {"figureA", 0, 4}, {"figureB", 0, 4}, {"cloth", 0, 1}, {"speed", 0.1, 4.0}, {"leftWidth", 0, 100000}, {"windowWidth", 0, 100000}};

QJsonObject viewJson(const ViewState& view)
{
    QJsonObject out;
    auto put = [&](const char* key, const auto& value) {
        if (value) out[QLatin1String(key)] = *value;
    };
    put("graphLayout", view.graphLayout);
    put("twoTakeMode", view.twoTakeMode);
    put("valueScale", view.valueScale);
    put("angleDisplay", view.angleDisplay);
    put("thesisTicks", view.thesisTicks);
    put("part", view.part);
    put("dof", view.dof);
    if (view.camera) {
        const CameraState& c = *view.camera;
        out["camera"] = QJsonObject{{"angle", c.angle},
                                    {"elevation", c.elevation},
                                    {"distance", c.distance},
                                    {"target", QJsonArray{c.target[0], c.target[1], c.target[2]}},
                                    {"fov", c.fov}};
    }
    QJsonObject shown;
    for (const auto& [key, member] : kShownObjectKeys)
        if (const std::optional<bool>& value = view.shown.*member) shown[QLatin1String(key)] = *value;
    if (!shown.isEmpty()) out["show"] = shown;
    put("figureA", view.figureA);
    put("figureB", view.figureB);
    if (view.cloth) out["cloth"] = *view.cloth ? 1 : 0;
    if (view.clothParameters) {
        QJsonObject values;
        for (const analysis::ClothParameterLimit& limit : analysis::clothParameterLimits())
            values[QLatin1String(limit.name)] = (*view.clothParameters).*(limit.member);
        out["clothParameters"] = values;
    }
    put("weightEmotion", view.weightEmotion);
    put("cellFunction", view.cellFunction);
    put("cellEmotion", view.cellEmotion);
    put("speed", view.speed);
    if (view.windowState) out["windowState"] = QString::fromLatin1(view.windowState->toBase64());
    put("leftWidth", view.leftWidth);
    put("windowWidth", view.windowWidth);
    return out;
}

/// The view of a checked "view" object (readProject checked every value first).
ViewState viewState(const QJsonObject& view)
{
    ViewState out;
    auto number = [&](const char* key, auto& field) {
        if (view.contains(QLatin1String(key))) field = std::remove_reference_t<decltype(*field)>(view[QLatin1String(key)].toDouble());
    };
    auto text = [&](const char* key, std::optional<QString>& field) {
        if (view.contains(QLatin1String(key))) field = view[QLatin1String(key)].toString();
    };
    number("graphLayout", out.graphLayout);
    number("twoTakeMode", out.twoTakeMode);
    number("valueScale", out.valueScale);
    number("angleDisplay", out.angleDisplay);
    if (view.contains("thesisTicks")) out.thesisTicks = view["thesisTicks"].toBool();
    text("part", out.part);
    text("dof", out.dof);
    if (view.contains("camera")) {
        const QJsonObject camera = view["camera"].toObject();
        const QJsonArray target = camera["target"].toArray();
        CameraState c;
        c.angle = camera["angle"].toDouble();
        c.elevation = camera["elevation"].toDouble();
        c.distance = camera["distance"].toDouble();
        c.target = {target[0].toDouble(), target[1].toDouble(), target[2].toDouble()};
        c.fov = camera["fov"].toDouble(35.0);
        out.camera = c;
    }
    const QJsonObject shown = view["show"].toObject();
    for (const auto& [key, member] : kShownObjectKeys)
        if (shown.contains(QLatin1String(key))) out.shown.*member = shown[QLatin1String(key)].toBool();
    number("figureA", out.figureA);
    number("figureB", out.figureB);
    if (view.contains("cloth")) out.cloth = view["cloth"].toDouble() != 0.0;
    if (view.contains("clothParameters")) {
        // The keys it holds; the others keep their defaults.
        const QJsonObject values = view["clothParameters"].toObject();
        analysis::ClothParameters cloth;
        for (const analysis::ClothParameterLimit& limit : analysis::clothParameterLimits())
            if (values.contains(QLatin1String(limit.name))) cloth.*(limit.member) = values[QLatin1String(limit.name)].toDouble();
        out.clothParameters = cloth;
    }
    text("weightEmotion", out.weightEmotion);
    text("cellFunction", out.cellFunction);
    text("cellEmotion", out.cellEmotion);
    number("speed", out.speed);
    number("leftWidth", out.leftWidth);
    number("windowWidth", out.windowWidth);
    // The window's dock layout (base64 of QMainWindow::saveState): a malformed one is left out,
    // the project still opens (the layout as it is).
    const QJsonValue layout = view["windowState"];
    if (layout.isString() && layout.toString().size() <= kMaxWindowStateChars)
        if (const auto decoded = QByteArray::fromBase64Encoding(layout.toString().toLatin1(), QByteArray::AbortOnBase64DecodingErrors))
            out.windowState = *decoded;
    return out;
}

long lineOfOffset(const QByteArray& text, int offset) { return 1 + long(text.left(offset).count('\n')); }

/// The line of the first `"key":` in the project's text, 0 when there is none: the line a value's
/// error names.
long lineOfKey(const QByteArray& text, const char* key)
{
    const QByteArray quoted = '"' + QByteArray(key) + '"';
    for (qsizetype at = text.indexOf(quoted); at >= 0; at = text.indexOf(quoted, at + 1)) {
        qsizetype next = at + quoted.size();
        while (next < text.size() && (text[next] == ' ' || text[next] == '\t' || text[next] == '\r' || text[next] == '\n')) ++next;
        if (next < text.size() && text[next] == ':') return lineOfOffset(text, int(at));
    }
    return 0;
}

/// Version 1's flat parameters ("normalise.tau": 4, "design.gains": {"p/d": [g0, g1]}, ...) in
/// version 2's typed layout. Version 1 decomposed the preprocessed takes, by least squares
/// unless the project chose KM2O. It stored only the values that differed from the defaults of
/// its day, when the path defaulted to the greedy scan: a version-1 project without
/// "normalise.path" meant greedy and keeps it (version 2 writes every parameter, the path too).
json upgradeVersion1(const json& flat)
{
    json p = {{"decompose", {{"input", "preprocessed"}, {"method", "least-squares"}}}, {"normalise", {{"path", "greedy"}}}};
    if (!flat.is_object()) return p;
    auto copy = [&](const char* from, const char* section, const char* key) {
        if (flat.contains(from)) p[section][key] = flat[from];
    };
    copy("normalise.tau", "normalise", "tau");
    copy("normalise.searchBand", "normalise", "searchBand");
    copy("normalise.maxScale", "normalise", "maxScale");
    copy("normalise.coupling", "normalise", "coupling");
    copy("normalise.path", "normalise", "path");
    copy("emotion.method", "decompose", "method");
    copy("emotion.weight", "design", "emotionWeight");
    if (flat.contains("emotion.order") && p["decompose"]["method"] == "km2o") p["decompose"]["M"] = flat["emotion.order"];
    if (flat.contains("design.warp") && flat["design.warp"].is_array() && !flat["design.warp"].empty()) p["design"]["warp"] = flat["design.warp"];
    if (flat.contains("design.gains") && flat["design.gains"].is_object()) {
        json gains = json::array();
        for (auto it = flat["design.gains"].begin(); it != flat["design.gains"].end(); ++it) {
            const auto slash = it.key().find('/');
            json entry = {{"g0", it.value().is_array() && it.value().size() == 2 ? it.value()[0] : json()},
                          {"g1", it.value().is_array() && it.value().size() == 2 ? it.value()[1] : json()}};
            try {
                entry["phrase"] = std::stoi(it.key().substr(0, slash));
                entry["dof"] = std::stoi(it.key().substr(slash + 1));
            } catch (const std::exception&) {
                entry["phrase"] = it.key(); // refused by the reader with its name
            }
            gains.push_back(entry);
        }
        std::sort(gains.begin(), gains.end(), [](const json& a, const json& b) {
            return a["phrase"].dump() + "/" + a["dof"].dump() < b["phrase"].dump() + "/" + b["dof"].dump();
        });
        p["design"]["gains"] = gains;
    }
    if (flat.contains("design.boundaries") && flat["design.boundaries"].is_array()) {
        const json& b = flat["design.boundaries"];
        if (b.empty()) p["design"]["boundaries"] = "suggested";
        else if (b.size() == 1 && b[0] == 0) p["design"]["boundaries"] = json::array(); // version 1's "no inner boundary"
        else p["design"]["boundaries"] = b;
    }
    return p;
}

/// The take id spelt `text` (TakeId::toString()'s "corpus/N", "imported/N", "live/name"; empty:
/// no take); nothing when it is none of these. The one place that reads an id's text.
std::optional<TakeId> parseTakeId(const QString& text)
{
    if (text.isEmpty()) return TakeId();
    static const QRegularExpression pattern(QStringLiteral("^(?:corpus/(\\d{1,9})|imported/(\\d{1,9})|live/([a-z]{1,32}))$"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch()) return std::nullopt;
    if (match.hasCaptured(1)) return TakeId::corpus(match.captured(1).toULongLong());
    if (match.hasCaptured(2)) return TakeId::imported(match.captured(2).toULongLong());
    return TakeId::live(match.captured(3));
}

} // namespace

analysis::Status writeProject(const ProjectState& state, const QString& file)
{
    QJsonObject root;
    root["format"] = kProjectFormatName;
    root["version"] = kProjectFormatVersion;
    root["corpus"] = state.corpus;
    QJsonArray imported;
    for (const auto& recipe : state.imported) {
        const QByteArray options =
            QByteArray::fromStdString(analysis::io::importOptionsToJson(recipe.options).dump(-1, ' ', false, json::error_handler_t::replace));
        imported.append(QJsonObject{{"path", recipe.path}, {"label", recipe.label}, {"options", QJsonDocument::fromJson(options).object()}});
    }
    root["imported"] = imported;
    root["parameters"] = QJsonDocument::fromJson(QByteArray::fromStdString(analysis::pipeline::toJson(state.parameters).dump())).object();
    root["takeA"] = state.takeA.toString();
    root["takeB"] = state.takeB.toString();
    root["time_s"] = state.timeSeconds;
    root["view"] = viewJson(state.view);

    const QByteArray text = QJsonDocument(root).toJson(QJsonDocument::Indented);
    return analysis::io::writeFileAtomically(std::filesystem::path(file.toStdString()),
                                             std::string_view(text.constData(), std::size_t(text.size())));
}

analysis::Result<ProjectState> readProject(const QString& file)
{
    // A regular file of at most 64 MB (a FIFO or device is refused, never waited on), read whole.
    auto text = analysis::io::readTextFile(std::filesystem::path(file.toStdString()), std::uintmax_t(kMaxProjectBytes));
    if (!text) return text.error();
    return parseProject(QByteArray::fromStdString(*text), file);
}

analysis::Result<ProjectState> parseProject(const QByteArray& text, const QString& sourceName)
{
    const std::string name = sourceName.toStdString();
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError)
        return parseError(name, lineOfOffset(text, error.offset), "expected JSON: " + error.errorString().toStdString());
    if (!document.isObject()) return parseError(name, 1, "expected a JSON object");
    const QJsonObject root = document.object();
    if (root["format"].toString() != kProjectFormatName)
        return parseError(name, lineOfKey(text, "format"), "expected \"format\": \"bunraku-project\"");
    const int version = root["version"].toInt();
    if (version != 1 && version != kProjectFormatVersion) return parseError(name, lineOfKey(text, "version"), "expected \"version\": 1 or 2");
    if (!root["corpus"].isString() || root["corpus"].toString().isEmpty())
        return parseError(name, lineOfKey(text, "corpus"), "expected \"corpus\": \"demo\" or a corpus folder");

    ProjectState state;
    state.corpus = root["corpus"].toString();
    const QJsonValue importedValue = root["imported"];
    if (!importedValue.isUndefined() && !importedValue.isArray()) return parseError(name, lineOfKey(text, "imported"), "expected \"imported\": [...]");
    if (importedValue.toArray().size() > kMaxImported) return parseError(name, lineOfKey(text, "imported"), "more than 10000 \"imported\" takes");
    const QJsonArray imported = importedValue.toArray();
    for (qsizetype i = 0; i < imported.size(); ++i) {
        const QJsonObject recipe = imported[i].toObject();
        if (!recipe["path"].isString() || recipe["path"].toString().isEmpty())
            return parseError(name, lineOfKey(text, "imported"), "expected \"path\" in every \"imported\" entry");
        ImportedTakeRecipe item{recipe["path"].toString(), recipe["label"].toString(), {}};
        // What the take was imported with (older projects: the defaults).
        if (recipe.contains("options")) {
            const std::string where = "imported[" + std::to_string(i) + "].options";
            if (!recipe["options"].isObject()) return parseError(name, lineOfKey(text, "options"), where + ": expected an object");
            const QByteArray options = QJsonDocument(recipe["options"].toObject()).toJson(QJsonDocument::Compact);
            auto read = analysis::io::importOptionsFromJson(json::parse(options.toStdString(), nullptr, false), name + ": " + where);
            if (!read) return read.error();
            item.options = std::move(read).value();
        }
        state.imported.push_back(std::move(item));
    }
    // The parameters: strictly typed and range-checked before anything uses them.
    json parameters = json::object();
    {
        auto whole = analysis::io::parseJsonText(text.toStdString(), name); // a number beyond a double (1e400) and the like
        if (!whole) return whole.error();
        if (whole->is_object() && whole->contains("parameters")) parameters = (*whole)["parameters"];
    }
    if (version == 1) parameters = upgradeVersion1(parameters);
    auto typed = analysis::pipeline::chainParametersFromJson(parameters, name);
    if (!typed) return typed.error();
    state.parameters = std::move(typed).value();

    for (auto [key, id] : {std::pair{"takeA", &state.takeA}, std::pair{"takeB", &state.takeB}}) {
        const QJsonValue value = root[key];
        const std::optional<TakeId> read = value.isUndefined() || value.isNull() ? TakeId()
                                           : value.isString()                    ? parseTakeId(value.toString())
                                                                                 : std::nullopt;
        if (!read) {
            const QString got = QString::fromUtf8(QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact).mid(1).chopped(1));
            return parseError(name, lineOfKey(text, key),
                              std::string("expected \"") + key + "\": a take id (corpus/N, imported/N or live/name), got " +
                                  got.left(80).toStdString());
        }
        *id = *read;
    }
    const QJsonValue time = root["time_s"];
    if (!time.isUndefined() && (!time.isDouble() || !std::isfinite(time.toDouble()) || time.toDouble() < 0.0 || time.toDouble() > 1e9))
        return parseError(name, lineOfKey(text, "time_s"), "expected \"time_s\": seconds in [0, 1e9]");
    state.timeSeconds = time.toDouble();
    const QJsonValue view = root["view"];
    if (!view.isUndefined() && !view.isObject()) return parseError(name, lineOfKey(text, "view"), "expected \"view\": {...}");
    const QJsonObject viewObject = view.toObject();
    for (const ViewRange& range : kViewRanges) {
        const QJsonValue value = viewObject[range.key];
        if (value.isUndefined()) continue;
        if (!value.isDouble() || !(value.toDouble() >= range.low && value.toDouble() <= range.high) ||
            (range.high > 1.5 && range.low == 0 && value.toDouble() != std::floor(value.toDouble())))
            return parseError(name, lineOfKey(text, range.key), std::string("expected \"view\".\"") + range.key + "\" in " + QString::number(range.low).toStdString() +
                                           ".." + QString::number(range.high).toStdString());
    }
    for (const char* key : {"part", "dof", "weightEmotion", "cellFunction", "cellEmotion"})
        if (viewObject.contains(key) && (!viewObject[key].isString() || viewObject[key].toString().size() > 256))
            return parseError(name, lineOfKey(text, key), std::string("expected \"view\".\"") + key + "\": a name of at most 256 characters");
    if (viewObject.contains("camera")) {
        // {"angle", "elevation", "distance", "target": [x, y, z], "fov"}: finite, in the ranges a
        // camera can take (render/camera.h).
        const QJsonObject camera = viewObject["camera"].toObject();
        const QJsonArray target = camera["target"].toArray();
        const auto inRange = [](const QJsonValue& value, double low, double high) {
            return value.isDouble() && value.toDouble() >= low && value.toDouble() <= high;
        };
        bool valid = viewObject["camera"].isObject() && inRange(camera["angle"], -3600.0, 3600.0) &&
                     inRange(camera["elevation"], -90.0, 90.0) && inRange(camera["distance"], 10.0, 5000.0) &&
                     (camera["fov"].isUndefined() || inRange(camera["fov"], 1.0, 170.0)) && target.size() == 3;
        for (const QJsonValue& coordinate : target) valid = valid && inRange(coordinate, -1e6, 1e6);
        if (!valid)
            return parseError(name, lineOfKey(text, "camera"), "expected \"view\".\"camera\": {\"angle\": deg, \"elevation\": deg in -90..90, "
                                       "\"distance\": cm in 10..5000, \"target\": [x, y, z] cm, \"fov\": deg in 1..170}");
    }
    if (viewObject.contains("show")) {
        // The 3D view's boxes: each key one of them, true or false.
        const QJsonValue shown = viewObject["show"];
        std::string keys;
        for (const auto& [key, member] : kShownObjectKeys) keys += std::string(keys.empty() ? "" : ", ") + key;
        if (!shown.isObject()) return parseError(name, lineOfKey(text, "show"), "expected \"view\".\"show\": {" + keys + ": true or false}");
        const QJsonObject values = shown.toObject();
        for (auto it = values.begin(); it != values.end(); ++it) {
            const bool known = std::any_of(std::begin(kShownObjectKeys), std::end(kShownObjectKeys),
                                           [&](const auto& entry) { return it.key() == QLatin1String(entry.first); });
            if (!known)
                return parseError(name, lineOfKey(text, "show"), "\"view\".\"show\": unknown object \"" + it.key().left(64).toStdString() + "\" (known: " + keys + ")");
            if (!it.value().isBool())
                return parseError(name, lineOfKey(text, "show"), "expected \"view\".\"show\".\"" + it.key().toStdString() + "\": true or false");
        }
    }
    if (viewObject.contains("clothParameters")) {
        // The 3D view's cloth settings: every key a cloth parameter in its range (one table).
        const QJsonValue cloth = viewObject["clothParameters"];
        if (!cloth.isObject()) return parseError(name, lineOfKey(text, "clothParameters"), "expected \"view\".\"clothParameters\": an object of cloth parameters");
        const QJsonObject values = cloth.toObject(); // one object: iterators of two temporaries never meet
        for (auto it = values.begin(); it != values.end(); ++it) {
            const auto& limits = analysis::clothParameterLimits();
            const auto limit = std::find_if(limits.begin(), limits.end(), [&](const analysis::ClothParameterLimit& l) { return it.key() == QLatin1String(l.name); });
            if (limit == limits.end())
                return parseError(name, lineOfKey(text, "clothParameters"), "\"view\".\"clothParameters\": unknown parameter \"" + it.key().left(64).toStdString() + "\"");
            if (!it.value().isDouble() || !(it.value().toDouble() >= limit->low && it.value().toDouble() <= limit->high))
                return parseError(name, lineOfKey(text, "clothParameters"), std::string("expected \"view\".\"clothParameters\".\"") + limit->name + "\" in " +
                                               QString::number(limit->low).toStdString() + ".." + QString::number(limit->high).toStdString());
        }
    }
    state.view = viewState(viewObject);
    return state;
}

} // namespace bunraku::app
