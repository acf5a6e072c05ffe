#pragma once
/// File > Export Multimodal Video...: the graphs (the thesis's four layouts, with the part and
/// DOF they show; for two takes 48 / 12 / 8 / 2 graphs), the thesis's ticks, the format (MP4
/// through ffmpeg or a PNG sequence), the frames of take A, the frame rate, the size and the
/// output. Starts from the graph dock's choices; the rest is remembered (QSettings, group
/// "multimodalExport").

#include "app/multimodal_frame.h"
#include "app/video_export.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace bunraku::app {

struct MultimodalExportChoice {
    MultimodalOptions layout;
    VideoExportOptions video; ///< lastFrame -1 = whole take, fps 0 = the take's rate
};

class MultimodalExportDialog : public QDialog {
    Q_OBJECT
public:
    /// `channels`: take A's (the part and DOF choices); `lastFrame`, `rateHz`: take A's;
    /// `twoTakes`: B is shown too (the layouts then name 48 / 12 / 8 / 2 graphs).
    MultimodalExportDialog(const std::vector<analysis::Channel>& channels, int lastFrame, double rateHz, bool twoTakes,
                           const MultimodalOptions& initial, QWidget* parent = nullptr);

    MultimodalExportChoice choice() const;

public slots:
    /// Adds the .mp4 suffix when missing, refuses an empty path, asks before replacing the
    /// frames of an earlier PNG export (QMessageBox "replaceFramesQuestion"), remembers, closes.
    void accept() override;

private:
    void browse();

    QComboBox* m_layout = nullptr;
    QComboBox* m_part = nullptr;
    QComboBox* m_dof = nullptr;
    QCheckBox* m_thesisTicks = nullptr;
    QComboBox* m_format = nullptr;
    QRadioButton* m_wholeTake = nullptr;
    QSpinBox* m_first = nullptr;
    QSpinBox* m_last = nullptr;
    QDoubleSpinBox* m_fps = nullptr;
    QComboBox* m_size = nullptr;
    QLineEdit* m_output = nullptr;
    bool m_overwrite = false;
};

} // namespace bunraku::app
