#include "app/launch_paths.h"

#include "app/document.h"
#include "app/file_controller.h"

#include <QFileInfo>

#include <vector>

namespace bunraku::app {

LaunchPath classifyLaunchPath(const QString& argument)
{
    const QFileInfo info(argument);
    if (info.isDir()) return {LaunchPathKind::Corpus, argument};
    if (info.fileName() == QStringLiteral("corpus.json")) return {LaunchPathKind::Corpus, info.path()};
    if (argument.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) return {LaunchPathKind::Project, argument};
    return {LaunchPathKind::Take, argument};
}

QString openLaunchPaths(FileController& files, const Document& document, const QStringList& arguments,
                        const std::function<void()>& beforeTakes)
{
    std::vector<LaunchPath> sources;
    std::vector<LaunchPath> takes;
    for (const QString& argument : arguments) {
        const LaunchPath path = classifyLaunchPath(argument);
        (path.kind == LaunchPathKind::Take ? takes : sources).push_back(path);
    }
    const auto showSomething = [&] {
        if (document.corpus().takes.empty()) files.corpora().openDemoCorpus();
    };
    if (sources.size() > 1) {
        showSomething();
        return QStringLiteral("open one corpus or project at a time (given: %1 and %2)").arg(sources[0].path, sources[1].path);
    }
    if (sources.empty()) {
        files.corpora().openDemoCorpus();
    } else {
        const LaunchPath& source = sources.front();
        const bool opened = source.kind == LaunchPathKind::Corpus ? files.corpora().openCorpusFolder(source.path) : files.projects().openProject(source.path);
        if (!opened) {
            showSomething();
            return files.lastError();
        }
    }
    if (beforeTakes) beforeTakes();
    QStringList paths;
    for (const LaunchPath& take : takes) paths << take.path;
    if (!paths.isEmpty() && files.imports().importTakeFiles(paths) < int(paths.size())) return files.lastError();
    return {};
}

} // namespace bunraku::app
