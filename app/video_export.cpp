#include "app/video_export.h"

#include "app/ffmpeg_encoder.h"

#include <QDir>
#include <QFile>
#include <QObject>
#include <QSaveFile>
#include <QSet>
#include <QTemporaryDir>

#include <cmath>
#include <filesystem>
#include <system_error>

namespace bunraku::app {
namespace {

using analysis::ErrorCode;

QString oldFramesMessage(const QString& folder, int count)
{
    return QObject::tr("the folder %1 already holds %2 (frame_*.png) of an earlier export: choose another folder, "
                       "or allow replacing them")
        .arg(folder, frameCountText(count));
}

/// Frames in a hidden staging folder inside the target, moved into place only by finish().
class PngSequenceSink final : public FrameSink {
public:
    PngSequenceSink(QString folder, bool overwrite) : m_folder(std::move(folder)), m_overwrite(overwrite) {}
    ~PngSequenceSink() override
    {
        if (!m_finished) abort();
    }
    PngSequenceSink(const PngSequenceSink&) = delete;
    PngSequenceSink& operator=(const PngSequenceSink&) = delete;

    analysis::Status open(QSize, double) override
    {
        const QDir dir(m_folder);
        if (!dir.exists()) {
            if (!QDir().mkpath(m_folder)) return ioError(QObject::tr("cannot create the folder %1").arg(m_folder));
            m_createdFolder = true;
        }
        if (auto status = checkOldFrames(); !status.ok()) return status;
        m_staging = std::make_unique<QTemporaryDir>(dir.filePath(QStringLiteral(".partial-XXXXXX")));
        if (!m_staging->isValid())
            return ioError(QObject::tr("cannot create a temporary folder in %1: %2").arg(m_folder, m_staging->errorString()));
        m_count = 0;
        return analysis::okStatus();
    }

    analysis::Status write(const QImage& image) override
    {
        if (!m_staging) return ioError(QObject::tr("the PNG sequence in %1 is not open").arg(m_folder));
        const QString path = QDir(m_staging->path()).filePath(frameName(m_count));
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit())
            return ioError(QObject::tr("cannot write %1: %2").arg(path, file.errorString()));
        ++m_count;
        return analysis::okStatus();
    }

    analysis::Status finish() override
    {
        if (!m_staging) return ioError(QObject::tr("the PNG sequence in %1 is not open").arg(m_folder));
        if (auto status = checkOldFrames(); !status.ok()) return status; // frames appeared meanwhile
        const QDir dir(m_folder);
        // The new sequence is complete: only now do the old frames go (those not replaced below).
        QSet<QString> fresh;
        for (int i = 0; i < m_count; ++i) fresh.insert(frameName(i));
        for (const QString& old : existingFrames(m_folder))
            if (!fresh.contains(old) && !QFile::remove(dir.filePath(old)))
                return ioError(QObject::tr("cannot remove the old frame %1").arg(dir.filePath(old)));
        for (int i = 0; i < m_count; ++i) {
            // rename(2) replaces an old frame of the same name atomically.
            std::error_code error;
            const QString target = dir.filePath(frameName(i));
            std::filesystem::rename(std::filesystem::path(QDir(m_staging->path()).filePath(frameName(i)).toStdString()),
                                    std::filesystem::path(target.toStdString()), error);
            if (error) return ioError(QObject::tr("cannot write %1: %2").arg(target, QString::fromStdString(error.message())));
        }
        m_staging.reset();
        m_finished = true;
        return analysis::okStatus();
    }

    void abort() override
    {
        m_staging.reset(); // removes the staging folder and the frames in it
        if (m_createdFolder && !m_finished) QDir().rmdir(m_folder); // only when empty
        m_createdFolder = false;
    }

private:
    static QString frameName(int index) { return QStringLiteral("frame_%1.png").arg(index, 5, 10, QLatin1Char('0')); }
    static analysis::Error ioError(const QString& message) { return analysis::makeError(ErrorCode::Io, message.toStdString()); }

    analysis::Status checkOldFrames() const
    {
        if (m_overwrite) return analysis::okStatus();
        const auto old = existingFrames(m_folder).size();
        if (old == 0) return analysis::okStatus();
        return analysis::makeError(ErrorCode::InvalidArgument, oldFramesMessage(m_folder, int(old)).toStdString());
    }

    QString m_folder;
    bool m_overwrite = false;
    bool m_createdFolder = false; ///< open() made m_folder: abort() removes it again when empty
    bool m_finished = false;
    std::unique_ptr<QTemporaryDir> m_staging;
    int m_count = 0;
};

/// The first frame fixes the size: the asked one, else the rendered one (even for H.264).
QSize outputSize(const VideoExportOptions& options, QSize rendered)
{
    QSize size = options.size.isEmpty() ? rendered : options.size;
    if (options.format == VideoFormat::Mp4) size = QSize(size.width() & ~1, size.height() & ~1);
    return size;
}

/// `image` at exactly `size`: cropped when it is at most a pixel larger (an odd view made even),
/// else scaled (a view resized during the export).
QImage fitted(const QImage& image, QSize size)
{
    if (image.size() == size) return image;
    const QSize extra = image.size() - size;
    if (extra.width() >= 0 && extra.height() >= 0 && extra.width() <= 1 && extra.height() <= 1)
        return image.copy(0, 0, size.width(), size.height());
    return image.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
}

VideoExportResult failed(FrameSink* sink, const QString& error)
{
    if (sink) sink->abort();
    VideoExportResult result;
    result.error = error;
    return result;
}

} // namespace

