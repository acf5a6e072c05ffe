#pragma once
/// The File menu, split by what it serves: corpora (CorpusController: open a folder or the demo,
/// make one from take files), takes imported into the document (ImportController), and the
/// project file (ProjectController: save, open, autosave, recovery and the unsaved-changes
/// prompt); exports are ExportController's. FileController owns the three and what they share:
/// how errors are told (a message box naming file, line and what was expected; with dialogs
/// off, lastError() and the status signal), the progress of long reads, the recent files, and
/// opening whatever a path names (a corpus folder, a project, a take file: dropped, recent or
/// given at launch). Nothing here throws.

#include "app/corpus_controller.h"
#include "app/import_controller.h"
#include "app/progress_task.h"
#include "app/project_controller.h"

#include "analysis/core/result.h"

#include <QObject>
#include <QScopedValueRollback>
#include <QString>
#include <QStringList>

#include <filesystem>
#include <functional>

class QMenu;
class QWidget;

namespace bunraku::app {

class Document;

/// The path a QString names (UTF-8), for the analysis's readers and writers.
inline std::filesystem::path toPath(const QString& file) { return std::filesystem::path(file.toStdString()); }

class FileController : public QObject {
    Q_OBJECT
public:
    FileController(Document& document, QWidget* window);
    ~FileController() override;

    CorpusController& corpora() { return *m_corpora; }
    ImportController& imports() { return *m_imports; }
    ProjectController& projects() { return *m_projects; }

    /// With dialogs off (tests, --screenshot) errors go to lastError() and the status signal
    /// instead of message boxes, and no question is asked.
    void setDialogsEnabled(bool enabled) { m_dialogs = enabled; }
    bool dialogsEnabled() const { return m_dialogs; }
    QString lastError() const { return m_lastError; }

    /// Opens a corpus folder, a project file or imports a take file, by what `path` is.
    bool openPath(const QString& path);
    /// Paths dropped on the window: when one of them would replace the document (a corpus
    /// folder or a project), asks to save unsaved changes first (nothing opens on Cancel).
    /// Returns how many were opened.
    int openDroppedPaths(const QStringList& paths);
    QStringList recentFiles() const;
    QMenu* recentMenu() const { return m_recentMenu; }

    /// How long work waits before its progress dialog shows, and an observer of its progress on
    /// the worker thread (tests hold the work there to press Cancel at a known point).
    void setProgressOptionsForTesting(ProgressTaskOptions options) { m_progressOptions = std::move(options); }

    // What the three controllers share.
    /// Tells a person why `title` failed: the status bar, lastError(), and a message box with
    /// dialogs on (unless a dialog that asked shows it: whileDialogAsks).
    void report(const QString& title, const analysis::Error& error);
    void clearLastError() { m_lastError.clear(); }
    /// An error that needs no message box (the status bar says it): lastError() and the status signal.
    void noteError(const QString& message)
    {
        m_lastError = message;
        emit statusMessage(message);
    }
    /// The window dialogs open over.
    QWidget* window() const { return m_window; }
    /// Runs `work` off the GUI thread, with a progress dialog over the window when dialogs are on.
    void runTask(const QString& label, const std::function<void(const analysis::RunControl&)>& work);
    void addRecent(const QString& path);
    /// Whether work run by runTask succeeded; if not, says so: `cancelled` in the status bar when
    /// the user stopped it, else report(failed, its error).
    bool succeeded(const analysis::Error* error, const QString& cancelled, const QString& failed);
    template <class T> bool succeeded(const analysis::Result<T>& result, const QString& cancelled, const QString& failed)
    {
        return succeeded(result ? nullptr : &result.error(), cancelled, failed);
    }
    /// While `asking` (a dialog) is open: progress dialogs open over it, and errors are shown by
    /// it rather than by a message box.
    template <class Work> auto whileDialogAsks(QWidget* asking, Work&& work)
    {
        const QScopedValueRollback<QWidget*> parent(m_window, asking);
        const QScopedValueRollback<bool> inDialog(m_errorsInDialog, true);
        return work();
    }

signals:
    void statusMessage(const QString& message);

private:
    void rebuildRecentMenu();

    QWidget* m_window;
    bool m_dialogs = true;
    bool m_errorsInDialog = false; ///< errors are shown by the dialog that asked, not a message box
    QString m_lastError;
    ProgressTaskOptions m_progressOptions;
    QMenu* m_recentMenu = nullptr;
    CorpusController* m_corpora = nullptr;
    ImportController* m_imports = nullptr;
    ProjectController* m_projects = nullptr;
};

} // namespace bunraku::app
