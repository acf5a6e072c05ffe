#pragma once
/// The project file (JSON, "bunraku-project" version 2): the corpus reference, the recipes of
/// derived takes (imported files, each with the options it was imported with:
/// analysis/io/import_options_json.h), the typed analysis parameters
/// (pipeline/parameters_json.h) and the view state. Live results are not stored: they are
/// recomputed from the parameters. Saves are atomic and durable (analysis/io/atomic_file.h).
/// Reading checks everything before using it: the parameters (types and ranges: `"maxScale": 2e9`
/// or a negative tau is refused naming the parameter, and nothing is allocated from a value),
/// the import options, take ids ("corpus/N", "imported/N", "live/name"), the time and the view's
/// values; a file over 64 MB or that is not a regular file (a FIFO, /dev/zero) is refused before
/// anything is read. Version 1 files (flat "panel.name" parameter keys) are read and converted.
///
/// {"format": "bunraku-project", "version": 2, "corpus": "demo" | "/abs/folder",
///  "imported": [{"path": ..., "label": ..., "options": {...}}], "parameters": {"normalise": {...}, ...},
///  "takeA": id, "takeB": id, "time_s": t, "view": {...}}

#include "analysis/core/result.h"
#include "analysis/io/take_reader.h"
#include "analysis/pipeline/stage_parameters.h"
#include "app/take_id.h"
#include "app/view_state.h"

#include <QByteArray>
#include <QString>
#include <QVector>

namespace bunraku::app {

struct ImportedTakeRecipe {
    QString path;
    QString label;
    /// What the take was imported with (analysis/io/import_options_json.h); the defaults for
    /// projects written before options were stored.
    analysis::io::ImportOptions options;
};

struct ProjectState {
    QString corpus; ///< "demo" or the corpus folder
    QVector<ImportedTakeRecipe> imported;
    analysis::pipeline::ChainParameters parameters;
    TakeId takeA;
    TakeId takeB;
    double timeSeconds = 0.0;
    ViewState view;
};

inline constexpr const char* kProjectFormatName = "bunraku-project";
inline constexpr int kProjectFormatVersion = 2;
/// The file name suffix of project files.
inline constexpr const char* kProjectSuffix = ".bunraku.json";

/// Writes `state` atomically (nothing replaced on failure); Io error naming the file.
analysis::Status writeProject(const ProjectState& state, const QString& file);
/// Reads a project; Parse errors name the file, the line and what was expected.
analysis::Result<ProjectState> readProject(const QString& file);
/// Parses project text; errors name `sourceName`.
analysis::Result<ProjectState> parseProject(const QByteArray& text, const QString& sourceName);

} // namespace bunraku::app
