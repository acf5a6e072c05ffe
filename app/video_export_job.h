#pragma once
/// One video export running without blocking the GUI: the frames are rendered on the GUI thread
/// one per turn of the event loop (the view's pose is the document's), and handed to a worker
/// thread that encodes and writes them (PNG files into a staged folder, or raw frames piped to
/// ffmpeg). At most kFramesInFlight frames wait between the two, so memory stays small. Cancel
/// and errors stop both sides; nothing half-written is left (video_export.h's sinks).

#include "app/video_export.h"

#include <QObject>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace bunraku::app {

class VideoExportJob : public QObject {
    Q_OBJECT
public:
    static constexpr int kFramesInFlight = 3;

    /// `render` is called on the GUI thread; the sink of `options` is made in the worker.
    VideoExportJob(VideoExportOptions options, FramePlan plan, FrameRenderer render, QObject* parent = nullptr);
    /// Cancels a running export and waits for the worker (which only checks for cancellation
    /// between frames and while ffmpeg finishes).
    ~VideoExportJob() override;

    VideoExportJob(const VideoExportJob&) = delete;
    VideoExportJob& operator=(const VideoExportJob&) = delete;

    /// Starts rendering at the next turn of the event loop; finished() follows exactly once.
    void start();
    /// Stops the export; finished() reports it cancelled (and nothing is left on disk).
    void cancel();
    bool running() const { return m_started && !m_done; }
    /// The outcome, valid after finished().
    const VideoExportResult& result() const { return m_result; }

signals:
    /// Before each frame is rendered, and once all are written: (frames done, total).
    void progress(int done, int total);
    void finished(const bunraku::app::VideoExportResult& result);

private:
    struct Frame {
        QImage image;
        int index = 0;
    };

    void renderNext();
    /// Stops the worker; finished() reports `error` once it has exited.
    void stopWithError(const QString& error);
    /// Tells the worker to stop (m_cancel, set under m_mutex) and wakes it.
    void requestCancel();
    std::unique_ptr<FrameSink> makeSink() const;
    void workerLoop();
    /// Called on the GUI thread when the worker consumed a frame, failed or finished.
    void workerReported();

    VideoExportOptions m_options;
    FramePlan m_plan;
    FrameRenderer m_render;
    QSize m_size;
    int m_next = 0;
    bool m_started = false;
    bool m_done = false;
    bool m_renderScheduled = false;
    bool m_lastQueued = false;                  ///< every frame was rendered and handed over
    std::optional<VideoExportResult> m_pending; ///< cancelled or failed on this side: reported once the worker exits
    VideoExportResult m_result;

    // Shared with the worker, under m_mutex.
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<Frame> m_queue;
    bool m_finishAllowed = false;   ///< all frames handed over and not cancelled: publish when written
    bool m_workerExited = false;
    bool m_workerSucceeded = false; ///< the sink published the output
    QString m_workerError;
    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

/// The size frames are written at: options.size, else the first rendered image's (made even for
/// MP4).
QSize videoOutputSize(const VideoExportOptions& options, QSize rendered);
/// `image` at exactly `size`: cropped when it is at most a pixel larger (an odd view made even),
/// else scaled (a view resized during the export).
QImage fittedFrame(const QImage& image, QSize size);

} // namespace bunraku::app
