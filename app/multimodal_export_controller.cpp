#include "app/multimodal_export_controller.h"

#include "app/document.h"
#include "app/multimodal_export.h"
#include "app/offscreen_view.h"
#include "render/scene.h"
#include "app/viewport_panel.h"
#include "widgets/graph_panel.h"
#include "widgets/viewport_widget.h"

#include "analysis/core/puppet_layout.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>

#include <memory>
#include <optional>

namespace bunraku::app {

MultimodalExportController::MultimodalExportController(Document& document, widgets::GraphPanel& graphs, ViewportPanel& viewport,
                                                       QWidget* window)
    : QObject(window), m_document(document), m_graphs(graphs), m_viewport(viewport), m_window(window)
{
    m_action = new QAction(tr("Export &Multimodal Video..."), this);
    m_action->setObjectName("exportMultimodalVideo");
    m_action->setStatusTip(tr("The 3D view and the graphs with a moving time cursor in one video, as the thesis's "
                              "multimodal display"));
    connect(m_action, &QAction::triggered, this, &MultimodalExportController::choose);
}

MultimodalOptions MultimodalExportController::graphDockLayout(QSize size) const
{
    MultimodalOptions options;
    options.layout = m_graphs.grid()->graphLayout();
    options.part = m_graphs.selectedPart().toStdString();
    options.dof = m_graphs.selectedDof().toStdString();
    options.thesisTicks = m_graphs.grid()->thesisTicks();
    options.size = size;
    return options;
}

VideoExportResult MultimodalExportController::exportVideo(const MultimodalOptions& layout, const VideoExportOptions& options,
                                                          const ExportProgress& progress)
{
    VideoExportResult refused;
    const TakePointer takeA = m_document.selectedTake(TakeSlot::A);
    const TakePointer takeB = m_document.selectedTake(TakeSlot::B);
    auto finish = [this](VideoExportResult result) {
        if (result.cancelled) emit message(tr("Export cancelled: nothing was written"));
        else if (!result.ok()) emit message(tr("Export failed: %1").arg(result.error.section(QLatin1Char('\n'), 0, 0)));
        else emit message(tr("Wrote %1 multimodal frames to %2").arg(result.frames).arg(result.output));
        return result;
    };
    if (!takeA) {
        refused.error = tr("There is no take to export: choose take A in the corpus browser.");
        return finish(refused);
    }
    auto frame = MultimodalFrame::create(takeA, takeB, layout);
    if (!frame) {
        refused.error = QString::fromStdString(frame.error().message);
        return finish(refused);
    }
    // the puppets of the takes that can pose it, drawn offscreen at the view rectangle's size
    std::vector<analysis::Take> puppets;
    for (const TakePointer& take : {takeA, takeB})
        if (take && render::drawableTake(*take)) puppets.push_back(*take);
    auto* view = m_viewport.viewport();
    const std::optional<render::Camera> camera = view->renderer() ? std::optional<render::Camera>(view->camera()) : std::nullopt;
    auto offscreen = OffscreenView::create(std::move(puppets), camera, view->visibility(), frame->geometry().view.size(),
                                           m_viewport.drawnKimonos()); // the kimonos the view dresses them in
    if (!offscreen) {
        refused.error = tr("Cannot draw the 3D view offscreen: %1").arg(QString::fromStdString(offscreen.error().message));
        return finish(refused);
    }
    const ViewImage draw = [&offscreen](double seconds, QSize) -> analysis::Result<QImage> {
        QImage image = (*offscreen)->render(seconds);
        if (image.isNull())
            return analysis::makeError(analysis::ErrorCode::Io, tr("the offscreen OpenGL context drew nothing (it was lost, "
                                                                   "e.g. by a graphics driver reset); try again").toStdString());
        return image;
    };

    std::unique_ptr<QProgressDialog> dialog;
    ExportProgress report = progress;
    if (!report) {
        const auto plan = planTakeFrames(*takeA, options);
        const int total = plan ? int(plan->times.size()) : 0;
        dialog = std::make_unique<QProgressDialog>(tr("Exporting the multimodal display to %1...").arg(QFileInfo(options.output).fileName()),
                                                   tr("Cancel"), 0, total, m_window);
        dialog->setObjectName("multimodalExportProgress");
        dialog->setWindowTitle(tr("Export Multimodal Video"));
        dialog->setWindowModality(Qt::WindowModal);
        dialog->setMinimumDuration(0);
        report = [&dialog](int done, int) {
            dialog->setValue(done);
            return !dialog->wasCanceled();
        };
    }
    VideoExportResult result = exportMultimodalVideo(*frame, draw, options, report);
    offscreen.value().reset();
    return finish(result);
}

void MultimodalExportController::choose()
{
    const TakePointer takeA = m_document.selectedTake(TakeSlot::A);
    if (!takeA) {
        QMessageBox::information(m_window, tr("Export Multimodal Video"), tr("Choose take A in the corpus browser first."));
        return;
    }
    const bool twoTakes = m_document.selectedTake(TakeSlot::B) != nullptr;
    MultimodalExportDialog dialog(takeA->channels, std::max(0, int(takeA->frameCount()) - 1), takeA->rateHz, twoTakes,
                                  graphDockLayout(), m_window);
    if (dialog.exec() != QDialog::Accepted) return;
    const MultimodalExportChoice choice = dialog.choice();
    const VideoExportResult result = exportVideo(choice.layout, choice.video);
    if (!result.ok() && !result.cancelled) QMessageBox::warning(m_window, tr("Export Multimodal Video"), result.error);
}

} // namespace bunraku::app
