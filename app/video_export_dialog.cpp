#include "app/video_export_dialog.h"

#include "app/ffmpeg_encoder.h"
#include "app/file_dialogs.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>

#include <algorithm>

namespace bunraku::app {
namespace {

const QString kGroup = QStringLiteral("videoExport");

QString sizeText(QSize size) { return QStringLiteral("%1 x %2").arg(size.width()).arg(size.height()); }

} // namespace

VideoExportDialog::VideoExportDialog(const VideoExportLimits& limits, QWidget* parent) : QDialog(parent), m_limits(limits)
{
    setWindowTitle(tr("Export 3D View Video"));
    setObjectName("videoExportDialog");

    m_format = new QComboBox(this);
    m_format->setObjectName("format");
    m_format->addItem(tr("MP4 video (H.264, encoded by ffmpeg)"), int(VideoFormat::Mp4));
    m_format->addItem(tr("PNG sequence (a folder of frame_00000.png ...)"), int(VideoFormat::PngSequence));

    m_wholeTake = new QRadioButton(tr("Whole take (frames 0 to %1)").arg(limits.lastFrame), this);
    m_frameRange = new QRadioButton(tr("Frames"), this);
    m_first = new QSpinBox(this);
    m_last = new QSpinBox(this);
    for (auto* box : {m_first, m_last}) box->setRange(0, std::max(0, limits.lastFrame));
    m_last->setValue(limits.lastFrame);
    auto* rangeGroup = new QButtonGroup(this);
    rangeGroup->addButton(m_wholeTake);
    rangeGroup->addButton(m_frameRange);
    auto* range = new QHBoxLayout;
    range->addWidget(m_frameRange);
    range->addWidget(m_first);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_last);
    range->addStretch(1);

    m_takeRate = new QRadioButton(tr("The take's rate (%1 fps)").arg(limits.rateHz, 0, 'g', 6), this);
    m_chosenRate = new QRadioButton(tr("Resample the timeline at"), this);
    m_fps = new QDoubleSpinBox(this);
    m_fps->setRange(1.0, 240.0);
    m_fps->setDecimals(3);
    m_fps->setSuffix(tr(" fps"));
    m_fps->setValue(30.0);
    auto* rateGroup = new QButtonGroup(this);
    rateGroup->addButton(m_takeRate);
    rateGroup->addButton(m_chosenRate);
    auto* rate = new QHBoxLayout;
    rate->addWidget(m_chosenRate);
    rate->addWidget(m_fps);
    rate->addStretch(1);

    m_resolution = new QComboBox(this);
    m_resolution->setObjectName("resolution");
    m_resolution->addItem(tr("The 3D view's size (%1)").arg(sizeText(limits.viewSize)), QSize());
    m_resolution->addItem(tr("1280 x 720 (HD)"), QSize(1280, 720));
    m_resolution->addItem(tr("1920 x 1080 (Full HD)"), QSize(1920, 1080));

    m_output = new QLineEdit(this);
    m_output->setObjectName("output");
    auto* browse = new QToolButton(this);
    browse->setText(tr("..."));
    browse->setToolTip(tr("Choose the file or folder"));
    auto* output = new QHBoxLayout;
    output->addWidget(m_output, 1);
    output->addWidget(browse);

    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));

    auto* form = new QFormLayout;
    form->addRow(tr("Format:"), m_format);
    form->addRow(tr("Range:"), m_wholeTake);
    form->addRow(QString(), range);
    form->addRow(tr("Frame rate:"), m_takeRate);
    form->addRow(QString(), rate);
    form->addRow(tr("Resolution:"), m_resolution);
    form->addRow(tr("Output:"), output);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &VideoExportDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QToolButton::clicked, this, &VideoExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, &VideoExportDialog::formatChanged);
    connect(m_first, &QSpinBox::valueChanged, this, [this](int value) {
        if (m_last->value() < value) m_last->setValue(value);
        m_frameRange->setChecked(true);
    });
    connect(m_last, &QSpinBox::valueChanged, this, [this](int value) {
        if (m_first->value() > value) m_first->setValue(value);
        m_frameRange->setChecked(true);
    });
    connect(m_fps, &QDoubleSpinBox::valueChanged, this, [this] { m_chosenRate->setChecked(true); });
    for (auto* button : {m_wholeTake, m_frameRange, m_takeRate, m_chosenRate})
        connect(button, &QRadioButton::toggled, this, &VideoExportDialog::updateSummary);
    for (auto* box : {m_first, m_last}) connect(box, &QSpinBox::valueChanged, this, &VideoExportDialog::updateSummary);
    connect(m_fps, &QDoubleSpinBox::valueChanged, this, &VideoExportDialog::updateSummary);
    connect(m_resolution, &QComboBox::currentIndexChanged, this, &VideoExportDialog::updateSummary);

    // Where the person last wrote a video (else the last folder they chose for anything or home:
    // never a folder they did not go to).
    m_mp4Path = QDir(rememberedFolder(FilePurpose::Video)).filePath(QStringLiteral("bunraku-view.mp4"));
    m_pngFolder = QDir(rememberedFolder(FilePurpose::VideoFrames)).filePath(QStringLiteral("bunraku-frames"));
    setOptions(rememberedOptions());
}

