#include "app/project_file.h"

#include "app/parameters.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

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
    for (const auto& recipe : state.imported) imported.append(QJsonObject{{"path", recipe.path}, {"label", recipe.label}});
    root["imported"] = imported;
    root["parameters"] = QJsonObject::fromVariantMap(state.parameters);
    root["takeA"] = state.takeA;
    root["takeB"] = state.takeB;
    root["time_s"] = state.timeSeconds;
    root["view"] = QJsonObject::fromVariantMap(state.view);

    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly))
        return makeError(ErrorCode::Io, file.toStdString() + ": cannot write: " + out.errorString().toStdString());
    out.write(QJsonDocument(root).toJson(QJsonDocument::Indented));
    if (!out.commit())
        return makeError(ErrorCode::Io, file.toStdString() + ": cannot write: " + out.errorString().toStdString());
    return analysis::okStatus();
}

analysis::Result<ProjectState> readProject(const QString& file)
{
    const std::string name = file.toStdString();
    QFile in(file);
    if (!in.open(QIODevice::ReadOnly)) return makeError(ErrorCode::Io, name + ": cannot open: " + in.errorString().toStdString());
    const QByteArray text = in.readAll();
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
    for (const auto& value : root["imported"].toArray()) {
        const QJsonObject recipe = value.toObject();
        if (!recipe["path"].isString()) return parseError(name, 0, "expected \"path\" in every \"imported\" entry");
        state.imported.push_back({recipe["path"].toString(), recipe["label"].toString()});
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
