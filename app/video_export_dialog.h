#pragma once
/// File > Export 3D View Video...: format (MP4 through ffmpeg, or a PNG sequence), frame range
/// (the whole take, or first..last frame), frame rate (the take's, or a chosen fps resampling the
/// timeline), resolution (the view's size, 1280x720 or 1920x1080) and the output path. The last
/// choices are remembered (QSettings, group "videoExport"); one output path is kept per format.

#include "app/video_export.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace bunraku::app {

/// What the dialog offers: the take's frames and rate and the view's size.
struct VideoExportLimits {
    int lastFrame = 0;   ///< last frame of take A
    double rateHz = 5.0; ///< take A's frame rate
    QSize viewSize;      ///< the 3D view in device pixels
};

class VideoExportDialog : public QDialog {
    Q_OBJECT
public:
    explicit VideoExportDialog(const VideoExportLimits& limits, QWidget* parent = nullptr);

    /// The choices, ready for MainWindow::exportViewVideo (lastFrame -1 = whole take, fps 0 =
    /// the take's rate, empty size = the view's).
    VideoExportOptions options() const;
    void setOptions(const VideoExportOptions& options);
    /// Suggests outputs named `name` (no suffix: "demo-greeting-none-2.mp4", "...-frames") in
    /// the folders last chosen for videos and frames (app/file_dialogs.h; `projectFile`'s folder
    /// or home when none was), instead of the last outputs' names.
    void suggestOutput(const QString& name, const QString& projectFile = {});

    /// The choices of the last accepted dialog (defaults the first time).
    static VideoExportOptions rememberedOptions();
    static void rememberOptions(const VideoExportOptions& options);

public slots:
    /// Adds the .mp4 suffix when missing, remembers the choices and closes; refuses an empty path.
    /// A PNG folder already holding frame_*.png is kept only when the person agrees to replace
    /// them (QMessageBox "replaceFramesQuestion"), which sets options().overwrite.
    void accept() override;

private:
    void browse();
    void formatChanged();
    void updateSummary();
    VideoFormat format() const;

    VideoExportLimits m_limits;
    QComboBox* m_format = nullptr;
    QRadioButton* m_wholeTake = nullptr;
    QRadioButton* m_frameRange = nullptr;
    QSpinBox* m_first = nullptr;
    QSpinBox* m_last = nullptr;
    QRadioButton* m_takeRate = nullptr;
    QRadioButton* m_chosenRate = nullptr;
    QDoubleSpinBox* m_fps = nullptr;
    QComboBox* m_resolution = nullptr;
    QLineEdit* m_output = nullptr;
    QLabel* m_summary = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QString m_mp4Path;   ///< the output kept for each format while switching
    QString m_pngFolder;
    bool m_overwrite = false; ///< the person agreed to replace the folder's frames (never remembered)
};

} // namespace bunraku::app
