#pragma once
/// One autosave file per running workbench, so that two instances never overwrite or delete each
/// other's recovery file: `autosave-<pid>-<ms>-<n>.bunraku.json` in the autosave folder, guarded by
/// a lock file next to it that holds the process id (QLockFile). An autosave whose lock is stale
/// (its process is gone: a crash, a kill) or missing is an orphan: the next workbench to start
/// offers it for recovery. Adopting an orphan makes it this instance's autosave, kept until the
/// user saves or discards the recovered work.

#include <QDateTime>
#include <QLockFile>
#include <QString>
#include <QVector>

#include <memory>

namespace bunraku::app {

/// An autosave left by a workbench that is no longer running.
struct OrphanedAutosave {
    QString path;
    QDateTime saved;  ///< when it was last written
    QString summary;  ///< what it holds, for a person: corpus, imported takes, edited analysis parts
};

class AutosaveSession {
public:
    /// `folder`: where autosaves live (created when needed); empty: the application's local
    /// data folder (QStandardPaths::AppLocalDataLocation).
    explicit AutosaveSession(QString folder = {});
    ~AutosaveSession(); ///< releases the lock; the autosave file itself stays unless removed

    AutosaveSession(const AutosaveSession&) = delete;
    AutosaveSession& operator=(const AutosaveSession&) = delete;

    QString folder() const { return m_folder; }
    /// This instance's autosave file (its own, or the orphan it adopted).
    QString path() const { return m_path; }

    /// Orphaned autosaves in the folder, newest first (this instance's own never among them).
    QVector<OrphanedAutosave> orphans() const;
    /// Takes over an orphan: locks it and makes it this instance's autosave (the previous own
    /// file is removed). False when another instance holds it or it is gone.
    bool adopt(const QString& orphanPath);
    /// Removes an orphan the user does not want (its file and stale lock); false when it is held.
    bool discardOrphan(const QString& orphanPath);
    /// Removes this instance's autosave file (the work was saved or discarded); the lock stays.
    void removeOwn();

private:
    QString m_folder;
    QString m_path;
    std::unique_ptr<QLockFile> m_lock;
};

/// "demo corpus, 2 imported take(s), edited normalisation, gains" for a project file, or why it
/// cannot be read.
QString describeProjectFile(const QString& file);

} // namespace bunraku::app
