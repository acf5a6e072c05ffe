#include "app/project_controller.h"

#include "app/corpus_controller.h"
#include "app/document.h"
#include "app/file_controller.h"
#include "app/file_dialogs.h"
#include "app/recovery_dialog.h"

#include "analysis/io/take_reader.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace bunraku::app {
ProjectController::ProjectController(Document& document, FileController& files)
    : QObject(&files), m_document(document), m_files(files), m_autosave(std::make_unique<AutosaveSession>())
{
    connect(&document, &Document::derivedTakesChanged, this, &ProjectController::showPendingLiveTakes);
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (!m_applying) m_pending[int(slot)] = {}; // the user chose another take meanwhile
    });
    connect(&files.corpora(), &CorpusController::corpusOpened, this, [this] { m_projectPath.clear(); });
    m_openProject = new QAction(tr("Open &Project..."), this);
    m_openProject->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    m_save = new QAction(tr("&Save Project"), this);
    m_save->setShortcut(QKeySequence::Save);
    m_saveAs = new QAction(tr("Save Project &As..."), this);
    m_saveAs->setShortcut(QKeySequence::SaveAs);
    connect(m_openProject, &QAction::triggered, this, [this] {
        if (!maybeSave()) return;
        const QString file = chooseOpenFile(m_files.window(), FilePurpose::Project, tr("Open project"), tr("Bunraku projects (*.json)"), m_projectPath);
        if (!file.isEmpty()) openProject(file);
    });
    connect(m_save, &QAction::triggered, this, [this] {
        if (m_projectPath.isEmpty())
            m_saveAs->trigger();
        else
            saveProject(m_projectPath);
    });
    connect(m_saveAs, &QAction::triggered, this, [this] {
        // The project's own name when it has one, else the corpus's.
        const QString name = m_projectPath.isEmpty() ? suggestedFileName(m_document, kProjectSuffix, NameParts::Corpus)
                                                     : QFileInfo(m_projectPath).fileName();
        QString file = chooseSaveFile(m_files.window(), FilePurpose::Project, tr("Save project"), name, tr("Bunraku projects (*.json)"),
                                      m_projectPath);
        if (file.isEmpty()) return;
        if (!file.endsWith(QStringLiteral(".json"))) file += kProjectSuffix;
        saveProject(file);
    });

    m_autosaveTimer.setInterval(60 * 1000);
    connect(&m_autosaveTimer, &QTimer::timeout, this, &ProjectController::autosave);
    m_autosaveTimer.start();
}

void ProjectController::setViewStateHooks(std::function<ViewState()> save, std::function<void(const ViewState&)> restore)
{
    m_saveView = std::move(save);
    m_restoreView = std::move(restore);
}

ProjectState ProjectController::captureState() const
{
    ProjectState state;
    state.corpus = m_document.corpusSource();
    std::vector<TakeId> importedIds;
    for (const auto& derived : m_document.derivedTakes())
        if (!derived.sourcePath.isEmpty()) {
            importedIds.push_back(derived.id);
            state.imported.push_back({derived.sourcePath, derived.label,
                                      derived.importOptions ? *derived.importOptions : analysis::io::ImportOptions{}});
        }
    state.parameters = m_document.parameters();
    // In the file an imported take is named by its place in "imported" (imported/1 the first),
    // not by the serial number it has in this session.
    const auto inFile = [&importedIds](const TakeId& id) {
        if (!id.isImported()) return id;
        const auto found = std::find(importedIds.begin(), importedIds.end(), id);
        return found == importedIds.end() ? TakeId() : TakeId::imported(std::size_t(found - importedIds.begin()) + 1);
    };
    state.takeA = inFile(m_document.selectedId(TakeSlot::A));
    state.takeB = inFile(m_document.selectedId(TakeSlot::B));
    state.timeSeconds = m_document.currentTime();
    if (m_saveView) state.view = m_saveView();
    return state;
}

bool ProjectController::applyState(const ProjectState& state)
{
    m_pending[0] = {};
    m_pending[1] = {};
    m_applying = true;
    const bool applied = applyStateNow(state);
    m_applying = false;
    return applied;
}

