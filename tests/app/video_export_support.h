#pragma once
/// Helpers shared by the 3D view export tests: video_export_test.cpp (MP4 frames and size
/// checked by ffprobe, PNG sequences, cancel, missing or failing ffmpeg, the dialog) and
/// video_export_safety_test.cpp (earlier exports and files never lost, errors that say why).
#include "tests/app/app_test_support.h"

#include "app/ffmpeg_encoder.h"
#include "app/video_export.h"
#include "app/video_export_dialog.h"
#include "app/viewport_panel.h"

#include "widgets/viewport_widget.h"

#include "analysis/io/staged_folder.h"

#include <catch2/catch.hpp>

#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QProcess>
#include <QProgressDialog>
#include <QMessageBox>
#include <QThread>
#include <QTimer>
#include <QUndoCommand>
#include <QUndoStack>

#include <cmath>
#include <filesystem>
#include <optional>

#include <QStandardPaths>

namespace bunraku::test::video {

struct Probe {
    int frames = 0;
    int width = 0;
    int height = 0;
};

inline bool ffmpegInstalled()
{
    return !QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty() &&
           !QStandardPaths::findExecutable(QStringLiteral("ffprobe")).isEmpty();
}

/// Frames decoded and size of the first video stream, by ffprobe.
inline std::optional<Probe> probe(const std::filesystem::path& file)
{
    QProcess process;
    process.start(QStringLiteral("ffprobe"),
                  {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                   "stream=nb_read_frames,width,height", "-of", "csv=p=0", QString::fromStdString(file.string())});
    if (!process.waitForFinished(30000) || process.exitCode() != 0) return std::nullopt;
    // ffprobe prints the fields in its own order: width,height,nb_read_frames.
    const QStringList fields = QString::fromLatin1(process.readAllStandardOutput()).trimmed().split(QLatin1Char(','));
    if (fields.size() != 3) return std::nullopt;
    return Probe{fields[2].toInt(), fields[0].toInt(), fields[1].toInt()};
}

/// Files in `folder` (the hidden temporary one of ffmpeg included).
inline int fileCount(const std::filesystem::path& folder)
{
    return int(QDir(QString::fromStdString(folder.string())).entryList(QDir::Files | QDir::Hidden).size());
}

/// Every entry of `folder`, hidden files and folders included.
inline QStringList allEntries(const std::filesystem::path& folder)
{
    return QDir(QString::fromStdString(folder.string())).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
}

/// `count` files frame_00000.png ... in `folder` that an earlier export left (with the manifest
/// of what it wrote, as every folder output has), each with its own text.
inline void writeOldFrames(const std::filesystem::path& folder, int count)
{
    auto staged = analysis::io::StagedFolder::begin(folder);
    REQUIRE(staged.ok());
    for (int i = 0; i < count; ++i)
        REQUIRE(staged->writeFile(QStringLiteral("frame_%1.png").arg(i, 5, 10, QLatin1Char('0')).toStdString(),
                                  "old frame " + std::to_string(i))
                    .ok());
    REQUIRE(staged->commit().ok());
}

/// True when the files of writeOldFrames(folder, count) are all there, unchanged.
inline bool oldFramesIntact(const std::filesystem::path& folder, int count)
{
    for (int i = 0; i < count; ++i) {
        QFile file(QDir(QString::fromStdString(folder.string())).filePath(QStringLiteral("frame_%1.png").arg(i, 5, 10, QLatin1Char('0'))));
        if (!file.open(QIODevice::ReadOnly) || file.readAll() != QByteArray("old frame ") + QByteArray::number(i)) return false;
    }
    return true;
}

/// A window on the demo corpus with corpus take 2 as take A, its time at `seconds`.
inline std::unique_ptr<bunraku::app::MainWindow> exportWindow(double seconds)
{
    auto window = bunraku::test::demoWindow();
    if (!window) return nullptr;
    window->document().selectTake(bunraku::app::TakeSlot::A, bunraku::app::TakeId::corpus(2));
    window->document().setCurrentTime(seconds);
    return window;
}

/// Sets PATH to `path` for one scope.
class ScopedPath {
public:
    explicit ScopedPath(const std::filesystem::path& path) : m_saved(qgetenv("PATH"))
    {
        qputenv("PATH", QByteArray::fromStdString(path.string()));
    }
    ~ScopedPath() { qputenv("PATH", m_saved); }
    ScopedPath(const ScopedPath&) = delete;
    ScopedPath& operator=(const ScopedPath&) = delete;

private:
    QByteArray m_saved;
};

} // namespace bunraku::test::video
