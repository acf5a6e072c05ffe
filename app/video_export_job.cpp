#include "app/video_export_job.h"

#include "app/ffmpeg_encoder.h"

#include <QTimer>

#include <cmath>

namespace bunraku::app {

QSize videoOutputSize(const VideoExportOptions& options, QSize rendered)
{
    QSize size = options.size.isEmpty() ? rendered : options.size;
    if (options.format == VideoFormat::Mp4) size = QSize(size.width() & ~1, size.height() & ~1);
    return size;
}

QImage fittedFrame(const QImage& image, QSize size)
{
    if (image.size() == size) return image;
    const QSize extra = image.size() - size;
    if (extra.width() >= 0 && extra.height() >= 0 && extra.width() <= 1 && extra.height() <= 1)
        return image.copy(0, 0, size.width(), size.height());
    return image.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
}

VideoExportJob::VideoExportJob(VideoExportOptions options, FramePlan plan, FrameRenderer render, QObject* parent)
    : QObject(parent), m_options(std::move(options)), m_plan(std::move(plan)), m_render(std::move(render))
{
}

VideoExportJob::~VideoExportJob()
{
    requestCancel();
    if (m_worker.joinable()) m_worker.join();
}

void VideoExportJob::start()
{
    if (m_started) return;
    m_started = true;
    m_worker = std::thread([this] { workerLoop(); });
    m_renderScheduled = true;
    QTimer::singleShot(0, this, &VideoExportJob::renderNext);
}

void VideoExportJob::cancel()
{
    if (!m_started || m_done || m_pending) return;
    m_pending = VideoExportResult{};
    m_pending->cancelled = true;
    requestCancel();
}

void VideoExportJob::requestCancel()
{
    // Set under the mutex: the worker tests m_cancel under it before it sleeps, so the wake-up
    // cannot fall between its test and its sleep (a worker that slept through it would keep an
    // export or the destructor's join waiting for a wake-up that never comes).
    {
        std::lock_guard lock(m_mutex);
        m_cancel = true;
    }
    m_wake.notify_all();
}

void VideoExportJob::renderNext()
{
    m_renderScheduled = false;
    if (m_done || m_pending) return;
    const int total = int(m_plan.times.size());
    if (m_lastQueued) return;
    {
        std::lock_guard lock(m_mutex);
        if (m_workerExited || int(m_queue.size()) >= kFramesInFlight) return;
    }
    emit progress(m_next, total); // a listener may cancel here
    if (m_pending) return;
    const double seconds = m_plan.times[std::size_t(m_next)];
    const analysis::Result<QImage> rendered = m_render(seconds);
    if (!rendered.ok() || rendered->isNull()) {
        const QString why = rendered.ok() ? tr("the renderer returned an empty image") : QString::fromStdString(rendered.error().message);
        stopWithError(tr("no image of the 3D view for take A frame %1 (%2 s; video frame %3 of %4): %5")
                          .arg(std::lround(seconds * m_plan.rateHz))
                          .arg(seconds, 0, 'f', 3)
                          .arg(m_next + 1)
                          .arg(total)
                          .arg(why));
        return;
    }
    if (m_next == 0) {
        m_size = videoOutputSize(m_options, rendered->size());
        if (m_size.width() < 2 || m_size.height() < 2) {
            stopWithError(tr("the 3D view is too small"));
            return;
        }
    }
    Frame frame{fittedFrame(rendered.value(), m_size), m_next};
    ++m_next;
    {
        std::lock_guard lock(m_mutex);
        m_queue.push_back(std::move(frame));
    }
    m_wake.notify_all();
    if (m_next == total) {
        m_lastQueued = true;
        emit progress(total, total); // the last chance to cancel before the result is published
        if (m_pending) return;
        {
            std::lock_guard lock(m_mutex);
            m_finishAllowed = true;
        }
        m_wake.notify_all();
        return;
    }
    m_renderScheduled = true;
    QTimer::singleShot(0, this, &VideoExportJob::renderNext);
}

void VideoExportJob::stopWithError(const QString& error)
{
    m_pending = VideoExportResult{};
    m_pending->error = error;
    requestCancel();
}

std::unique_ptr<FrameSink> VideoExportJob::makeSink() const
{
    if (m_options.format == VideoFormat::Mp4) {
        auto encoder = std::make_unique<FfmpegEncoder>(m_options.output);
        encoder->setCancelFlag(&m_cancel);
        return encoder;
    }
    return makePngSequenceSink(m_options.output, m_options.overwrite);
}

void VideoExportJob::workerLoop()
{
    // The sink lives and dies in this thread (ffmpeg's QProcess included).
    std::unique_ptr<FrameSink> sink = makeSink();
    bool opened = false;
    QString error;
    bool finished = false;
    while (true) {
        Frame frame;
        bool finishNow = false;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_cancel || !m_queue.empty() || m_finishAllowed; });
            if (m_cancel) break;
            if (!m_queue.empty()) {
                frame = std::move(m_queue.front());
                m_queue.pop_front();
            } else {
                finishNow = true;
            }
        }
        if (finishNow) {
            if (auto status = sink->finish(); !status.ok()) error = QString::fromStdString(status.error().message);
            else finished = true;
            break;
        }
        if (!opened) {
            if (auto status = sink->open(m_size, m_plan.fps); !status.ok()) {
                error = QString::fromStdString(status.error().message);
                break;
            }
            opened = true;
        }
        if (auto status = sink->write(frame.image); !status.ok()) {
            error = QString::fromStdString(status.error().message);
            break;
        }
        QMetaObject::invokeMethod(this, [this] { workerReported(); }, Qt::QueuedConnection);
    }
    if (!finished) sink->abort();
    sink.reset();
    {
        std::lock_guard lock(m_mutex);
        m_workerError = error;
        m_workerSucceeded = finished;
        m_workerExited = true;
    }
    QMetaObject::invokeMethod(this, [this] { workerReported(); }, Qt::QueuedConnection);
}

void VideoExportJob::workerReported()
{
    if (m_done) return;
    bool exited = false, succeeded = false;
    QString error;
    {
        std::lock_guard lock(m_mutex);
        exited = m_workerExited;
        succeeded = m_workerSucceeded;
        error = m_workerError;
    }
    if (!exited) {
        if (!m_renderScheduled && !m_pending) {
            m_renderScheduled = true;
            QTimer::singleShot(0, this, &VideoExportJob::renderNext);
        }
        return;
    }
    if (m_worker.joinable()) m_worker.join(); // it has returned: this does not wait
    VideoExportResult result;
    if (succeeded) { // published: a cancel that came too late changes nothing
        result.frames = int(m_plan.times.size());
        result.output = m_options.output;
    } else if (m_pending) {
        result = *m_pending;
    } else {
        result.error = error.isEmpty() ? tr("the export stopped without a result") : error;
    }
    m_done = true;
    m_result = result;
    emit finished(m_result);
}

} // namespace bunraku::app
