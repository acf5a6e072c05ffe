#pragma once
/// File > Export 3D View Video...: take A's frames (take B beside it) as seen in the 3D view,
/// written by the video export (video_export.h) as an MP4 or a PNG sequence with a progress
/// dialog and Cancel; the document's time and playback are restored afterwards.

#include "app/video_export.h"

#include <QObject>

class QAction;
class QWidget;

namespace bunraku::app {

class Document;
class FileController;
class PlaybackController;
class ViewportPanel;

class ViewVideoController : public QObject {
    Q_OBJECT
public:
    ViewVideoController(Document& document, PlaybackController& playback, ViewportPanel& viewport, FileController& files,
                        QWidget* window);

    /// "Export 3D View &Video...", for the File menu.
    QAction* action() const { return m_action; }

    /// Exports the 3D view over a frame range of take A (frames at take A's rate, both takes
    /// shown; lastFrame -1 = take A's last frame) as an MP4 or a PNG sequence, without asking
    /// anything (a folder holding frames is refused unless options.overwrite). At the view's size
    /// the view itself is grabbed (what you see); at another size, or with the view hidden, an
    /// offscreen renderer draws the same takes, camera and toggles. `progress` (done, total)
    /// returns false to cancel; without it a QProgressDialog with Cancel ("videoExportProgress")
    /// shows. On cancel or error nothing is left.
    VideoExportResult exportVideo(const VideoExportOptions& options, const ExportProgress& progress = {});
    /// Every frame of take A as a PNG sequence at the view's size in `folder`; the frames
    /// written (0 when `folder` already holds frame_*.png).
    int exportFrames(const QString& folder);

signals:
    /// A line for the status bar.
    void message(const QString& text);

private:
    void choose();

    Document& m_document;
    PlaybackController& m_playback;
    ViewportPanel& m_viewport;
    FileController& m_files;
    QWidget* m_window = nullptr;
    QAction* m_action = nullptr;
};

} // namespace bunraku::app
