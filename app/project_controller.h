#pragma once
/// The project file (app/project_file.h): save with an atomic write, open (the imported takes
/// read again off the GUI thread, live takes shown when recomputed), autosave once a minute,
/// recovery of a crashed workbench's autosave, and the unsaved-changes prompt. Errors are told
/// by the FileController.

#include "app/autosave_session.h"
#include "app/document.h"
#include "app/project_file.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <memory>

class QAction;

namespace bunraku::app {

class FileController;

class ProjectController : public QObject {
    Q_OBJECT
public:
    ProjectController(Document& document, FileController& files);

    /// The view state stored in projects, provided by the main window.
    void setViewStateHooks(std::function<ViewState()> save, std::function<void(const ViewState&)> restore);

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
    /// Offers every autosave left by a workbench that is no longer running (RecoveryDialog, with
    /// the time and content of each); asks only when dialogs are enabled.
    void offerRecovery();
    /// Asks to save unsaved changes; false when the user cancels.
    bool maybeSave();
    /// What the unsaved-changes question answers when dialogs are off; empty: no question is
    /// asked (the default). Tests set Save, Discard or Cancel to drive the real prompts.
    void setUnsavedAnswerForTesting(std::function<int()> answer) { m_unsavedAnswer = std::move(answer); }
    /// The project file last saved or opened; empty for a document that is not a project's.
    QString projectPath() const { return m_projectPath; }
    /// The live take ("live/...") an opened project showed in `slot` and that is still being
    /// recomputed: it is shown as soon as it is published. Empty when none is awaited.
    TakeId pendingLiveTake(TakeSlot slot) const { return m_pending[int(slot)]; }

    QAction* openProjectAction() const { return m_openProject; }
    QAction* saveProjectAction() const { return m_save; }
    QAction* saveProjectAsAction() const { return m_saveAs; }

private:
    ProjectState captureState() const;
    bool applyState(const ProjectState& state);
    bool applyStateNow(const ProjectState& state);
    /// Shows awaited live takes that have been published.
    void showPendingLiveTakes();

    Document& m_document;
    FileController& m_files;
    QString m_projectPath;
    TakeId m_pending[2];        ///< awaited live takes per slot (see pendingLiveTake)
    double m_pendingTime = 0.0; ///< the project's time, applied when an awaited take appears
    bool m_applying = false;    ///< inside applyState: selections are the project's own
    QStringList m_unreadTakes;  ///< the last opened project's imported takes that could not be read, with why
    QStringList m_unshownTakes; ///< its take A or B that is not there, with the take shown instead
    QTimer m_autosaveTimer;
    std::unique_ptr<AutosaveSession> m_autosave;
    std::function<int()> m_unsavedAnswer;
    std::function<ViewState()> m_saveView;
    std::function<void(const ViewState&)> m_restoreView;
    QAction* m_openProject = nullptr;
    QAction* m_save = nullptr;
    QAction* m_saveAs = nullptr;
};

} // namespace bunraku::app
