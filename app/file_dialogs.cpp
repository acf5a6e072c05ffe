#include "app/file_dialogs.h"

#include "app/document.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

namespace bunraku::app {

namespace {

const QString kLastFolderKey = QStringLiteral("folders/last");

FileChooser& chooser()
{
    static FileChooser instance;
    return instance;
}

bool existingFolder(const QString& folder) { return !folder.isEmpty() && QFileInfo(folder).isDir(); }

} // namespace

QString purposeKey(FilePurpose purpose)
{
    switch (purpose) {
    case FilePurpose::Corpus: return QStringLiteral("folders/corpus");
    case FilePurpose::NewCorpus: return QStringLiteral("folders/newCorpus");
    case FilePurpose::Project: return QStringLiteral("folders/project");
    case FilePurpose::ImportTake: return QStringLiteral("folders/import");
    case FilePurpose::ExportTake: return QStringLiteral("folders/exportTake");
    case FilePurpose::Screenshot: return QStringLiteral("folders/screenshot");
    case FilePurpose::Report: return QStringLiteral("folders/report");
    case FilePurpose::Video: return QStringLiteral("folders/video");
    case FilePurpose::VideoFrames: return QStringLiteral("folders/videoFrames");
    }
    return kLastFolderKey;
}

QString rememberedPurposeFolder(FilePurpose purpose)
{
    const QString folder = QSettings().value(purposeKey(purpose)).toString();
    return existingFolder(folder) ? folder : QString();
}

QString workbenchFolder(FilePurpose purpose)
{
    QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (documents.isEmpty()) documents = QDir::homePath();
    const QString root = QDir(documents).filePath(QStringLiteral("Bunraku"));
    switch (purpose) {
    case FilePurpose::Corpus:
    case FilePurpose::NewCorpus: return QDir(root).filePath(QStringLiteral("corpora"));
    default: return root;
    }
}

QString unusedFolder(const QString& parent, const QString& name)
{
    const QDir dir(parent);
    QString candidate = dir.filePath(name);
    for (int n = 2; QFileInfo::exists(candidate); ++n) candidate = dir.filePath(name + QLatin1Char('-') + QString::number(n));
    return candidate;
}

QString rememberedFolder(FilePurpose purpose, const QString& projectFile)
{
    if (const QString folder = rememberedPurposeFolder(purpose); !folder.isEmpty()) return folder;
    if (const QString last = QSettings().value(kLastFolderKey).toString(); existingFolder(last)) return last;
    if (!projectFile.isEmpty() && existingFolder(QFileInfo(projectFile).absolutePath())) return QFileInfo(projectFile).absolutePath();
    return QDir::homePath();
}

void rememberFolder(FilePurpose purpose, const QString& path)
{
    if (path.isEmpty()) return;
    const QString folder = QFileInfo(path).absolutePath(); // a file's folder, or a folder's parent
    QSettings settings;
    settings.setValue(purposeKey(purpose), folder);
    settings.setValue(kLastFolderKey, folder);
}

QString suggestedFileName(const Document& document, const QString& suffix, NameParts parts)
{
    const QString source = document.corpusSource();
    QString name = source == QStringLiteral("demo") ? QStringLiteral("demo") : QFileInfo(source).fileName();
    // The take's short name, never a live result's recipe.
    const QString take = document.takeName(document.selectedId(parts == NameParts::CorpusAndTakeB ? TakeSlot::B : TakeSlot::A));
    if (!take.isEmpty() && parts != NameParts::Corpus) name += QLatin1Char('-') + take;
    // Letters, digits, '.', '_' and '-' only; runs of anything else become one '-'.
    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9._-]+"));
    name.replace(unsafe, QStringLiteral("-"));
    while (name.startsWith(QLatin1Char('-')) || name.startsWith(QLatin1Char('.'))) name.remove(0, 1);
    while (name.endsWith(QLatin1Char('-'))) name.chop(1);
    if (name.size() > 120) name.truncate(120);
    if (name.isEmpty()) name = QStringLiteral("bunraku");
    return name + suffix;
}

void setFileChooser(FileChooser replacement) { chooser() = std::move(replacement); }

QString chooseSaveFile(QWidget* parent, FilePurpose purpose, const QString& title, const QString& suggestedName,
                       const QString& filter, const QString& projectFile, QString* selectedFilter)
{
    const QString start = QDir(rememberedFolder(purpose, projectFile)).filePath(suggestedName);
    const QString file = chooser() ? chooser()(purpose, start) : QFileDialog::getSaveFileName(parent, title, start, filter, selectedFilter);
    rememberFolder(purpose, file);
    return file;
}

QString chooseOpenFile(QWidget* parent, FilePurpose purpose, const QString& title, const QString& filter, const QString& projectFile)
{
    const QString start = rememberedFolder(purpose, projectFile);
    const QString file = chooser() ? chooser()(purpose, start) : QFileDialog::getOpenFileName(parent, title, start, filter);
    rememberFolder(purpose, file);
    return file;
}

QString chooseFolder(QWidget* parent, FilePurpose purpose, const QString& title, const QString& projectFile)
{
    const QString start = rememberedFolder(purpose, projectFile);
    const QString folder = chooser() ? chooser()(purpose, start) : QFileDialog::getExistingDirectory(parent, title, start);
    rememberFolder(purpose, folder);
    return folder;
}

} // namespace bunraku::app
