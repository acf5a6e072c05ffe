#include "app/view_video_controller.h"

#include "app/project_controller.h"

#include "render/scene.h"

#include "app/document.h"
#include "app/file_controller.h"
#include "app/file_dialogs.h"
#include "app/offscreen_view.h"
#include "app/playback_controller.h"
#include "app/video_export_dialog.h"
#include "app/viewport_panel.h"

#include "widgets/viewport_widget.h"

#include "analysis/core/puppet_layout.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>

#include <cmath>
#include <memory>
#include <optional>

namespace bunraku::app {

ViewVideoController::ViewVideoController(Document& document, PlaybackController& playback, ViewportPanel& viewport,
                                         FileController& files, QWidget* window)
    : QObject(window), m_document(document), m_playback(playback), m_viewport(viewport), m_files(files), m_window(window)
{
    m_action = new QAction(tr("Export 3D View &Video..."), this);
    m_action->setObjectName("exportViewVideoAction");
    connect(m_action, &QAction::triggered, this, &ViewVideoController::choose);
}

int ViewVideoController::exportFrames(const QString& folder)
{
    VideoExportOptions options;
    options.format = VideoFormat::PngSequence;
    options.output = folder;
    return exportVideo(options, [](int, int) { return true; }).frames;
}

VideoExportResult ViewVideoController::exportVideo(const VideoExportOptions& options, const ExportProgress& progress)
{
    VideoExportResult refused;
    const TakePointer take = m_document.selectedTake(TakeSlot::A);
    if (!take) {
        refused.error = tr("There is no take to export: choose take A in the corpus browser.");
        return refused;
    }
    // Take A's own frames, even when a longer take B is shown beside it.
    const int lastAvailable = int(take->frameCount()) - 1;
    const int lastFrame = options.lastFrame < 0 ? lastAvailable : options.lastFrame;
    if (lastAvailable < 0 || options.firstFrame < 0 || options.firstFrame > lastFrame || lastFrame > lastAvailable) {
        refused.error = lastAvailable < 0 ? tr("Take A has no frames to export.")
                                          : tr("Frames %1 to %2 cannot be exported: take A has frames 0 to %3.")
                                                .arg(options.firstFrame).arg(lastFrame).arg(lastAvailable);
        return refused;
    }
    const FramePlan plan = planFrames(take->rateHz, options.firstFrame, lastFrame, options.fps);

    // At the view's own size the view itself is grabbed (what you see); else an offscreen copy.
    auto* view = m_viewport.viewport();
    const qreal ratio = view->devicePixelRatioF();
    const QSize viewPixels(int(std::lround(view->width() * ratio)), int(std::lround(view->height() * ratio)));
    std::unique_ptr<OffscreenView> offscreen;
    FrameRenderer render;
    if (options.size.isEmpty() && view->isVisible()) {
        render = [this, view](double seconds) -> analysis::Result<QImage> {
            if (!view->isVisible())
                return analysis::makeError(analysis::ErrorCode::Unsupported,
                                           tr("the 3D view is no longer shown (its dock was closed or the window "
                                              "minimised during the export); show it, or export at a chosen "
                                              "resolution, which draws offscreen").toStdString());
            m_document.setCurrentTime(seconds);
            QImage image = view->grabFramebuffer(); // renders the current pose
            if (image.isNull())
                return analysis::makeError(analysis::ErrorCode::Io,
                                           tr("the 3D view could not be grabbed: it is not on screen or its OpenGL "
                                              "context was lost; show it, or export at a chosen resolution, which "
                                              "draws offscreen").toStdString());
            return image;
        };
    } else {
        std::vector<analysis::Take> takes;
        for (TakeSlot slot : {TakeSlot::A, TakeSlot::B})
            if (TakePointer shown = m_document.selectedTake(slot); shown && render::drawableTake(*shown))
                takes.push_back(*shown);
        const std::optional<render::Camera> camera =
            view->renderer() ? std::optional<render::Camera>(view->camera()) : std::nullopt;
        auto made = OffscreenView::create(std::move(takes), camera, view->visibility(),
                                          options.size.isEmpty() ? viewPixels : options.size, m_viewport.drawnKimonos());
        if (!made) {
            refused.error = tr("Cannot draw the 3D view offscreen: %1").arg(QString::fromStdString(made.error().message));
            return refused;
        }
        offscreen = std::move(made.value());
        render = [&offscreen](double seconds) -> analysis::Result<QImage> {
            QImage image = offscreen->render(seconds);
            if (image.isNull())
                return analysis::makeError(analysis::ErrorCode::Io,
                                           tr("the offscreen OpenGL context drew nothing (it was lost, e.g. by a "
                                              "graphics driver reset); try again, or export at the view's size")
                                               .toStdString());
            return image;
        };
    }

    std::unique_ptr<QProgressDialog> dialog;
    ExportProgress report = progress;
    if (!report) {
        dialog = std::make_unique<QProgressDialog>(tr("Exporting the 3D view to %1...").arg(QFileInfo(options.output).fileName()),
                                                   tr("Cancel"), 0, int(plan.times.size()), m_window);
        dialog->setObjectName("videoExportProgress");
        dialog->setWindowTitle(tr("Export 3D View Video"));
        dialog->setWindowModality(Qt::WindowModal);
        dialog->setMinimumDuration(0);
        report = [&dialog](int done, int) {
            dialog->setValue(done);
            return !dialog->wasCanceled();
        };
    }

    const bool wasPlaying = m_playback.playing();
    const double restoreTime = m_document.currentTime();
    m_playback.setPlaying(false);
    VideoExportResult result = app::exportFrames(options, plan, render, report);
    offscreen.reset();
    dialog.reset();
    m_document.setCurrentTime(restoreTime);
    m_playback.setPlaying(wasPlaying);

    if (result.cancelled)
        emit message(tr("Export cancelled: nothing was written"));
    else if (!result.ok())
        emit message(tr("Export failed: %1").arg(result.error.section(QLatin1Char('\n'), 0, 0)));
    else
        emit message(tr("Wrote %1 frames to %2").arg(result.frames).arg(result.output));
    return result;
}

void ViewVideoController::choose()
{
    const TakePointer take = m_document.selectedTake(TakeSlot::A);
    if (!take) {
        QMessageBox::information(m_window, tr("Export 3D View Video"), tr("Choose take A in the corpus browser first."));
        return;
    }
    auto* view = m_viewport.viewport();
    VideoExportLimits limits;
    limits.lastFrame = std::max(0, int(take->frameCount()) - 1); // take A's own frames, not the longer take's
    limits.rateHz = take->rateHz;
    limits.viewSize = QSize(int(std::lround(view->width() * view->devicePixelRatioF())),
                            int(std::lround(view->height() * view->devicePixelRatioF())));
    VideoExportDialog dialog(limits, m_window);
    dialog.suggestOutput(suggestedFileName(m_document, {}), m_files.projects().projectPath());
    if (dialog.exec() != QDialog::Accepted) return;
    const VideoExportResult result = exportVideo(dialog.options());
    if (!result.ok() && !result.cancelled) QMessageBox::warning(m_window, tr("Export 3D View Video"), result.error);
}

} // namespace bunraku::app
