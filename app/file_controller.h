#pragma once
/// The File menu's actions: open a corpus (folder or the demo), import takes (CSV, BVH with a
/// joint map dialog, FASTRAK), recent files, drag-and-drop, export of the current take (CSV,
/// BVH), screenshots of any view, and the project file with atomic saves, autosave, recovery
/// and the unsaved-changes prompt. Errors are shown as messages naming file, line and what was
/// expected; nothing here throws.

#include "app/autosave_session.h"
#include "app/document.h"
#include "app/progress_task.h"
#include "app/project_file.h"

#include "analysis/core/result.h"
#include "analysis/io/corpus_builder.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <functional>
#include <memory>

class QAction;
class QMenu;
class QWidget;

namespace bunraku::app {

class Document;

class FileController : public QObject {
    Q_OBJECT
public:
    FileController(Document& document, QWidget* window);

    /// With dialogs off (tests, --screenshot) errors go to lastError() and the status signal
    /// instead of message boxes, and no question is asked.
    void setDialogsEnabled(bool enabled) { m_dialogs = enabled; }
    QString lastError() const { return m_lastError; }

    /// The view state stored in projects, provided by the main window.
    void setViewStateHooks(std::function<ViewState()> save, std::function<void(const ViewState&)> restore);

    // Operations without dialogs (each returns false and reports the error on failure).
    bool openDemoCorpus();
    bool openCorpusFolder(const QString& folder);
    /// Opens a corpus folder, a project file or imports a take file, by what `path` is.
    bool openPath(const QString& path);
    /// Paths dropped on the window: when one of them would replace the document (a corpus
    /// folder or a project), asks to save unsaved changes first (nothing opens on Cancel).
    /// Returns how many were opened.
    int openDroppedPaths(const QStringList& paths);
    /// Imports a take; `jointMap` ("head=Head,...", may be empty) applies to BVH files (with
    /// dialogs and no map, the joint map dialog asks first, from the file's first pose). With
    /// dialogs the file is read and imported off the GUI thread behind a progress dialog that
    /// can cancel it; a cancelled import changes nothing.
    bool importTakeFile(const QString& file, const QString& jointMap = {});
    /// Imports several take files: with dialogs and more than one BVH file, one dialog
    /// (import_takes_dialog.h) chooses the joints, side and units of all of them first. Stops at
    /// the first failure (lastError); returns how many were imported.
    int importTakeFiles(const QStringList& files);
    /// Builds a corpus from take files (analysis/io/corpus_builder.h, as `bunraku corpus`),
    /// writes it to `folder` and opens it. With dialogs the work runs off the GUI thread behind a
    /// progress dialog that can cancel it; the notes (rates, neutral emotion) go to the status bar.
    bool createCorpusFromFiles(const std::vector<analysis::io::CorpusSource>& sources,
                               const analysis::io::CorpusBuildOptions& options, const QString& folder);
    /// File > New Corpus from Files: the dialog, then createCorpusFromFiles. `inputs` preset it.
    /// When the corpus cannot be made the dialog stays open with everything the user entered and
    /// the error (the row of the file it names selected). The corpus made is remembered as the
    /// folder of corpora (file_dialogs.h), where the next new corpus is suggested.
    void chooseFilesForCorpus(const QStringList& inputs = {});
    bool saveProject(const QString& file);
    bool openProject(const QString& file);
    /// Writes this instance's autosave file now (when there are unsaved changes).
    bool autosave();
    /// This instance's autosave file (one per running workbench, see autosave_session.h).
    QString autosavePath() const;
    AutosaveSession& autosaveSession() { return *m_autosave; }
    /// Opens an orphaned autosave as unsaved work: it becomes this instance's autosave, the
    /// title is marked modified, quitting asks to save, and the file is kept until the work is
    /// saved or discarded.
    bool recoverAutosave(const QString& file);
    /// What the unsaved-changes question answers when dialogs are off; empty: no question is
    /// asked (the default). Tests set Save, Discard or Cancel to drive the real prompts.
    void setUnsavedAnswerForTesting(std::function<int()> answer) { m_unsavedAnswer = std::move(answer); }
    /// How long work waits before its progress dialog shows, and an observer of its progress on
    /// the worker thread (tests hold the work there to press Cancel at a known point).
    void setProgressOptionsForTesting(ProgressTaskOptions options) { m_progressOptions = std::move(options); }
    QString projectPath() const { return m_projectPath; }
    /// The live take ("live/...") an opened project showed in `slot` and that is still being
    /// recomputed: it is shown as soon as it is published. Empty when none is awaited.
    QString pendingLiveTake(TakeSlot slot) const { return m_pending[int(slot)]; }
    /// Asks to save unsaved changes; false when the user cancels.
    bool maybeSave();
    QStringList recentFiles() const;

    QAction* openCorpusAction() const { return m_openCorpus; }
    QAction* openDemoAction() const { return m_openDemo; }
    QAction* newCorpusAction() const { return m_newCorpus; }
    QAction* importAction() const { return m_import; }
    QAction* openProjectAction() const { return m_openProject; }
    QAction* saveProjectAction() const { return m_save; }
    QAction* saveProjectAsAction() const { return m_saveAs; }
    QMenu* recentMenu() const { return m_recentMenu; }

    /// Offers every autosave left by a workbench that is no longer running (RecoveryDialog, with
    /// the time and content of each); asks only when dialogs are enabled.
    void offerRecovery();

signals:
    void statusMessage(const QString& message);

private:
    void report(const QString& title, const analysis::Error& error);
    /// importTakeFile, with the BVH options `preset` chosen in a dialog for several files (no
    /// joint dialog then).
    bool importTake(const QString& file, const std::optional<analysis::io::BvhImportOptions>& preset, const QString& jointMap = {});
    void addRecent(const QString& path);
    void rebuildRecentMenu();
    ProjectState captureState() const;
    bool applyState(const ProjectState& state);
    bool applyStateNow(const ProjectState& state);
    /// Shows awaited live takes that have been published.
    void showPendingLiveTakes();
    void chooseAndImport();

    Document& m_document;
    QWidget* m_window;
    bool m_dialogs = true;
    QString m_lastError;
    QString m_projectPath;
    QString m_pending[2];       ///< awaited live takes per slot (see pendingLiveTake)
    double m_pendingTime = 0.0; ///< the project's time, applied when an awaited take appears
    bool m_applying = false;    ///< inside applyState: selections are the project's own
    bool m_errorsInDialog = false; ///< errors are shown by the dialog that asked, not a message box
    QStringList m_unreadTakes;     ///< the last opened project's imported takes that could not be read, with why
    QTimer m_autosaveTimer;
    std::unique_ptr<AutosaveSession> m_autosave;
    std::function<int()> m_unsavedAnswer;
    ProgressTaskOptions m_progressOptions;
    std::function<ViewState()> m_saveView;
    std::function<void(const ViewState&)> m_restoreView;
    QAction* m_openCorpus = nullptr;
    QAction* m_openDemo = nullptr;
    QAction* m_newCorpus = nullptr;
    QAction* m_import = nullptr;
    QAction* m_openProject = nullptr;
    QAction* m_save = nullptr;
    QAction* m_saveAs = nullptr;
    QMenu* m_recentMenu = nullptr;
};

} // namespace bunraku::app
