#include "app/multimodal_export.h"

#include <QObject>

#include <cmath>
#include <string>

namespace bunraku::app {

analysis::Result<FramePlan> planTakeFrames(const analysis::Take& takeA, const VideoExportOptions& options)
{
    const int lastAvailable = int(takeA.frameCount()) - 1;
    const int lastFrame = options.lastFrame < 0 ? lastAvailable : options.lastFrame;
    if (lastAvailable < 0)
        return analysis::makeError(analysis::ErrorCode::InvalidArgument, "take A has no frames to export");
    if (options.firstFrame < 0 || options.firstFrame > lastFrame || lastFrame > lastAvailable)
        return analysis::makeError(analysis::ErrorCode::InvalidArgument,
                                   "frames " + std::to_string(options.firstFrame) + " to " + std::to_string(lastFrame) +
                                       " cannot be exported: take A has frames 0 to " + std::to_string(lastAvailable));
    if (options.fps < 0.0 || !std::isfinite(options.fps))
        return analysis::makeError(analysis::ErrorCode::InvalidArgument, "the frame rate must be positive (or 0: the take's)");
    FramePlan plan = planFrames(takeA.rateHz, options.firstFrame, lastFrame, options.fps);
    if (plan.times.empty())
        return analysis::makeError(analysis::ErrorCode::InvalidArgument, "take A has no frame rate, so no frames to plan");
    return plan;
}

VideoExportResult exportMultimodalVideo(const MultimodalFrame& frame, const ViewImage& view, VideoExportOptions options,
                                        const ExportProgress& progress)
{
    options.size = frame.options().size;
    VideoExportResult refused;
    auto plan = planTakeFrames(frame.takeA(), options);
    if (!plan) {
        refused.error = QString::fromStdString(plan.error().message);
        return refused;
    }
    const FrameRenderer render = [&frame, &view](double seconds) { return frame.render(view, seconds); };
    return exportFrames(options, *plan, render, progress);
}

} // namespace bunraku::app
