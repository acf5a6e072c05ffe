#pragma once
/// The paths given to `bunraku-workbench` on its command line, which is also how a desktop
/// passes the files of a double click (Exec=bunraku-workbench %F): a corpus (its folder or its
/// corpus.json manifest), a project (*.bunraku.json, or any other .json) or take files (CSV,
/// BVH, FASTRAK).

#include <QString>
#include <QStringList>

#include <functional>

namespace bunraku::app {

class FileController;
class Document;

enum class LaunchPathKind {
    Corpus,  ///< a corpus folder, or its corpus.json manifest (the folder opens)
    Project, ///< a project file
    Take,    ///< a take file, imported over the corpus
};

struct LaunchPath {
    LaunchPathKind kind = LaunchPathKind::Take;
    QString path; ///< for a corpus, its folder
};

/// What `argument` names (no file is read; a missing path is a take, and importing it fails
/// naming it).
LaunchPath classifyLaunchPath(const QString& argument);

/// Opens `arguments`: the corpus or project first (at most one), then every take file imported
/// over it - over the demo corpus when no corpus or project is named - all at once
/// (FileController::importTakeFiles: one dialog for several BVH files). `beforeTakes` runs
/// between the two (the workbench shows its window there, so the dialog opens over it). No
/// arguments: the demo corpus. Stops at the first failure and returns its message (empty on
/// success); the window then still shows a corpus (the demo corpus when nothing else opened).
QString openLaunchPaths(FileController& files, const Document& document, const QStringList& arguments,
                        const std::function<void()>& beforeTakes = {});

} // namespace bunraku::app
