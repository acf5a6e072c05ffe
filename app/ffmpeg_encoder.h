#pragma once
/// The MP4 sink of a video export: raw RGB frames streamed to `ffmpeg` (found on PATH) through
/// its standard input, encoded to H.264 (libx264, yuv420p, CRF 18) into a file ffmpeg creates
/// itself inside a fresh private folder beside the output (0700, hidden, named by
/// analysis/io/atomic_file.h's temporarySiblingName), moved over the output only after ffmpeg
/// exits with 0, then flushed to the disk. No temporary images; cancel or failure kills ffmpeg
/// and removes the private folder, so an existing output is untouched unless the export
/// completes. Used from the export's worker thread: every wait on ffmpeg happens there, in
/// slices that check the cancel flag.

#include "app/video_export.h"

#include <QProcess>

#include <atomic>
#include <functional>

namespace bunraku::app {

/// The ffmpeg executable on PATH (looked up at each call), empty when there is none.
QString findFfmpeg();

/// What to tell a person when ffmpeg is not on PATH (names the package to install).
QString ffmpegMissingMessage();

class FfmpegEncoder final : public FrameSink {
public:
    /// `output`: the .mp4 file to create (replaced if it exists).
    explicit FfmpegEncoder(QString output);
    ~FfmpegEncoder() override; ///< aborts an encode that was not finished

    /// Starts ffmpeg for frames of `size` (even width and height) at `fps` frames per second.
    analysis::Status open(QSize size, double fps) override;
    analysis::Status write(const QImage& image) override;
    analysis::Status finish() override;
    void abort() override;

    /// The file ffmpeg writes into (in a private folder next to the output); empty before open()
    /// and after finish() or abort().
    QString temporaryPath() const { return m_temporary; }
    /// Waits on ffmpeg stop early (as a failure) once `*cancel` is true.
    void setCancelFlag(const std::atomic<bool>* cancel) { m_cancel = cancel; }

private:
    /// ffmpeg's error output, its last lines only, for messages.
    QString errorTail();
    analysis::Status failure(const QString& what);

    /// Waits for `done` in short slices; false on timeout or cancel.
    bool waitWhile(const std::function<bool()>& done, int timeoutMs);
    void removeTemporaryFolder();

    QString m_output;
    QString m_temporary;       ///< the file ffmpeg creates
    QString m_temporaryFolder; ///< its private folder
    const std::atomic<bool>* m_cancel = nullptr;
    QSize m_size;
    QProcess m_process;
    QByteArray m_row; ///< one frame as packed rgb24
    QByteArray m_errors;
};

} // namespace bunraku::app
