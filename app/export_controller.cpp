#include "app/export_controller.h"

#include "app/file_dialogs.h"
#include "app/progress_task.h"

#include "analysis/body/body_description.h"
#include "render/take_export.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>

#include <filesystem>

namespace bunraku::app {

namespace {

QString slotName(TakeSlot slot) { return slot == TakeSlot::A ? QStringLiteral("A") : QStringLiteral("B"); }

} // namespace

ExportController::ExportController(Document& document, QWidget* window) : QObject(window), m_document(document), m_window(window)
{
    m_exportA = new QAction(tr("&Export Take A..."), this);
    m_exportA->setObjectName("exportTakeAAction");
    m_exportA->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    m_exportB = new QAction(tr("Export Take &B..."), this);
    m_exportB->setObjectName("exportTakeBAction");
    for (QAction* action : {m_exportA, m_exportB})
        action->setToolTip(tr("Write the take as BVH (on its own skeleton when it has one), glTF binary or CSV"));
    connect(m_exportA, &QAction::triggered, this, [this] { chooseAndExport(TakeSlot::A); });
    connect(m_exportB, &QAction::triggered, this, [this] { chooseAndExport(TakeSlot::B); });
}

bool ExportController::exportTake(TakeSlot slot, const QString& file, bool kimono)
{
    const TakePointer take = m_document.selectedTake(slot);
    if (!take) {
        report(tr("Nothing to export: no take is shown as %1.").arg(slotName(slot)));
        return false;
    }
    // Names inside the file are short and stable (the take's name: "bow designed"); the recipe
    // a live result is listed with goes into the file's metadata.
    const TakeId id = m_document.selectedId(slot);
    const QString label = m_document.takeLabel(id);
    const QString name = m_document.takeName(id);
    const std::filesystem::path path(file.toStdString());
    analysis::Status status = analysis::okStatus();
    if (kimono) {
        // The cloth's simulation takes a while on a long take: off the GUI thread, with Cancel.
        const analysis::ClothParameters parameters = m_cloth;
        runProgressTask(m_dialogs ? m_window : nullptr, tr("Simulating the kimono of take %1 for %2...").arg(slotName(slot), QFileInfo(file).fileName()),
                        [&](const analysis::RunControl& control) {
                            render::KimonoExport cloth;
                            cloth.cloth = parameters;
                            cloth.control = control;
                            status = render::exportTake(*take, analysis::defaultBodyDescription(), path, name.toStdString(),
                                                        label != name ? label.toStdString() : std::string(), &cloth);
                        });
    } else {
        status = render::exportTake(*take, analysis::defaultBodyDescription(), path, name.toStdString(),
                                    label != name ? label.toStdString() : std::string());
    }
    if (!status && status.error().code == analysis::ErrorCode::Cancelled) {
        m_lastError = tr("Export of take %1 cancelled: nothing was written").arg(slotName(slot));
        emit statusMessage(m_lastError);
        return false;
    }
    if (!status) {
        report(tr("Cannot export take %1: %2").arg(slotName(slot), QString::fromStdString(status.error().message)));
        return false;
    }
    m_lastError.clear();
    QString message = kimono ? tr("Exported take %1 (%2) with its simulated kimono to %3").arg(slotName(slot), label, file)
                             : tr("Exported take %1 (%2) to %3").arg(slotName(slot), label, file);
    const TakePointer perChannel = m_document.perChannelGhostOf(m_document.selectedId(slot));
    m_lastNote = QString::fromStdString(render::takeExportNote(*take, std::filesystem::path(file.toStdString()), perChannel.get()));
    if (!m_lastNote.isEmpty()) message += QStringLiteral(": ") + m_lastNote;
    emit statusMessage(message);
    return true;
}

void ExportController::chooseAndExport(TakeSlot slot)
{
    const QString bvh = tr("BVH on the take's skeleton (*.bvh)");
    const QString glb = tr("glTF binary (*.glb)");
    const QString csv = tr("CSV take (*.csv)");
    const QString glbKimono = tr("glTF binary with the kimono simulated as cloth (*.glb)");
    const QString csvKimono = tr("CSV take with the kimono's measured channels (*.csv)");
    QString filter = bvh;
    // In the folder last exported to, named after the corpus and the take's name ("demo-greeting-none-2.bvh",
    // "demo-bow-designed.bvh").
    const QString name = suggestedFileName(m_document, QStringLiteral(".bvh"),
                                           slot == TakeSlot::A ? NameParts::CorpusAndTakeA : NameParts::CorpusAndTakeB);
    QString file = chooseSaveFile(m_window, FilePurpose::ExportTake, tr("Export take %1").arg(slotName(slot)), name,
                                  bvh + ";;" + glb + ";;" + glbKimono + ";;" + csv + ";;" + csvKimono, {}, &filter);
    if (file.isEmpty()) return;
    if (render::takeExportFormat(std::filesystem::path(file.toStdString())) == render::TakeExportFormat::Unknown)
        file += filter == glb || filter == glbKimono ? QStringLiteral(".glb")
                : filter == csv || filter == csvKimono ? QStringLiteral(".csv")
                                                       : QStringLiteral(".bvh");
    exportTake(slot, file, filter == glbKimono || filter == csvKimono);
}

void ExportController::report(const QString& message)
{
    m_lastError = message;
    emit statusMessage(message);
    if (m_dialogs) QMessageBox::warning(m_window, tr("Export take"), message);
}

} // namespace bunraku::app
