#include "app/autosave_session.h"

#include "app/document.h"
#include "app/project_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QObject>
#include <QStandardPaths>

#include <algorithm>

namespace bunraku::app {
namespace {

const QString kPrefix = QStringLiteral("autosave");
const QString kLockSuffix = QStringLiteral(".lock");

QString lockPathOf(const QString& autosave) { return autosave + kLockSuffix; }

/// A lock that only a dead owner makes stale (never its age: a workbench runs for days).
std::unique_ptr<QLockFile> tryLocking(const QString& autosave)
{
    auto lock = std::make_unique<QLockFile>(lockPathOf(autosave));
    lock->setStaleLockTime(0);
    if (!lock->tryLock(0)) return nullptr;
    return lock;
}

} // namespace

AutosaveSession::AutosaveSession(QString folder) : m_folder(std::move(folder))
{
    if (m_folder.isEmpty()) m_folder = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
    QDir().mkpath(m_folder);
    static int counter = 0; // several windows of one process each have their own
    const QString name = QStringLiteral("%1-%2-%3-%4%5")
                             .arg(kPrefix)
                             .arg(QCoreApplication::applicationPid())
                             .arg(QDateTime::currentMSecsSinceEpoch())
                             .arg(counter++)
                             .arg(QString::fromLatin1(kProjectSuffix));
    m_path = QDir(m_folder).filePath(name);
    m_lock = tryLocking(m_path);
    // Locks of dead instances that never wrote an autosave: taking one removes it on release.
    const QDir dir(m_folder);
    for (const QString& lock : dir.entryList({kPrefix + QStringLiteral("*") + kLockSuffix}, QDir::Files | QDir::Hidden)) {
        const QString autosave = dir.filePath(lock.chopped(kLockSuffix.size()));
        if (autosave != m_path && !QFileInfo::exists(autosave)) tryLocking(autosave);
    }
}

AutosaveSession::~AutosaveSession() = default;

QVector<OrphanedAutosave> AutosaveSession::orphans() const
{
    QVector<OrphanedAutosave> found;
    const QDir dir(m_folder);
    const QStringList names =
        dir.entryList({kPrefix + QStringLiteral("*") + QString::fromLatin1(kProjectSuffix)}, QDir::Files | QDir::Hidden);
    for (const QString& name : names) {
        const QString path = dir.filePath(name);
        if (path == m_path) continue;
        // Locked by a running instance: its own autosave, not an orphan. Probing takes the
        // lock of a dead owner over, and releases it again at once.
        if (!tryLocking(path)) continue;
        found.push_back({path, QFileInfo(path).lastModified(), describeProjectFile(path)});
    }
    std::sort(found.begin(), found.end(), [](const OrphanedAutosave& a, const OrphanedAutosave& b) { return a.saved > b.saved; });
    return found;
}

bool AutosaveSession::adopt(const QString& orphanPath)
{
    if (orphanPath == m_path) return true;
    if (!QFileInfo::exists(orphanPath)) return false;
    auto lock = tryLocking(orphanPath);
    if (!lock) return false;
    removeOwn();
    m_lock = std::move(lock); // releases (and removes) the lock of the previous own file
    m_path = orphanPath;
    return true;
}

bool AutosaveSession::discardOrphan(const QString& orphanPath)
{
    if (orphanPath == m_path) return false;
    auto lock = tryLocking(orphanPath);
    if (!lock) return false;
    QFile::remove(orphanPath);
    return true; // the lock file goes with `lock`
}

void AutosaveSession::removeOwn() { QFile::remove(m_path); }

QString describeProjectFile(const QString& file)
{
    const auto state = readProject(file);
    if (!state) return QObject::tr("unreadable: %1").arg(QString::fromStdString(state.error().message));
    const QString corpus = state->corpus == QStringLiteral("demo") ? QObject::tr("demo corpus")
                                                                   : QObject::tr("corpus %1").arg(state->corpus);
    QStringList parts{corpus};
    if (!state->imported.isEmpty()) parts << QObject::tr("%n imported take(s)", nullptr, int(state->imported.size()));
    // Which parts of the analysis were edited (against the defaults).
    const ParameterSections sections = changedSections(state->parameters, AnalysisParameters{});
    const std::pair<ParameterSection, const char*> names[] = {
        {kPreprocessSection, "preprocessing"}, {kNormaliseSection, "normalisation"}, {kDecomposeSection, "decomposition"},
        {kFluctuationSection, "fluctuations"}, {kAxisSection, "motion axis"},     {kWeightSection, "emotion weight"},
        {kWarpSection, "warp"},                {kGainSection, "gains"},           {kBoundarySection, "phrase boundaries"}};
    QStringList edited;
    for (const auto& [section, name] : names)
        if (sections.testFlag(section)) edited << QObject::tr(name);
    if (!edited.isEmpty()) parts << QObject::tr("edited %1").arg(edited.join(QStringLiteral(", ")));
    return parts.join(QStringLiteral(", "));
}

} // namespace bunraku::app