void ProjectController::showPendingLiveTakes()
{
    bool shown = false;
    for (int slot = 0; slot < 2; ++slot) {
        if (m_pending[slot].isEmpty() || !m_document.take(m_pending[slot])) continue;
        const TakeId id = m_pending[slot];
        m_pending[slot] = {};
        m_applying = true; // the project's own selection: do not drop the other pending slot
        m_document.selectTake(TakeSlot(slot), id);
        m_applying = false;
        shown = true;
    }
    if (shown) m_document.setCurrentTime(m_pendingTime);
}

bool ProjectController::applyStateNow(const ProjectState& state)
{
    // The project's imported takes are read first, off the GUI thread behind a progress dialog
    // (an hour-long take among them): Cancel leaves the document as it was.
    std::vector<analysis::Result<analysis::Take>> takes;
    bool cancelled = false;
    m_unreadTakes.clear();
    m_unshownTakes.clear();
    if (!state.imported.empty())
        m_files.runTask(tr("Reading the project's %n imported take(s)...", nullptr, int(state.imported.size())),
                        [&](const analysis::RunControl& control) {
                            const double share = 1.0 / double(state.imported.size());
                            for (qsizetype i = 0; i < state.imported.size() && !cancelled; ++i) {
                                // The options the take was imported with: the same joint map, axes, units and rate.
                                const auto& recipe = state.imported[i];
                                takes.push_back(analysis::io::readTakeFile(toPath(recipe.path), recipe.options,
                                                                           control.step(share * double(i), share * double(i + 1))));
                                cancelled = control.cancelled();
                            }
                        });
    if (cancelled) {
        emit m_files.statusMessage(tr("Opening the project cancelled; nothing was changed"));
        return false;
    }
    const bool opened = state.corpus == QStringLiteral("demo") ? m_files.corpora().openDemoCorpus()
                                                               : m_files.corpora().openCorpusFolder(state.corpus);
    if (!opened) return false;
    std::vector<DerivedTake> imported;
    // The ids the project's imported takes get in this session, by their place in the file (none
    // for a take that could not be read): "imported/N" in the file is recipeIds[N - 1].
    std::vector<TakeId> recipeIds(std::size_t(state.imported.size()));
    for (qsizetype i = 0; i < state.imported.size(); ++i) {
        const auto& recipe = state.imported[i];
        auto& take = takes[std::size_t(i)];
        if (!take) {
            m_unreadTakes.append(tr("'%1' (%2)").arg(recipe.label, QString::fromStdString(take.error().message)));
            m_files.report(tr("Cannot re-import the take '%1' of the project").arg(recipe.label), take.error());
            continue;
        }
        recipeIds[std::size_t(i)] = m_document.nextImportedId();
        imported.push_back(DerivedTake{recipeIds[std::size_t(i)], recipe.label,
                                       std::make_shared<const analysis::Take>(std::move(take).value()), recipe.path, TakeId(),
                                       std::make_shared<const analysis::io::ImportOptions>(recipe.options), nullptr, {}});
    }
    m_document.restoreProject(std::move(imported), state.parameters);
    // Live results are recomputed after opening: a live take shown as A or B is awaited and
    // shown when published (showPendingLiveTakes); until then A keeps the corpus's first take.
    const TakeId saved[2] = {state.takeA, state.takeB};
    for (int slot = 0; slot < 2; ++slot) {
        TakeId id = saved[slot];
        if (id.isImported()) id = id.index() >= 1 && id.index() <= recipeIds.size() ? recipeIds[id.index() - 1] : TakeId();
        if (id.isLive() && !m_document.take(id)) {
            m_pending[slot] = id;
            // Until it is recomputed A shows a take of the cell the live results were computed
            // for (they follow take A's cell), else the take the corpus opened with.
            if (slot == 0 && state.view.cellFunction && state.view.cellEmotion) {
                const auto& corpusTakes = m_document.corpus().takes;
                const std::string function = state.view.cellFunction->toStdString(), emotion = state.view.cellEmotion->toStdString();
                const auto inCell = std::find_if(corpusTakes.begin(), corpusTakes.end(), [&](const analysis::Take& take) {
                    return take.labels.function == function && take.labels.emotion == emotion;
                });
                if (inCell != corpusTakes.end())
                    m_document.selectTake(TakeSlot::A, TakeId::corpus(std::size_t(inCell - corpusTakes.begin())));
            }
            continue;
        }
        m_document.selectTake(TakeSlot(slot), id);
        // A take the project names that is not here (a corpus changed since, an import that
        // could not be read, an edited file): said, with the take shown instead.
        if (!saved[slot].isEmpty() && (id.isEmpty() || m_document.selectedId(TakeSlot(slot)) != id)) {
            const QString shown = m_document.selectedId(TakeSlot(slot)).isEmpty()
                                      ? tr("no take")
                                      : m_document.takeLabel(m_document.selectedId(TakeSlot(slot)));
            m_unshownTakes.append(tr("its take %1, %2, is not in it (%1 shows %3)")
                                      .arg(slot == 0 ? QStringLiteral("A") : QStringLiteral("B"), saved[slot].toString(), shown));
        }
    }
    m_pendingTime = state.timeSeconds;
    m_document.setCurrentTime(state.timeSeconds);
    if (m_restoreView) m_restoreView(state.view);
    return true;
}

