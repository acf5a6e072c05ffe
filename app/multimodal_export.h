#pragma once
/// The multimodal display as a video (thesis chapter 6: puppet, axis, orbits and graphs in one
/// picture): frames composed by MultimodalFrame, planned and written by the 3D-view video
/// export's own functions (planFrames, exportFrames), so the output appears atomically (MP4
/// renamed into place when ffmpeg succeeds, PNG frames moved in from a hidden folder) and a
/// cancel or an error leaves nothing behind. Used by File > Export Multimodal Video... and
/// `bunraku render --multimodal`.

#include "app/multimodal_frame.h"
#include "app/video_export.h"

namespace bunraku::app {

/// The frames of take A's range [options.firstFrame, options.lastFrame] (-1: its last frame)
/// at options.fps (0: the take's rate); an error message for a person when the range does not
/// fit the take.
analysis::Result<FramePlan> planTakeFrames(const analysis::Take& takeA, const VideoExportOptions& options);

/// Renders and writes the frames: `view` draws the 3D view at each time (its size is the
/// frame's view rectangle), `frame` composes it with the graphs. options.size is taken from
/// frame.options().size. Progress and cancel as exportFrames.
VideoExportResult exportMultimodalVideo(const MultimodalFrame& frame, const ViewImage& view, VideoExportOptions options,
                                        const ExportProgress& progress = {});

} // namespace bunraku::app