void VideoExportDialog::suggestOutput(const QString& name, const QString& projectFile)
{
    m_mp4Path = QDir(rememberedFolder(FilePurpose::Video, projectFile)).filePath(name + QStringLiteral(".mp4"));
    m_pngFolder = QDir(rememberedFolder(FilePurpose::VideoFrames, projectFile)).filePath(name + QStringLiteral("-frames"));
    m_output->setText(format() == VideoFormat::Mp4 ? m_mp4Path : m_pngFolder);
}

VideoFormat VideoExportDialog::format() const { return VideoFormat(m_format->currentData().toInt()); }

VideoExportOptions VideoExportDialog::options() const
{
    VideoExportOptions options;
    options.format = format();
    if (m_frameRange->isChecked()) {
        options.firstFrame = m_first->value();
        options.lastFrame = m_last->value();
    }
    options.fps = m_chosenRate->isChecked() ? m_fps->value() : 0.0;
    options.size = m_resolution->currentData().toSize();
    options.output = m_output->text().trimmed();
    options.overwrite = m_overwrite && options.format == VideoFormat::PngSequence;
    return options;
}

void VideoExportDialog::setOptions(const VideoExportOptions& options)
{
    // The output of the other format stays as remembered: switching formats brings it back.
    if (!options.output.isEmpty()) (options.format == VideoFormat::Mp4 ? m_mp4Path : m_pngFolder) = options.output;
    m_output->setProperty("shownFormat", QVariant()); // the shown text is replaced, not kept
    m_format->setCurrentIndex(m_format->findData(int(options.format)));
    const bool whole = options.firstFrame <= 0 && (options.lastFrame < 0 || options.lastFrame >= m_limits.lastFrame);
    m_first->setValue(std::clamp(options.firstFrame, 0, m_limits.lastFrame));
    m_last->setValue(options.lastFrame < 0 ? m_limits.lastFrame : std::clamp(options.lastFrame, 0, m_limits.lastFrame));
    (whole ? m_wholeTake : m_frameRange)->setChecked(true);
    if (options.fps > 0.0) m_fps->setValue(options.fps);
    (options.fps > 0.0 ? m_chosenRate : m_takeRate)->setChecked(true);
    int resolution = m_resolution->findData(options.size);
    if (resolution < 0) { // a size from elsewhere (the settings file edited by hand)
        m_resolution->addItem(sizeText(options.size), options.size);
        resolution = m_resolution->count() - 1;
    }
    m_resolution->setCurrentIndex(resolution);
    formatChanged();
}

VideoExportOptions VideoExportDialog::rememberedOptions()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    VideoExportOptions options;
    options.format = settings.value("format").toString() == QStringLiteral("png") ? VideoFormat::PngSequence : VideoFormat::Mp4;
    options.firstFrame = settings.value("firstFrame", 0).toInt();
    options.lastFrame = settings.value("lastFrame", -1).toInt();
    options.fps = settings.value("fps", 0.0).toDouble();
    options.size = settings.value("size", QSize()).toSize();
    options.output = settings.value(options.format == VideoFormat::Mp4 ? "mp4Path" : "pngFolder").toString();
    return options;
}