bool ProjectController::saveProject(const QString& file)
{
    if (const auto status = writeProject(captureState(), file); !status) {
        m_files.report(tr("Cannot save the project"), status.error());
        return false;
    }
    m_projectPath = file;
    m_document.undoStack()->setClean();
    m_autosave->removeOwn();
    m_files.addRecent(file);
    emit m_files.statusMessage(tr("Saved %1").arg(file));
    return true;
}

bool ProjectController::openProject(const QString& file)
{
    auto state = readProject(file);
    if (!state) {
        m_files.report(tr("Cannot open the project"), state.error());
        return false;
    }
    if (!applyState(state.value())) return false;
    m_projectPath = file;
    m_files.addRecent(file);
    if (m_unreadTakes.isEmpty() && m_unshownTakes.isEmpty()) {
        emit m_files.statusMessage(tr("Opened project %1").arg(file));
    } else {
        // The last word in the status bar: which takes are missing and why (each unread one was
        // reported too), and a take A or B the project names that is not there.
        QStringList said;
        if (!m_unreadTakes.isEmpty())
            said.append(tr("without %n of its imported take(s), which could not be read: %1", nullptr, int(m_unreadTakes.size()))
                            .arg(m_unreadTakes.join(QStringLiteral("; "))));
        said.append(m_unshownTakes);
        m_files.noteError(tr("Opened project %1 %2").arg(file, said.join(QStringLiteral("; "))));
    }
    return true;
}

QString ProjectController::autosavePath() const { return m_autosave->path(); }

bool ProjectController::autosave()
{
    if (m_document.undoStack()->isClean()) return false;
    QDir().mkpath(QFileInfo(autosavePath()).absolutePath());
    return bool(writeProject(captureState(), autosavePath()));
}

bool ProjectController::recoverAutosave(const QString& file)
{
    if (!m_autosave->adopt(file)) {
        m_files.report(tr("Cannot recover"), analysis::makeError(analysis::ErrorCode::Io,
                                                         file.toStdString() + ": another workbench is using it, or it is gone"));
        return false;
    }
    if (!openProject(file)) return false;
    m_projectPath.clear(); // the user chooses where to save it
    // Recovered work is unsaved work: marked in the title, asked about when quitting, and its
    // autosave kept until it is saved or discarded.
    m_document.undoStack()->resetClean();
    return true;
}

void ProjectController::offerRecovery()
{
    if (!m_files.dialogsEnabled()) return;
    const QVector<OrphanedAutosave> orphans = m_autosave->orphans();
    if (orphans.isEmpty()) return;
    RecoveryDialog dialog(orphans, [this](const QString& path) { return m_autosave->discardOrphan(path); }, m_files.window());
    if (dialog.exec() == QDialog::Accepted && !dialog.chosen().isEmpty()) recoverAutosave(dialog.chosen());
}

bool ProjectController::maybeSave()
{
    if (m_document.undoStack()->isClean()) return true;
    if (!m_files.dialogsEnabled() && !m_unsavedAnswer) return true;
    const int answer = !m_files.dialogsEnabled() ? m_unsavedAnswer()
                                  : QMessageBox::warning(m_files.window(), tr("Unsaved changes"),
                                                         tr("The project has unsaved changes. Save them?"),
                                                         QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                                         QMessageBox::Save);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save) {
        m_save->trigger();
        return m_document.undoStack()->isClean();
    }
    m_autosave->removeOwn();
    return true;
}

} // namespace bunraku::app
