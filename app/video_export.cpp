#include "app/video_export.h"

#include "app/ffmpeg_encoder.h"

#include <QDir>
#include <QFile>
#include <QObject>
#include <QSaveFile>

#include <cmath>

namespace bunraku::app {
namespace {

using analysis::ErrorCode;

class PngSequenceSink final : public FrameSink {
public:
    explicit PngSequenceSink(QString folder) : m_folder(std::move(folder)) {}

    analysis::Status open(QSize, double) override
    {
        if (!QDir().mkpath(m_folder))
            return analysis::makeError(ErrorCode::Io, QObject::tr("cannot create the folder %1").arg(m_folder).toStdString());
        return analysis::okStatus();
    }

    analysis::Status write(const QImage& image) override
    {
        const QString path =
            QDir(m_folder).filePath(QStringLiteral("frame_%1.png").arg(m_written.size(), 5, 10, QLatin1Char('0')));
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit())
            return analysis::makeError(ErrorCode::Io,
                                       QObject::tr("cannot write %1: %2").arg(path, file.errorString()).toStdString());
        m_written << path;
        return analysis::okStatus();
    }

    analysis::Status finish() override { return analysis::okStatus(); }

    void abort() override
    {
        for (const QString& path : std::as_const(m_written)) QFile::remove(path);
        m_written.clear();
    }

private:
    QString m_folder;
    QStringList m_written;
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
    const double start = firstFrame / rateHz;
    const double span = (lastFrame - firstFrame) / rateHz;
    // The small tolerance keeps the last take frame when span * fps is an integer up to rounding.
    const auto count = static_cast<long>(std::floor(span * plan.fps + 1e-9)) + 1;
    plan.times.reserve(std::size_t(count));
    for (long i = 0; i < count; ++i) plan.times.push_back(fps > 0.0 ? start + double(i) / fps : (firstFrame + i) / rateHz);
    return plan;
}

std::unique_ptr<FrameSink> makePngSequenceSink(const QString& folder) { return std::make_unique<PngSequenceSink>(folder); }

VideoExportResult exportFrames(const VideoExportOptions& options, const FramePlan& plan, const FrameRenderer& render,
                               const ExportProgress& progress)
{
    if (options.output.isEmpty()) return failed(nullptr, QObject::tr("no output %1 was given")
                                                             .arg(options.format == VideoFormat::Mp4 ? QObject::tr("file")
                                                                                                     : QObject::tr("folder")));
    if (plan.times.empty()) return failed(nullptr, QObject::tr("the frame range is empty"));
    if (options.format == VideoFormat::Mp4 && findFfmpeg().isEmpty()) return failed(nullptr, ffmpegMissingMessage());
    if (!options.size.isEmpty() && (options.size.width() < 16 || options.size.height() < 16))
        return failed(nullptr, QObject::tr("%1x%2 pixels is too small for a video")
                                   .arg(options.size.width()).arg(options.size.height()));

    std::unique_ptr<FrameSink> sink;
    if (options.format == VideoFormat::Mp4)
        sink = std::make_unique<FfmpegEncoder>(options.output);
    else
        sink = makePngSequenceSink(options.output);

    const int total = int(plan.times.size());
    QSize size;
    for (int i = 0; i < total; ++i) {
        if (progress && !progress(i, total)) {
            sink->abort();
            VideoExportResult result;
            result.cancelled = true;
            return result;
        }
        const QImage image = render(plan.times[std::size_t(i)]);
        if (image.isNull())
            return failed(sink.get(), QObject::tr("the 3D view produced no image for frame %1 (is it shown?)").arg(i));
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