void VideoExportDialog::rememberOptions(const VideoExportOptions& options)
{
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue("format", options.format == VideoFormat::Mp4 ? QStringLiteral("mp4") : QStringLiteral("png"));
    settings.setValue("firstFrame", options.firstFrame);
    settings.setValue("lastFrame", options.lastFrame);
    settings.setValue("fps", options.fps);
    settings.setValue("size", options.size);
    settings.setValue(options.format == VideoFormat::Mp4 ? "mp4Path" : "pngFolder", options.output);
}

void VideoExportDialog::accept()
{
    QString output = m_output->text().trimmed();
    if (output.isEmpty()) {
        m_summary->setText(tr("Choose where to write the export."));
        return;
    }
    if (format() == VideoFormat::Mp4 && QFileInfo(output).suffix().compare(QStringLiteral("mp4"), Qt::CaseInsensitive) != 0)
        output += QStringLiteral(".mp4");
    m_output->setText(output);
    m_overwrite = false;
    if (format() == VideoFormat::PngSequence) {
        // Old frames are replaced only when the person says so (and only once the new ones are done).
        if (const auto old = existingFrames(output).size(); old > 0) {
            QMessageBox question(QMessageBox::Question, tr("Export 3D View Video"),
                                 tr("Folder %1 already holds %2 (frame_*.png): replace them?")
                                     .arg(QDir::toNativeSeparators(output), frameCountText(int(old))),
                                 QMessageBox::Yes | QMessageBox::No, this);
            question.setObjectName("replaceFramesQuestion");
            question.setInformativeText(tr("The old frames are removed only after the new sequence is complete."));
            question.setDefaultButton(QMessageBox::No);
            if (question.exec() != QMessageBox::Yes) {
                m_summary->setText(tr("Choose another folder, or allow replacing its frames."));
                return;
            }
            m_overwrite = true;
        }
    }
    rememberOptions(options());
    rememberFolder(format() == VideoFormat::Mp4 ? FilePurpose::Video : FilePurpose::VideoFrames, output);
    QDialog::accept();
}

void VideoExportDialog::browse()
{
    QString chosen;
    if (format() == VideoFormat::Mp4)
        chosen = QFileDialog::getSaveFileName(this, tr("MP4 video"), m_output->text(), tr("MP4 videos (*.mp4)"));
    else
        chosen = QFileDialog::getExistingDirectory(this, tr("Folder for the PNG frames"), QFileInfo(m_output->text()).absolutePath());
    if (!chosen.isEmpty()) m_output->setText(chosen);
}

void VideoExportDialog::formatChanged()
{
    // Keep what was typed for the format being left, show the other one's.
    const bool mp4 = format() == VideoFormat::Mp4;
    if (m_output->property("shownFormat").isValid())
        (m_output->property("shownFormat").toInt() == int(VideoFormat::Mp4) ? m_mp4Path : m_pngFolder) = m_output->text();
    m_output->setText(mp4 ? m_mp4Path : m_pngFolder);
    m_output->setProperty("shownFormat", int(format()));
    updateSummary();
}

void VideoExportDialog::updateSummary()
{
    const VideoExportOptions chosen = options();
    const FramePlan plan = planFrames(m_limits.rateHz, chosen.firstFrame,
                                      chosen.lastFrame < 0 ? m_limits.lastFrame : chosen.lastFrame, chosen.fps);
    const double seconds = plan.times.empty() ? 0.0 : double(plan.times.size()) / plan.fps;
    QString text = tr("%n frame(s), %1 s of video at %2 fps.", nullptr, int(plan.times.size()))
                       .arg(seconds, 0, 'f', 1)
                       .arg(plan.fps, 0, 'g', 6);
    const bool ffmpegMissing = format() == VideoFormat::Mp4 && findFfmpeg().isEmpty();
    if (ffmpegMissing) text += QStringLiteral("<br><b>") + ffmpegMissingMessage().toHtmlEscaped() + QStringLiteral("</b>");
    m_summary->setText(text);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(!ffmpegMissing);
}

} // namespace bunraku::app