FramePlan planFrames(double rateHz, int firstFrame, int lastFrame, double fps)
{
    FramePlan plan;
    if (!(rateHz > 0.0) || firstFrame < 0 || lastFrame < firstFrame) return plan;
    plan.fps = fps > 0.0 ? fps : rateHz;
    plan.rateHz = rateHz;
    const double start = firstFrame / rateHz;
    const double span = (lastFrame - firstFrame) / rateHz;
    // The small tolerance keeps the last take frame when span * fps is an integer up to rounding.
    const auto count = static_cast<long>(std::floor(span * plan.fps + 1e-9)) + 1;
    plan.times.reserve(std::size_t(count));
    for (long i = 0; i < count; ++i) plan.times.push_back(fps > 0.0 ? start + double(i) / fps : (firstFrame + i) / rateHz);
    return plan;
}

QString frameCountText(int count)
{
    return count == 1 ? QObject::tr("1 frame") : QObject::tr("%1 frames").arg(count);
}

QStringList existingFrames(const QString& folder)
{
    if (folder.isEmpty()) return {};
    return QDir(folder).entryList({QStringLiteral("frame_*.png")}, QDir::Files | QDir::Hidden, QDir::Name);
}

std::unique_ptr<FrameSink> makePngSequenceSink(const QString& folder, bool overwrite)
{
    return std::make_unique<PngSequenceSink>(folder, overwrite);
}

VideoExportResult exportFrames(const VideoExportOptions& options, const FramePlan& plan, const FrameRenderer& render,
                               const ExportProgress& progress)
{
    if (options.output.isEmpty()) return failed(nullptr, QObject::tr("no output %1 was given")
                                                             .arg(options.format == VideoFormat::Mp4 ? QObject::tr("file")
                                                                                                     : QObject::tr("folder")));
    if (plan.times.empty()) return failed(nullptr, QObject::tr("the frame range is empty"));
    if (options.format == VideoFormat::Mp4 && findFfmpeg().isEmpty()) return failed(nullptr, ffmpegMissingMessage());
    if (options.format == VideoFormat::PngSequence && !options.overwrite)
        if (const auto old = existingFrames(options.output).size(); old > 0)
            return failed(nullptr, oldFramesMessage(options.output, int(old)));
    if (!options.size.isEmpty() && (options.size.width() < 16 || options.size.height() < 16))
        return failed(nullptr, QObject::tr("%1x%2 pixels is too small for a video")
                                   .arg(options.size.width()).arg(options.size.height()));

    std::unique_ptr<FrameSink> sink;
    if (options.format == VideoFormat::Mp4)
        sink = std::make_unique<FfmpegEncoder>(options.output);
    else
        sink = makePngSequenceSink(options.output, options.overwrite);

    const int total = int(plan.times.size());
    QSize size;
    for (int i = 0; i < total; ++i) {
        if (progress && !progress(i, total)) {
            sink->abort();
            VideoExportResult result;
            result.cancelled = true;
            return result;
        }
        const double seconds = plan.times[std::size_t(i)];
        const analysis::Result<QImage> rendered = render(seconds);
        if (!rendered.ok() || rendered->isNull()) {
            const QString why = rendered.ok() ? QObject::tr("the renderer returned an empty image")
                                              : QString::fromStdString(rendered.error().message);
            return failed(sink.get(), QObject::tr("no image of the 3D view for take A frame %1 (%2 s; video frame %3 of %4): %5")
                                          .arg(std::lround(seconds * plan.rateHz))
                                          .arg(seconds, 0, 'f', 3)
                                          .arg(i + 1)
                                          .arg(total)
                                          .arg(why));
        }
        const QImage& image = rendered.value();
        if (i == 0) {
            size = outputSize(options, image.size());
            if (size.width() < 2 || size.height() < 2) return failed(sink.get(), QObject::tr("the 3D view is too small"));
            if (auto status = sink->open(size, plan.fps); !status.ok())
                return failed(sink.get(), QString::fromStdString(status.error().message));
        }
        if (auto status = sink->write(fitted(image, size)); !status.ok())
            return failed(sink.get(), QString::fromStdString(status.error().message));
    }
    if (progress && !progress(total, total)) {
        sink->abort();
        VideoExportResult result;
        result.cancelled = true;
        return result;
    }
    if (auto status = sink->finish(); !status.ok()) return failed(sink.get(), QString::fromStdString(status.error().message));
    VideoExportResult result;
    result.frames = total;
    result.output = options.output;
    return result;
}

} // namespace bunraku::app
