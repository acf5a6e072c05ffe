#include "app/project_file.h"

#include "app/parameters.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/import_options_json.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <filesystem>
#include <string_view>

namespace bunraku::app {
namespace {

using analysis::ErrorCode;
using analysis::makeError;
using analysis::parseError;

long lineOfOffset(const QByteArray& text, int offset)
{
    return 1 + long(text.left(offset).count('\n'));
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
        const QByteArray options = QByteArray::fromStdString(analysis::io::importOptionsToJson(recipe.options).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
        imported.append(QJsonObject{{"path", recipe.path}, {"label", recipe.label}, {"options", QJsonDocument::fromJson(options).object()}});
    }
    root["imported"] = imported;
    root["parameters"] = QJsonObject::fromVariantMap(state.parameters);
    root["takeA"] = state.takeA;
    root["takeB"] = state.takeB;
    root["time_s"] = state.timeSeconds;
    root["view"] = QJsonObject::fromVariantMap(state.view);

    const QByteArray text = QJsonDocument(root).toJson(QJsonDocument::Indented);
    return analysis::io::writeFileAtomically(std::filesystem::path(file.toStdString()),
                                             std::string_view(text.constData(), std::size_t(text.size())));
}

analysis::Result<ProjectState> readProject(const QString& file)
{
    auto text = analysis::io::readTextFile(std::filesystem::path(file.toStdString()), analysis::io::kDocumentLimitBytes);
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
        return parseError(name, 0, "expected \"format\": \"bunraku-project\"");
    if (root["version"].toInt() != kProjectFormatVersion)
        return parseError(name, 0, "expected \"version\": 1");
    if (!root["corpus"].isString() || root["corpus"].toString().isEmpty())
        return parseError(name, 0, "expected \"corpus\": \"demo\" or a corpus folder");

    ProjectState state;
    state.corpus = root["corpus"].toString();
    const QJsonArray imported = root["imported"].toArray();
    for (qsizetype i = 0; i < imported.size(); ++i) {
        const QJsonObject recipe = imported[i].toObject();
        if (!recipe["path"].isString()) return parseError(name, 0, "expected \"path\" in every \"imported\" entry");
        ImportedTakeRecipe item{recipe["path"].toString(), recipe["label"].toString(), {}};
        if (recipe.contains("options")) {
            const QByteArray options = QJsonDocument(recipe["options"].toObject()).toJson(QJsonDocument::Compact);
            const nlohmann::json parsed = nlohmann::json::parse(options.toStdString(), nullptr, false);
            auto read = analysis::io::importOptionsFromJson(parsed, name + ": imported[" + std::to_string(i) + "].options");
            if (!recipe["options"].isObject() || !read)
                return read ? parseError(name, 0, "imported[" + std::to_string(i) + "].options: expected an object") : read.error();
            item.options = std::move(read).value();
        }
        state.imported.push_back(std::move(item));
    }
    const QVariantMap stored = root["parameters"].toObject().toVariantMap();
    for (auto it = stored.begin(); it != stored.end(); ++it) {
        QVariant value = it.value();
        const QVariant fallback = parameters::defaultValue(it.key());
        // JSON numbers come back as doubles: give each parameter its declared type again.
        if (fallback.isValid() && value.metaType() != fallback.metaType() && value.canConvert(fallback.metaType()))
            value.convert(fallback.metaType());
        state.parameters.insert(it.key(), value);
    }
    state.takeA = root["takeA"].toString();
    state.takeB = root["takeB"].toString();
    state.timeSeconds = root["time_s"].toDouble();
    state.view = root["view"].toObject().toVariantMap();
    return state;
}

} // namespace bunraku::app
