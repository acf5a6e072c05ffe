#include "app/video_export.h"

#include "app/ffmpeg_encoder.h"
#include "app/image_file.h"
#include "app/video_export_job.h"

#include "analysis/io/staged_folder.h"

#include <QDir>
#include <QEventLoop>
#include <QObject>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string_view>

namespace bunraku::app {
namespace {

using analysis::ErrorCode;

QString oldFramesMessage(const QString& folder, int count)
{
    return QObject::tr("the folder %1 already holds %2 (frame_*.png) of an earlier export: choose another folder, "
                       "or allow replacing them")
        .arg(folder, frameCountText(count));
}

/// Frames built in a hidden folder beside the target (analysis/io/staged_folder.h) and swapped
/// in by finish(): the target holds the earlier export or the new one, never a mix; a folder
/// holding files this program did not write there is refused, naming them.
class PngSequenceSink final : public FrameSink {
public:
    PngSequenceSink(QString folder, bool overwrite) : m_folder(std::move(folder)), m_overwrite(overwrite) {}
    PngSequenceSink(const PngSequenceSink&) = delete;
    PngSequenceSink& operator=(const PngSequenceSink&) = delete;

    analysis::Status open(QSize, double) override
    {
        if (auto status = checkOldFrames(); !status.ok()) return status;
        auto staged = analysis::io::StagedFolder::begin(std::filesystem::path(m_folder.toStdString()));
        if (!staged) return staged.error();
        m_staged.emplace(std::move(staged).value());
        m_count = 0;
        return analysis::okStatus();
    }

    analysis::Status write(const QImage& image) override
    {
        if (!m_staged) return ioError(QObject::tr("the PNG sequence in %1 is not open").arg(m_folder));
        const QString name = frameName(m_count);
        auto bytes = encodeImage(image, QDir(m_folder).filePath(name), "PNG");
        if (!bytes) return bytes.error();
        if (auto written = m_staged->writeFile(name.toStdString(), std::string_view(bytes->constData(), std::size_t(bytes->size())));
            !written)
            return written;
        ++m_count;
        return analysis::okStatus();
    }

    analysis::Status finish() override
    {
        if (!m_staged) return ioError(QObject::tr("the PNG sequence in %1 is not open").arg(m_folder));
        if (auto status = checkOldFrames(); !status.ok()) return status; // frames appeared meanwhile
        auto committed = m_staged->commit();
        m_staged.reset();
        return committed;
    }

    void abort() override { m_staged.reset(); } // removes the staging folder and the frames in it

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
    std::optional<analysis::io::StagedFolder> m_staged;
    int m_count = 0;
};

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

QString exportRefusal(const VideoExportOptions& options, const FramePlan& plan)
{
    if (options.output.isEmpty())
        return QObject::tr("no output %1 was given")
            .arg(options.format == VideoFormat::Mp4 ? QObject::tr("file") : QObject::tr("folder"));
    if (plan.times.empty()) return QObject::tr("the frame range is empty");
    if (options.format == VideoFormat::Mp4 && findFfmpeg().isEmpty()) return ffmpegMissingMessage();
    if (options.format == VideoFormat::PngSequence) {
        if (!options.overwrite)
            if (const auto old = existingFrames(options.output).size(); old > 0) return oldFramesMessage(options.output, int(old));
        if (auto replaceable = analysis::io::checkReplaceableFolder(std::filesystem::path(options.output.toStdString())); !replaceable)
            return QString::fromStdString(replaceable.error().message);
    }
    if (!options.size.isEmpty() && (options.size.width() < 16 || options.size.height() < 16))
        return QObject::tr("%1x%2 pixels is too small for a video").arg(options.size.width()).arg(options.size.height());
    return {};
}

VideoExportResult exportFrames(const VideoExportOptions& options, const FramePlan& plan, const FrameRenderer& render,
                               const ExportProgress& progress)
{
    if (const QString refused = exportRefusal(options, plan); !refused.isEmpty()) return failed(nullptr, refused);
    // The export runs as a job: this thread renders a frame per turn of a local event loop (timers,
    // repaints and the progress dialog's Cancel keep working), a worker writes them.
    VideoExportJob job(options, plan, render);
    QEventLoop loop;
    QObject::connect(&job, &VideoExportJob::progress, &job, [&job, &progress](int done, int total) {
        if (progress && !progress(done, total)) job.cancel();
    });
    QObject::connect(&job, &VideoExportJob::finished, &loop, &QEventLoop::quit);
    job.start();
    loop.exec();
    return job.result();
}

} // namespace bunraku::app
