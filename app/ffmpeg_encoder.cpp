#include "app/ffmpeg_encoder.h"

#include "analysis/io/atomic_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <filesystem>
#include <system_error>

namespace bunraku::app {
namespace {

using analysis::ErrorCode;

constexpr int kStartTimeoutMs = 10000;
constexpr int kWriteTimeoutMs = 60000;     ///< ffmpeg not taking a frame for a minute is a hang
constexpr int kFinishTimeoutMs = 600000;   ///< flushing the encoder's last frames
constexpr qsizetype kErrorBytesKept = 16384;
constexpr int kErrorLinesShown = 6;

analysis::Error errorOf(ErrorCode code, const QString& message) { return analysis::makeError(code, message.toStdString()); }

} // namespace

QString findFfmpeg() { return QStandardPaths::findExecutable(QStringLiteral("ffmpeg")); }

QString ffmpegMissingMessage()
{
    return QObject::tr("MP4 export needs ffmpeg, which was not found on PATH. Install it (Debian/Ubuntu: "
                       "sudo apt-get install ffmpeg) or export a PNG sequence instead.");
}

FfmpegEncoder::FfmpegEncoder(QString output) : m_output(std::move(output)) {}

FfmpegEncoder::~FfmpegEncoder() { abort(); }

analysis::Status FfmpegEncoder::open(QSize size, double fps)
{
    const QString program = findFfmpeg();
    if (program.isEmpty()) return errorOf(ErrorCode::NotFound, ffmpegMissingMessage());
    if (size.isEmpty() || size.width() % 2 != 0 || size.height() % 2 != 0)
        return errorOf(ErrorCode::InvalidArgument,
                       QObject::tr("H.264 needs an even width and height, not %1x%2").arg(size.width()).arg(size.height()));
    if (!(fps > 0.0)) return errorOf(ErrorCode::InvalidArgument, QObject::tr("the frame rate must be positive"));
    if (!QDir().mkpath(QFileInfo(m_output).absolutePath()))
        return errorOf(ErrorCode::Io, QObject::tr("cannot create the folder of %1").arg(m_output));
    // A fresh private folder beside the output: ffmpeg creates the file in it itself (no name is
    // reserved, deleted and handed over), and nothing of the user's is touched until the move.
    removeTemporaryFolder();
    const std::filesystem::path target(QFileInfo(m_output).absoluteFilePath().toStdString());
    auto folder = analysis::io::makeTemporaryFolderBeside(target);
    if (!folder) return folder.error();
    m_temporaryFolder = QString::fromStdString(folder->string());
    m_temporary = QDir(m_temporaryFolder).filePath(QFileInfo(m_output).fileName());
    m_size = size;
    m_errors.clear();
    m_row.resize(qsizetype(size.width()) * size.height() * 3);
    const QStringList arguments{
        QStringLiteral("-hide_banner"), QStringLiteral("-loglevel"), QStringLiteral("error"), QStringLiteral("-n"),
        // input: raw packed RGB frames on stdin
        QStringLiteral("-f"), QStringLiteral("rawvideo"), QStringLiteral("-pix_fmt"), QStringLiteral("rgb24"),
        QStringLiteral("-s"), QStringLiteral("%1x%2").arg(size.width()).arg(size.height()),
        QStringLiteral("-framerate"), QString::number(fps, 'g', 10), QStringLiteral("-i"), QStringLiteral("-"),
        // output: H.264 in MP4 that every player opens
        QStringLiteral("-an"), QStringLiteral("-c:v"), QStringLiteral("libx264"), QStringLiteral("-crf"),
        QStringLiteral("18"), QStringLiteral("-pix_fmt"), QStringLiteral("yuv420p"), QStringLiteral("-movflags"),
        QStringLiteral("+faststart"), QStringLiteral("-f"), QStringLiteral("mp4"), m_temporary};
    m_process.setStandardOutputFile(QProcess::nullDevice());
    m_process.setProcessChannelMode(QProcess::SeparateChannels);
    m_process.start(program, arguments);
    if (!m_process.waitForStarted(kStartTimeoutMs))
        return failure(QObject::tr("could not start %1: %2").arg(program, m_process.errorString()));
    return analysis::okStatus();
}

analysis::Status FfmpegEncoder::write(const QImage& image)
{
    if (m_process.state() != QProcess::Running) return failure(QObject::tr("ffmpeg stopped before the last frame"));
    if (image.size() != m_size)
        return failure(QObject::tr("a frame of %1x%2 pixels in a video of %3x%4")
                           .arg(image.width()).arg(image.height()).arg(m_size.width()).arg(m_size.height()));
    const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
    const qsizetype rowBytes = qsizetype(m_size.width()) * 3;
    for (int y = 0; y < m_size.height(); ++y) // QImage pads rows to 4 bytes; ffmpeg wants them packed
        std::copy_n(reinterpret_cast<const char*>(rgb.constScanLine(y)), rowBytes, m_row.data() + y * rowBytes);
    if (m_process.write(m_row) != m_row.size()) return failure(QObject::tr("could not send a frame to ffmpeg"));
    // At most two frames wait in our buffer: memory stays small and a dead ffmpeg shows at once.
    if (!waitWhile([this] { return m_process.bytesToWrite() <= 2 * m_row.size() || m_process.state() != QProcess::Running; },
                   kWriteTimeoutMs) ||
        m_process.bytesToWrite() > 2 * m_row.size())
        return failure(m_cancel && *m_cancel ? QObject::tr("cancelled")
                       : m_process.state() == QProcess::Running ? QObject::tr("ffmpeg stopped accepting frames")
                                                                : QObject::tr("ffmpeg stopped before the last frame"));
    m_errors += m_process.readAllStandardError();
    if (m_errors.size() > kErrorBytesKept) m_errors = m_errors.right(kErrorBytesKept);
    return analysis::okStatus();
}

analysis::Status FfmpegEncoder::finish()
{
    if (m_process.state() == QProcess::NotRunning) return failure(QObject::tr("ffmpeg is not running"));
    m_process.closeWriteChannel();
    if (!waitWhile([this] { return m_process.state() == QProcess::NotRunning; }, kFinishTimeoutMs))
        return failure(m_cancel && *m_cancel ? QObject::tr("cancelled") : QObject::tr("ffmpeg did not finish"));
    if (m_process.exitStatus() != QProcess::NormalExit || m_process.exitCode() != 0)
        return failure(QObject::tr("ffmpeg failed (exit code %1)").arg(m_process.exitCode()));
    if (!QFileInfo::exists(m_temporary)) return failure(QObject::tr("ffmpeg wrote no file"));
    // rename(2) replaces an existing output atomically: a player never sees half a file; the
    // file and its folder are flushed to the disk first and after.
    const auto moved = analysis::io::moveIntoPlace(std::filesystem::path(m_temporary.toStdString()),
                                                   std::filesystem::path(QFileInfo(m_output).absoluteFilePath().toStdString()));
    if (!moved) return failure(QString::fromStdString(moved.error().message));
    m_temporary.clear(); // it is the output now
    removeTemporaryFolder();
    return analysis::okStatus();
}

void FfmpegEncoder::abort()
{
    if (m_process.state() != QProcess::NotRunning) {
        m_process.kill();
        m_process.waitForFinished(kStartTimeoutMs);
    }
    removeTemporaryFolder();
}

bool FfmpegEncoder::waitWhile(const std::function<bool()>& done, int timeoutMs)
{
    constexpr int kSliceMs = 50;
    for (int waited = 0; !done(); waited += kSliceMs) {
        if ((m_cancel && *m_cancel) || waited >= timeoutMs) return false;
        if (m_process.state() == QProcess::NotRunning) return done();
        if (m_process.bytesToWrite() > 0) m_process.waitForBytesWritten(kSliceMs);
        else m_process.waitForFinished(kSliceMs);
    }
    return true;
}

void FfmpegEncoder::removeTemporaryFolder()
{
    if (!m_temporaryFolder.isEmpty()) QDir(m_temporaryFolder).removeRecursively();
    m_temporaryFolder.clear();
    m_temporary.clear();
}

QString FfmpegEncoder::errorTail()
{
    m_errors += m_process.readAllStandardError();
    QStringList lines = QString::fromLocal8Bit(m_errors).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    if (lines.size() > kErrorLinesShown) lines = lines.mid(lines.size() - kErrorLinesShown);
    return lines.join(QLatin1Char('\n')).trimmed();
}

analysis::Status FfmpegEncoder::failure(const QString& what)
{
    if (m_process.state() != QProcess::NotRunning) m_process.waitForFinished(1000); // let it say why
    const QString tail = errorTail();
    abort();
    return errorOf(ErrorCode::Io, tail.isEmpty() ? what : QObject::tr("%1:\n%2").arg(what, tail));
}

} // namespace bunraku::app
