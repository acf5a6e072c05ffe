#include "app/import_controller.h"

#include "app/commands.h"
#include "app/document.h"
#include "app/file_controller.h"
#include "app/file_dialogs.h"
#include "app/import_takes_dialog.h"
#include "app/joint_map_dialog.h"
#include "app/project_controller.h"

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_joint_map.h"

#include <QAction>
#include <QFileInfo>
#include <QInputDialog>

#include <filesystem>

namespace bunraku::app {
ImportController::ImportController(Document& document, FileController& files) : QObject(&files), m_document(document), m_files(files)
{
    m_import = new QAction(tr("&Import Take..."), this);
    m_import->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    m_import->setToolTip(tr("Import a take from CSV, BVH or FASTRAK"));
    connect(m_import, &QAction::triggered, this, &ImportController::chooseAndImport);
}

int ImportController::importTakeFiles(const QStringList& files)
{
    QStringList bvhFiles;
    for (const QString& file : files)
        if (analysis::io::takeFileFormat(toPath(file)) == analysis::io::TakeFileFormat::Bvh) bvhFiles << file;
    std::optional<ImportTakesDialog> dialog;
    if (m_files.dialogsEnabled() && bvhFiles.size() > 1) {
        // One dialog for all the BVH files, over the window (not one joint dialog per file).
        dialog.emplace(bvhFiles, m_files.window());
        if (dialog->exec() != QDialog::Accepted) {
            emit m_files.statusMessage(tr("Import of %n file(s) cancelled; nothing was changed", nullptr, int(files.size())));
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

bool ImportController::importTakeFile(const QString& file, const QString& jointMap) { return importTake(file, std::nullopt, jointMap); }

bool ImportController::importTake(const QString& file, const std::optional<analysis::io::BvhImportOptions>& preset, const QString& jointMap)
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
        if (m_files.dialogsEnabled()) {
            auto names = analysis::io::listSceneAnimations(toPath(file));
            if (!names) {
                m_files.report(title, names.error());
                return false;
            }
            if (names->size() > 1) {
                QStringList items;
                for (std::size_t a = 0; a < names->size(); ++a)
                    items << tr("%1: %2").arg(a).arg((*names)[a].empty() ? tr("(unnamed)") : QString::fromStdString((*names)[a]));
                bool chosen = false;
                const QString item = QInputDialog::getItem(m_files.window(), tr("Import %1").arg(name), tr("The file has %1 animations; import:").arg(items.size()),
                                                           items, 0, false, &chosen);
                if (!chosen) return false;
                options.scene.animation = std::to_string(items.indexOf(item));
            }
        }
        analysis::Result<analysis::io::BvhFile> read = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
        m_files.runTask(tr("Reading %1...").arg(name), [&](const analysis::RunControl& control) {
            read = analysis::io::readSkeletalFile(toPath(file), options, control);
        });
        if (!m_files.succeeded(read, tr("Import of %1 cancelled; nothing was changed").arg(name), title)) return false;
        converted = std::move(read).value();
    }
    if (bvh && preset) {
        // Chosen in the dialog for several files: no joint dialog.
    } else if (bvh && !jointMap.isEmpty()) {
        auto map = analysis::io::parseJointMap(jointMap.toStdString());
        if (!map) {
            m_files.report(title, map.error());
            return false;
        }
        options.bvh.jointMap = map.value();
    } else if (bvh && m_files.dialogsEnabled()) {
        // The dialog needs the hierarchy and the first pose only: a long BVH take is read after it.
        auto start = converted ? analysis::Result<analysis::io::BvhFile>(*converted) : analysis::io::readBvhStart(toPath(file));
        if (!start) {
            m_files.report(title, start.error());
            return false;
        }
        JointMapDialog dialog(*start, name, m_files.window());
        if (dialog.exec() != QDialog::Accepted) return false;
        options.bvh.jointMap = dialog.jointMap();
        options.bvh.side = dialog.side();
        dialog.applyUnits(options.bvh);
    }
    // Read and imported off the GUI thread behind a progress dialog that can cancel it.
    analysis::Result<analysis::Take> take = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
    std::string partMap;
    m_files.runTask(tr("Reading %1...").arg(name), [&](const analysis::RunControl& control) {
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
    });
    if (!m_files.succeeded(take, tr("Import of %1 cancelled; nothing was changed").arg(name), title)) return false;
    const QString mapNote = partMap.empty() ? QString() : tr(" (part map: %1)").arg(QString::fromStdString(partMap));
    const QString absolute = QFileInfo(file).absoluteFilePath();
    auto pointer = std::make_shared<const analysis::Take>(std::move(take).value());
    m_document.undoStack()->push(new ImportTake(&m_document, std::move(pointer), name, absolute,
                                                std::make_shared<const analysis::io::ImportOptions>(options)));
    m_files.addRecent(absolute);
    emit m_files.statusMessage(tr("Imported %1%2").arg(absolute, mapNote));
    return true;
}

void ImportController::chooseAndImport()
{
    const QString file = chooseOpenFile(
        m_files.window(), FilePurpose::ImportTake, tr("Import take"),
        tr("Takes (*.csv *.bvh *.fbx *.glb *.gltf *.dae *.txt *.fastrak *.fst);;CSV (*.csv);;BVH (*.bvh);;FBX (*.fbx);;glTF (*.glb *.gltf);;"
           "Collada (*.dae);;FASTRAK (*.txt *.fastrak *.fst)"),
        m_files.projects().projectPath());
    if (!file.isEmpty()) importTakeFile(file);
}

} // namespace bunraku::app
