#pragma once
/// The MP4 sink of a video export: raw RGB frames streamed to `ffmpeg` (found on PATH) through
/// its standard input, encoded to H.264 (libx264, yuv420p, CRF 18) in a hidden temporary file
/// next to the output (a fresh name, .NAME.partial-XXXXXX), renamed over the output only after
/// ffmpeg exits with 0. No temporary images; cancel or failure kills ffmpeg and removes the
/// partial file, so an existing output is untouched unless the export completes.

#include "app/video_export.h"

#include <QProcess>

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

    /// The temporary file ffmpeg writes into (next to the output, hidden); empty before open()
    /// and after finish() or abort().
    QString temporaryPath() const { return m_temporary; }

private:
    /// ffmpeg's error output, its last lines only, for messages.
    QString errorTail();
    analysis::Status failure(const QString& what);

    QString m_output;
    QString m_temporary;
    QSize m_size;
    QProcess m_process;
    QByteArray m_row; ///< one frame as packed rgb24
    QByteArray m_errors;
};

} // namespace bunraku::app
