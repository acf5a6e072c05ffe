#pragma once
/// Export of the 3D view as a video: which frames (a frame range of take A, resampled to any
/// frame rate), and where they go (an MP4 H.264 file through ffmpeg, or a PNG sequence). The
/// caller renders each frame (the view's grabFramebuffer or an OffscreenRenderer) on the GUI
/// thread; this file plans the times, and a worker thread streams the images to a FrameSink that
/// cleans up on cancel or error, so a half-written result never stays on disk.

#include "analysis/core/result.h"

#include <QImage>
#include <QSize>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

namespace bunraku::app {

enum class VideoFormat {
    Mp4,         ///< one .mp4 file, H.264 (libx264, yuv420p) encoded by ffmpeg on PATH
    PngSequence, ///< a folder of frame_00000.png, frame_00001.png, ...
};

struct VideoExportOptions {
    VideoFormat format = VideoFormat::Mp4;
    int firstFrame = 0; ///< first exported frame of take A (at the take's rate), inclusive
    int lastFrame = -1; ///< last exported frame of take A, inclusive; -1 = the end of the take
    double fps = 0.0;   ///< frames per second of the output; 0 = the take's own rate
    QSize size;         ///< output pixels; empty = the 3D view's size (made even for MP4)
    QString output;     ///< the .mp4 file, or the folder for the PNG frames
    /// PNG only: replace the frame_*.png already in the output folder (all of them, once the new
    /// sequence is complete). Without it an export into a folder holding frames is refused.
    bool overwrite = false;
};

struct VideoExportResult {
    int frames = 0;         ///< frames in the finished output (0 on error or cancel)
    QString output;         ///< the file or folder written
    QString error;          ///< what went wrong, for a person; empty on success and on cancel
    bool cancelled = false; ///< the user stopped it; nothing was left on disk
    bool ok() const { return error.isEmpty() && !cancelled; }
};

/// The frames of one export.
struct FramePlan {
    std::vector<double> times; ///< seconds on the document's timeline, increasing
    double fps = 0.0;          ///< frames per second of the output
    double rateHz = 0.0;       ///< take A's frame rate (names the take frame in messages)
};

/// From firstFrame / rateHz to lastFrame / rateHz (both included when on the grid) in steps of
/// 1 / fps; fps <= 0 exports every take frame at the take's rate. Empty when lastFrame <
/// firstFrame or rateHz <= 0. A higher fps repeats take frames (the view shows the nearest one).
FramePlan planFrames(double rateHz, int firstFrame, int lastFrame, double fps);

/// Where the frames of one export go. open() once, write() each frame (all of the size given to
/// open), then finish() to publish the result, or abort() to remove everything written.
class FrameSink {
public:
    virtual ~FrameSink() = default;
    virtual analysis::Status open(QSize size, double fps) = 0;
    virtual analysis::Status write(const QImage& image) = 0;
    virtual analysis::Status finish() = 0;
    virtual void abort() = 0;
};

/// "1 frame", "10 frames": for messages.
QString frameCountText(int count);

/// The frame_*.png files already in `folder` (file names, sorted); empty when it does not exist.
QStringList existingFrames(const QString& folder);

/// PNG files frame_00000.png ... in `folder`, built in a hidden folder beside it and swapped in
/// by finish() (analysis/io/staged_folder.h): the folder then holds exactly the new sequence. An
/// aborted export leaves the folder as it was. open() refuses a folder that already holds
/// frame_*.png unless `overwrite`, and always one holding files this program did not write there.
std::unique_ptr<FrameSink> makePngSequenceSink(const QString& folder, bool overwrite = false);

/// Renders the scene at `seconds`: the image, or why there is none (the view hidden, its OpenGL
/// context lost...), which stops the export with an error naming the take frame.
using FrameRenderer = std::function<analysis::Result<QImage>(double seconds)>;
/// Called on the GUI thread before each frame and after the last with (frames done, total);
/// false cancels.
using ExportProgress = std::function<bool(int done, int total)>;

/// Why the export cannot start (no output, an empty range, no ffmpeg, a folder of earlier frames
/// without overwrite or of someone else's files, a tiny size); empty when it can.
QString exportRefusal(const VideoExportOptions& options, const FramePlan& plan);

/// Renders the planned frames into the sink of `options` (MP4 or PNG; options.fps and the range
/// are already in `plan`) as a VideoExportJob (video_export_job.h): frames are rendered on this
/// thread while a local event loop runs, and encoded and written by a worker thread. Every image
/// is brought to options.size (the first image's size when empty, cropped to even dimensions for
/// MP4). Checks for ffmpeg before rendering.
VideoExportResult exportFrames(const VideoExportOptions& options, const FramePlan& plan,
                               const FrameRenderer& render, const ExportProgress& progress = {});

} // namespace bunraku::app
