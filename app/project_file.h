#pragma once
/// The project file (JSON, "bunraku-project" version 1): the corpus reference, the recipes of
/// derived takes (imported files), the undoable parameters (edits) and the view state. Live
/// results are not stored: they are recomputed from the parameters. Saves are atomic (QSaveFile).
///
/// {"format": "bunraku-project", "version": 1, "corpus": "demo" | "/abs/folder",
///  "imported": [{"path": ..., "label": ...}], "parameters": {key: value},
///  "takeA": id, "takeB": id, "time_s": t, "view": {...}}

#include "analysis/core/result.h"

#include <QString>
#include <QVariantMap>
#include <QVector>

namespace bunraku::app {

struct ImportedTakeRecipe {
    QString path;
    QString label;
};

struct ProjectState {
    QString corpus; ///< "demo" or the corpus folder
    QVector<ImportedTakeRecipe> imported;
    QVariantMap parameters;
    QString takeA;
    QString takeB;
    double timeSeconds = 0.0;
    QVariantMap view;
};

inline constexpr const char* kProjectFormatName = "bunraku-project";
inline constexpr int kProjectFormatVersion = 1;
/// The file name suffix of project files.
inline constexpr const char* kProjectSuffix = ".bunraku.json";

/// Writes `state` atomically (nothing replaced on failure); Io error naming the file.
analysis::Status writeProject(const ProjectState& state, const QString& file);
/// Reads a project; Parse errors name the file, the line and what was expected.
analysis::Result<ProjectState> readProject(const QString& file);

} // namespace bunraku::app
