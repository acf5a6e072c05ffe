#include "app/file_controller.h"

#include "app/commands.h"
#include "app/document.h"
#include "app/file_dialogs.h"
#include "app/import_takes_dialog.h"
#include "app/joint_map_dialog.h"
#include "app/new_corpus_dialog.h"
#include "app/progress_task.h"
#include "app/recovery_dialog.h"

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QScopedValueRollback>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>
#include <filesystem>

namespace bunraku::app {
namespace {

constexpr int kRecentCount = 8;
const QString kRecentKey = QStringLiteral("files/recent");

std::filesystem::path toPath(const QString& file) { return std::filesystem::path(file.toStdString()); }

} // namespace

FileController::FileController(Document& document, QWidget* window)
    : QObject(window), m_document(document), m_window(window), m_autosave(std::make_unique<AutosaveSession>())
{
    connect(&document, &Document::derivedTakesChanged, this, &FileController::showPendingLiveTakes);
    connect(&document, &Document::selectionChanged, this, [this](TakeSlot slot) {
        if (!m_applying) m_pending[int(slot)].clear(); // the user chose another take meanwhile
    });
    m_openCorpus = new QAction(tr("&Open Corpus Folder..."), this);
    m_openCorpus->setShortcut(QKeySequence::Open);
    m_openDemo = new QAction(tr("Open &Demo Corpus"), this);
    m_newCorpus = new QAction(tr("&New Corpus from Files..."), this);
    m_newCorpus->setToolTip(tr("Make a corpus of take files (BVH, CSV, FASTRAK): labels from their names, one part map, one rate"));
    m_import = new QAction(tr("&Import Take..."), this);
    m_import->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    m_import->setToolTip(tr("Import a take from CSV, BVH or FASTRAK"));
    m_openProject = new QAction(tr("Open &Project..."), this);
    m_openProject->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    m_save = new QAction(tr("&Save Project"), this);
    m_save->setShortcut(QKeySequence::Save);
    m_saveAs = new QAction(tr("Save Project &As..."), this);
    m_saveAs->setShortcut(QKeySequence::SaveAs);
    m_recentMenu = new QMenu(tr("Open &Recent"), window);

    connect(m_openDemo, &QAction::triggered, this, [this] {
        if (maybeSave()) openDemoCorpus();
    });
    connect(m_openCorpus, &QAction::triggered, this, [this] {
        if (!maybeSave()) return;
        const QString folder = chooseFolder(m_window, FilePurpose::Corpus, tr("Open corpus folder"), m_projectPath);
        if (!folder.isEmpty()) openCorpusFolder(folder);
    });
    connect(m_newCorpus, &QAction::triggered, this, [this] {
        if (maybeSave()) chooseFilesForCorpus();
    });
    connect(m_import, &QAction::triggered, this, &FileController::chooseAndImport);
    connect(m_openProject, &QAction::triggered, this, [this] {
        if (!maybeSave()) return;
        const QString file = chooseOpenFile(m_window, FilePurpose::Project, tr("Open project"), tr("Bunraku projects (*.json)"), m_projectPath);
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
        QString file = chooseSaveFile(m_window, FilePurpose::Project, tr("Save project"), name, tr("Bunraku projects (*.json)"),
                                      m_projectPath);
        if (file.isEmpty()) return;
        if (!file.endsWith(QStringLiteral(".json"))) file += kProjectSuffix;
        saveProject(file);
    });

    m_autosaveTimer.setInterval(60 * 1000);
    connect(&m_autosaveTimer, &QTimer::timeout, this, &FileController::autosave);
    m_autosaveTimer.start();
    rebuildRecentMenu();
}

void FileController::setViewStateHooks(std::function<ViewState()> save, std::function<void(const ViewState&)> restore)
{
    m_saveView = std::move(save);
    m_restoreView = std::move(restore);
}

void FileController::report(const QString& title, const analysis::Error& error)
{
    m_lastError = QString::fromStdString(error.message);
    emit statusMessage(title + QStringLiteral(": ") + m_lastError);
    if (m_dialogs && !m_errorsInDialog) QMessageBox::warning(m_window, title, m_lastError);
}

bool FileController::openDemoCorpus()
{
    auto demo = analysis::synth::generateDemoCorpus();
    auto truth = std::make_shared<const analysis::synth::DemoGroundTruth>(std::move(demo.truth));
    // Shown first: the first take the generator did not turn about (its yaw channels wrap at
    // +-180 and the puppet faces away; such takes are there to exercise preprocessing).
    std::size_t first = 0;
    while (first + 1 < truth->takes.size() && truth->takes[first].yawWraps) ++first;
    m_document.setCorpus(std::move(demo.corpus), QStringLiteral("demo"), truth);
    if (first > 0) m_document.selectTake(TakeSlot::A, Document::corpusTakeId(first));
    m_projectPath.clear();
    emit statusMessage(tr("Opened the demo corpus (%1 takes)").arg(m_document.corpus().takes.size()));
    return true;
}

bool FileController::openCorpusFolder(const QString& folder)
{
    analysis::Result<analysis::Corpus> corpus = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
    runProgressTask(m_dialogs ? m_window : nullptr, tr("Reading the corpus %1...").arg(QFileInfo(folder).fileName()),
                    [&](const analysis::RunControl& control) { corpus = analysis::io::readCorpus(toPath(folder), control); },
                    m_progressOptions);
    if (!corpus && corpus.error().code == analysis::ErrorCode::Cancelled) {
        emit statusMessage(tr("Opening %1 cancelled; nothing was changed").arg(folder));
        return false;
    }
    if (!corpus) {
        report(tr("Cannot open the corpus"), corpus.error());
        return false;
    }
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    m_document.setCorpus(std::move(corpus).value(), absolute);
    m_projectPath.clear();
    addRecent(absolute);
    emit statusMessage(tr("Opened %1 (%2 takes)").arg(absolute).arg(m_document.corpus().takes.size()));
    return true;
}

bool FileController::openPath(const QString& path)
{
    const QFileInfo info(path);
    if (info.isDir()) return openCorpusFolder(path);
    if (path.endsWith(QStringLiteral(".json"))) return openProject(path);
    if (!info.exists()) {
        report(tr("Cannot open"), analysis::makeError(analysis::ErrorCode::NotFound, path.toStdString() + ": no such file or folder"));
        return false;
    }
    return importTakeFile(path);
}

int FileController::openDroppedPaths(const QStringList& paths)
{
    const bool replaces = std::any_of(paths.begin(), paths.end(), [](const QString& path) {
        return QFileInfo(path).isDir() || path.endsWith(QStringLiteral(".json"));
    });
    if (replaces && !maybeSave()) return 0;
    // Take files together (one dialog for several BVH files), the rest one by one.
    int opened = 0;
    QStringList takes;
    for (const QString& path : paths) {
        if (!QFileInfo(path).isDir() && !path.endsWith(QStringLiteral(".json")) && QFileInfo::exists(path)) takes << path;
        else opened += openPath(path) ? 1 : 0;
    }
    return opened + (takes.isEmpty() ? 0 : importTakeFiles(takes));
}

int FileController::importTakeFiles(const QStringList& files)
{
    QStringList bvhFiles;
    for (const QString& file : files)
        if (analysis::io::takeFileFormat(toPath(file)) == analysis::io::TakeFileFormat::Bvh) bvhFiles << file;
    std::optional<ImportTakesDialog> dialog;
    if (m_dialogs && bvhFiles.size() > 1) {
        // One dialog for all the BVH files, over the window (not one joint dialog per file).
        dialog.emplace(bvhFiles, m_window);
        if (dialog->exec() != QDialog::Accepted) {
            emit statusMessage(tr("Import of %n file(s) cancelled; nothing was changed", nullptr, int(files.size())));
            return 0;
        }
    }
    int imported = 0;
    for (const QString& file : files) {
        const int row = dialog ? int(bvhFiles.indexOf(file)) : -1;
        const bool done = row >= 0 ? importTake(file, dialog->options(row)) : importTakeFile(file);
        if (!done) break;
        ++imported;
    }
    return imported;
}

bool FileController::importTakeFile(const QString& file, const QString& jointMap) { return importTake(file, std::nullopt, jointMap); }

bool FileController::importTake(const QString& file, const std::optional<analysis::io::BvhImportOptions>& preset, const QString& jointMap)
{
    analysis::io::ImportOptions options;
    options.bvh.guessUnits = true;
    if (preset) options.bvh = *preset;
    const QString name = QFileInfo(file).fileName();
    const QString title = tr("Cannot import %1").arg(name);
    const auto format = analysis::io::takeFileFormat(toPath(file));
    const bool scene = format == analysis::io::TakeFileFormat::Scene;
    const bool bvh = format == analysis::io::TakeFileFormat::Bvh || scene;
    // FBX, glTF and Collada: the animation chosen from the file's list, then the whole file
    // converted (behind the progress dialog) before the part map is chosen on its skeleton.
    std::optional<analysis::io::BvhFile> converted;
    if (scene) {
        if (m_dialogs) {
            auto names = analysis::io::listSceneAnimations(toPath(file));
            if (!names) {
                report(title, names.error());
                return false;
            }
            if (names->size() > 1) {
                QStringList items;
                for (std::size_t a = 0; a < names->size(); ++a)
                    items << tr("%1: %2").arg(a).arg((*names)[a].empty() ? tr("(unnamed)") : QString::fromStdString((*names)[a]));
                bool chosen = false;
                const QString item = QInputDialog::getItem(m_window, tr("Import %1").arg(name), tr("The file has %1 animations; import:").arg(items.size()),
                                                           items, 0, false, &chosen);
                if (!chosen) return false;
                options.scene.animation = std::to_string(items.indexOf(item));
            }
        }
        analysis::Result<analysis::io::BvhFile> read = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
        runProgressTask(m_dialogs ? m_window : nullptr, tr("Reading %1...").arg(name), [&](const analysis::RunControl& control) {
            read = analysis::io::readSkeletalFile(toPath(file), options, control);
        }, m_progressOptions);
        if (!read && read.error().code == analysis::ErrorCode::Cancelled) {
            emit statusMessage(tr("Import of %1 cancelled; nothing was changed").arg(name));
            return false;
        }
        if (!read) {
            report(title, read.error());
            return false;
        }
        converted = std::move(read).value();
    }
    if (bvh && preset) {
        // Chosen in the dialog for several files: no joint dialog.
    } else if (bvh && !jointMap.isEmpty()) {
        auto map = analysis::io::parseJointMap(jointMap.toStdString());
        if (!map) {
            report(title, map.error());
            return false;
        }
        options.bvh.jointMap = map.value();
    } else if (bvh && m_dialogs) {
        // The dialog needs the hierarchy and the first pose only: a long BVH take is read after it.
        auto start = converted ? analysis::Result<analysis::io::BvhFile>(*converted) : analysis::io::readBvhStart(toPath(file));
        if (!start) {
            report(title, start.error());
            return false;
        }
        JointMapDialog dialog(*start, name, m_window);
        if (dialog.exec() != QDialog::Accepted) return false;
        options.bvh.jointMap = dialog.jointMap();
        options.bvh.side = dialog.side();
        dialog.applyUnits(options.bvh);
    }
    // Read and imported off the GUI thread behind a progress dialog that can cancel it.
    analysis::Result<analysis::Take> take = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
    std::string partMap;
    runProgressTask(m_dialogs ? m_window : nullptr, tr("Reading %1...").arg(name), [&](const analysis::RunControl& control) {
        if (!bvh) {
            take = analysis::io::readTakeFile(toPath(file), options);
            return;
        }
        auto parsed = converted ? analysis::Result<analysis::io::BvhFile>(std::move(*converted))
                                : analysis::io::readBvh(toPath(file), control.step(0.0, 0.5));
        if (!parsed) {
            take = parsed.error();
            return;
        }
        auto imported = analysis::io::importBvhPuppet(*parsed, scene ? analysis::io::sceneBvhOptions(options.bvh) : options.bvh,
                                                      control.step(0.5, 1.0));
        if (!imported) {
            take = imported.error();
            return;
        }
        partMap = imported->map->describe();
        take = std::move(imported->take);
    }, m_progressOptions);
    if (!take && take.error().code == analysis::ErrorCode::Cancelled) {
        emit statusMessage(tr("Import of %1 cancelled; nothing was changed").arg(name));
        return false;
    }
    if (!take) {
        report(title, take.error());
        return false;
    }
    const QString mapNote = partMap.empty() ? QString() : tr(" (part map: %1)").arg(QString::fromStdString(partMap));
    const QString absolute = QFileInfo(file).absoluteFilePath();
    auto pointer = std::make_shared<const analysis::Take>(std::move(take).value());
    m_document.undoStack()->push(new ImportTake(&m_document, std::move(pointer), name, absolute,
                                                std::make_shared<const analysis::io::ImportOptions>(options)));
    addRecent(absolute);
    emit statusMessage(tr("Imported %1%2").arg(absolute, mapNote));
    return true;
}

bool FileController::createCorpusFromFiles(const std::vector<analysis::io::CorpusSource>& sources,
                                           const analysis::io::CorpusBuildOptions& options, const QString& folder)
{
    analysis::Result<analysis::io::CorpusBuild> result = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
    runProgressTask(m_dialogs ? m_window : nullptr, tr("Reading %n take file(s)...", nullptr, int(sources.size())),
                    [&](const analysis::RunControl& control) {
                        result = analysis::io::buildCorpus(sources, options, control);
                        if (!result) return;
                        if (auto written = analysis::io::writeCorpus(result->corpus, toPath(folder)); !written) result = written.error();
                    }, m_progressOptions);
    if (!result && result.error().code == analysis::ErrorCode::Cancelled) {
        emit statusMessage(tr("Making the corpus %1 cancelled; nothing was written").arg(folder));
        return false;
    }
    if (!result) {
        report(tr("Cannot make the corpus"), result.error());
        return false;
    }
    if (!openCorpusFolder(folder)) return false;
    QStringList notes;
    for (const auto& note : result->notes) notes << QString::fromStdString(note);
    emit statusMessage(tr("Made the corpus %1 from %n file(s)", nullptr, int(sources.size())).arg(folder) +
                       (notes.isEmpty() ? QString() : QStringLiteral("; ") + notes.join(QStringLiteral("; "))));
    return true;
}

void FileController::chooseFilesForCorpus(const QStringList& inputs)
{
    NewCorpusDialog dialog(m_window);
    dialog.addInputs(inputs);
    dialog.setCreator([this](NewCorpusDialog& asking) {
        // The progress dialog over the new-corpus dialog; an error is shown in it, which stays open.
        const QScopedValueRollback<QWidget*> parent(m_window, &asking);
        const QScopedValueRollback<bool> inDialog(m_errorsInDialog, true);
        const QString folder = asking.outputFolder();
        m_lastError.clear();
        if (createCorpusFromFiles(asking.sources(), asking.buildOptions(), folder)) {
            rememberFolder(FilePurpose::Corpus, QFileInfo(folder).absoluteFilePath());
            rememberFolder(FilePurpose::NewCorpus, QFileInfo(folder).absoluteFilePath());
            return true;
        }
        asking.showCreateError(m_lastError.isEmpty() ? tr("cancelled; nothing was written") : m_lastError);
        return false;
    });
    dialog.exec();
}

ProjectState FileController::captureState() const
{
    ProjectState state;
    state.corpus = m_document.corpusSource();
    for (const auto& derived : m_document.derivedTakes())
        if (!derived.sourcePath.isEmpty())
            state.imported.push_back({derived.sourcePath, derived.label,
                                      derived.importOptions ? *derived.importOptions : analysis::io::ImportOptions{}});
    state.parameters = m_document.parameters();
    state.takeA = m_document.selectedId(TakeSlot::A);
    state.takeB = m_document.selectedId(TakeSlot::B);
    state.timeSeconds = m_document.currentTime();
    if (m_saveView) state.view = m_saveView();
    return state;
}

bool FileController::applyState(const ProjectState& state)
{
    m_pending[0].clear();
    m_pending[1].clear();
    m_applying = true;
    const bool applied = applyStateNow(state);
    m_applying = false;
    return applied;
}

void FileController::showPendingLiveTakes()
{
    bool shown = false;
    for (int slot = 0; slot < 2; ++slot) {
        if (m_pending[slot].isEmpty() || !m_document.take(m_pending[slot])) continue;
        const QString id = m_pending[slot];
        m_pending[slot].clear();
        m_applying = true; // the project's own selection: do not drop the other pending slot
        m_document.selectTake(TakeSlot(slot), id);
        m_applying = false;
        shown = true;
    }
    if (shown) m_document.setCurrentTime(m_pendingTime);
}

bool FileController::applyStateNow(const ProjectState& state)
{
    // The project's imported takes are read first, off the GUI thread behind a progress dialog
    // (an hour-long take among them): Cancel leaves the document as it was.
    std::vector<analysis::Result<analysis::Take>> takes;
    bool cancelled = false;
    m_unreadTakes.clear();
    if (!state.imported.empty())
        runProgressTask(m_dialogs ? m_window : nullptr, tr("Reading the project's %n imported take(s)...", nullptr, int(state.imported.size())),
                        [&](const analysis::RunControl& control) {
                            const double share = 1.0 / double(state.imported.size());
                            for (qsizetype i = 0; i < state.imported.size() && !cancelled; ++i) {
                                // The options the take was imported with: the same joint map, axes, units and rate.
                                const auto& recipe = state.imported[i];
                                takes.push_back(analysis::io::readTakeFile(toPath(recipe.path), recipe.options,
                                                                           control.step(share * double(i), share * double(i + 1))));
                                cancelled = control.cancelled();
                            }
                        }, m_progressOptions);
    if (cancelled) {
        emit statusMessage(tr("Opening the project cancelled; nothing was changed"));
        return false;
    }
    const bool opened = state.corpus == QStringLiteral("demo") ? openDemoCorpus() : openCorpusFolder(state.corpus);
    if (!opened) return false;
    std::vector<DerivedTake> imported;
    for (qsizetype i = 0; i < state.imported.size(); ++i) {
        const auto& recipe = state.imported[i];
        auto& take = takes[std::size_t(i)];
        if (!take) {
            m_unreadTakes.append(tr("'%1' (%2)").arg(recipe.label, QString::fromStdString(take.error().message)));
            report(tr("Cannot re-import the take '%1' of the project").arg(recipe.label), take.error());
            continue;
        }
        imported.push_back(DerivedTake{m_document.nextImportedId(), recipe.label,
                                       std::make_shared<const analysis::Take>(std::move(take).value()), recipe.path, QString(),
                                       std::make_shared<const analysis::io::ImportOptions>(recipe.options), nullptr, {}});
    }
    m_document.restoreProject(std::move(imported), state.parameters);
    // Live results are recomputed after opening: a live take shown as A or B is awaited and
    // shown when published (showPendingLiveTakes); until then A keeps the corpus's first take.
    const QString ids[2] = {state.takeA, state.takeB};
    for (int slot = 0; slot < 2; ++slot) {
        if (Document::isLiveTakeId(ids[slot]) && !m_document.take(ids[slot]))
            m_pending[slot] = ids[slot];
        else
            m_document.selectTake(TakeSlot(slot), ids[slot]);
    }
    m_pendingTime = state.timeSeconds;
    m_document.setCurrentTime(state.timeSeconds);
    if (m_restoreView) m_restoreView(state.view);
    return true;
}

bool FileController::saveProject(const QString& file)
{
    if (const auto status = writeProject(captureState(), file); !status) {
        report(tr("Cannot save the project"), status.error());
        return false;
    }
    m_projectPath = file;
    m_document.undoStack()->setClean();
    m_autosave->removeOwn();
    addRecent(file);
    emit statusMessage(tr("Saved %1").arg(file));
    return true;
}

bool FileController::openProject(const QString& file)
{
    auto state = readProject(file);
    if (!state) {
        report(tr("Cannot open the project"), state.error());
        return false;
    }
    if (!applyState(state.value())) return false;
    m_projectPath = file;
    addRecent(file);
    if (m_unreadTakes.isEmpty()) {
        emit statusMessage(tr("Opened project %1").arg(file));
    } else {
        // The last word in the status bar: which takes are missing and why (each was reported too).
        m_lastError = tr("Opened project %1 without %n of its imported take(s), which could not be read: %2", nullptr,
                         int(m_unreadTakes.size()))
                          .arg(file, m_unreadTakes.join(QStringLiteral("; ")));
        emit statusMessage(m_lastError);
    }
    return true;
}

QString FileController::autosavePath() const { return m_autosave->path(); }

bool FileController::autosave()
{
    if (m_document.undoStack()->isClean()) return false;
    QDir().mkpath(QFileInfo(autosavePath()).absolutePath());
    return bool(writeProject(captureState(), autosavePath()));
}

bool FileController::recoverAutosave(const QString& file)
{
    if (!m_autosave->adopt(file)) {
        report(tr("Cannot recover"), analysis::makeError(analysis::ErrorCode::Io,
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

void FileController::offerRecovery()
{
    if (!m_dialogs) return;
    const QVector<OrphanedAutosave> orphans = m_autosave->orphans();
    if (orphans.isEmpty()) return;
    RecoveryDialog dialog(orphans, [this](const QString& path) { return m_autosave->discardOrphan(path); }, m_window);
    if (dialog.exec() == QDialog::Accepted && !dialog.chosen().isEmpty()) recoverAutosave(dialog.chosen());
}

bool FileController::maybeSave()
{
    if (m_document.undoStack()->isClean()) return true;
    if (!m_dialogs && !m_unsavedAnswer) return true;
    const int answer = !m_dialogs ? m_unsavedAnswer()
                                  : QMessageBox::warning(m_window, tr("Unsaved changes"),
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
            if (maybeSave()) openPath(path);
        });
    }
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void FileController::chooseAndImport()
{
    const QString file = chooseOpenFile(
        m_window, FilePurpose::ImportTake, tr("Import take"),
        tr("Takes (*.csv *.bvh *.fbx *.glb *.gltf *.dae *.txt *.fastrak *.fst);;CSV (*.csv);;BVH (*.bvh);;FBX (*.fbx);;glTF (*.glb *.gltf);;"
           "Collada (*.dae);;FASTRAK (*.txt *.fastrak *.fst)"),
        m_projectPath);
    if (!file.isEmpty()) importTakeFile(file);
}

} // namespace bunraku::app
