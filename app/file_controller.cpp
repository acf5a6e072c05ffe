#include "app/file_controller.h"

#include "app/corpus_controller.h"
#include "app/import_controller.h"
#include "app/project_controller.h"

#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

#include <algorithm>

namespace bunraku::app {
namespace {

constexpr int kRecentCount = 8;
const QString kRecentKey = QStringLiteral("files/recent");

} // namespace

FileController::FileController(Document& document, QWidget* window) : QObject(window), m_window(window)
{
    m_recentMenu = new QMenu(tr("Open &Recent"), window);
    // Corpora first: the project controller follows the corpora opened.
    m_corpora = new CorpusController(document, *this);
    m_imports = new ImportController(document, *this);
    m_projects = new ProjectController(document, *this);
    rebuildRecentMenu();
}

FileController::~FileController() = default;

void FileController::report(const QString& title, const analysis::Error& error)
{
    m_lastError = QString::fromStdString(error.message);
    emit statusMessage(title + QStringLiteral(": ") + m_lastError);
    if (m_dialogs && !m_errorsInDialog) QMessageBox::warning(m_window, title, m_lastError);
}

void FileController::runTask(const QString& label, const std::function<void(const analysis::RunControl&)>& work)
{
    runProgressTask(m_dialogs ? m_window : nullptr, label, work, m_progressOptions);
}

bool FileController::succeeded(const analysis::Error* error, const QString& cancelled, const QString& failed)
{
    if (!error) return true;
    if (error->code == analysis::ErrorCode::Cancelled) emit statusMessage(cancelled);
    else report(failed, *error);
    return false;
}

bool FileController::openPath(const QString& path)
{
    const QFileInfo info(path);
    if (info.isDir()) return m_corpora->openCorpusFolder(path);
    if (path.endsWith(QStringLiteral(".json"))) return m_projects->openProject(path);
    if (!info.exists()) {
        report(tr("Cannot open"), analysis::makeError(analysis::ErrorCode::NotFound, path.toStdString() + ": no such file or folder"));
        return false;
    }
    return m_imports->importTakeFile(path);
}

int FileController::openDroppedPaths(const QStringList& paths)
{
    const bool replaces = std::any_of(paths.begin(), paths.end(), [](const QString& path) {
        return QFileInfo(path).isDir() || path.endsWith(QStringLiteral(".json"));
    });
    if (replaces && !m_projects->maybeSave()) return 0;
    // Take files together (one dialog for several BVH files), the rest one by one.
    int opened = 0;
    QStringList takes;
    for (const QString& path : paths) {
        if (!QFileInfo(path).isDir() && !path.endsWith(QStringLiteral(".json")) && QFileInfo::exists(path)) takes << path;
        else opened += openPath(path) ? 1 : 0;
    }
    return opened + (takes.isEmpty() ? 0 : m_imports->importTakeFiles(takes));
}

QStringList FileController::recentFiles() const { return QSettings().value(kRecentKey).toStringList(); }

void FileController::addRecent(const QString& path)
{
    QStringList recent = recentFiles();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kRecentCount) recent.removeLast();
    QSettings().setValue(kRecentKey, recent);
    rebuildRecentMenu();
}

void FileController::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = recentFiles();
    for (const QString& path : recent) {
        m_recentMenu->addAction(path, this, [this, path] {
            if (m_projects->maybeSave()) openPath(path);
        });
    }
    m_recentMenu->setEnabled(!recent.isEmpty());
}

} // namespace bunraku::app
