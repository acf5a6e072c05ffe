#include "app/multimodal_export_dialog.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>

#include <algorithm>

namespace bunraku::app {
namespace {

const QString kGroup = QStringLiteral("multimodalExport");

QString defaultOutput()
{
    const QString movies = QStandardPaths::writableLocation(QStandardPaths::MoviesLocation);
    return QDir(movies.isEmpty() ? QDir::homePath() : movies).filePath(QStringLiteral("multimodal.mp4"));
}

void addUnique(QComboBox* box, const QString& text)
{
    if (box->findText(text) < 0) box->addItem(text);
}

} // namespace

MultimodalExportDialog::MultimodalExportDialog(const std::vector<analysis::Channel>& channels, int lastFrame, double rateHz,
                                               bool twoTakes, const MultimodalOptions& initial, QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Export Multimodal Video"));
    setObjectName("multimodalExportDialog");
    m_layout = new QComboBox(this);
    m_layout->setObjectName("layout");
    m_layout->addItem(twoTakes ? tr("All channels (48 graphs)") : tr("All channels (24 graphs)"), int(widgets::GraphLayout::AllChannels));
    m_layout->addItem(twoTakes ? tr("One part (12 graphs)") : tr("One part (6 graphs)"), int(widgets::GraphLayout::OnePart));
    m_layout->addItem(twoTakes ? tr("One DOF (8 graphs)") : tr("One DOF (4 graphs)"), int(widgets::GraphLayout::OneDof));
    m_layout->addItem(twoTakes ? tr("Single (2 graphs)") : tr("Single (1 graph)"), int(widgets::GraphLayout::Single));
    m_layout->setCurrentIndex(std::max(0, m_layout->findData(int(initial.layout))));
    m_part = new QComboBox(this);
    m_part->setObjectName("part");
    m_dof = new QComboBox(this);
    m_dof->setObjectName("dof");
    for (const auto& channel : channels) {
        addUnique(m_part, QString::fromStdString(channel.part));
        addUnique(m_dof, QString::fromStdString(channel.dof));
    }
    m_part->setCurrentIndex(std::max(0, m_part->findText(QString::fromStdString(initial.part))));
    m_dof->setCurrentIndex(std::max(0, m_dof->findText(QString::fromStdString(initial.dof))));
    m_thesisTicks = new QCheckBox(tr("Thesis ticks (values every 10, time every 2 s)"), this);
    m_thesisTicks->setObjectName("thesisTicks");
    m_thesisTicks->setChecked(initial.thesisTicks);

    m_format = new QComboBox(this);
    m_format->setObjectName("format");
    m_format->addItem(tr("MP4 video (H.264, encoded by ffmpeg)"), int(VideoFormat::Mp4));
    m_format->addItem(tr("PNG sequence (a folder of frame_00000.png ...)"), int(VideoFormat::PngSequence));
    m_wholeTake = new QRadioButton(tr("Whole take A (frames 0 to %1)").arg(lastFrame), this);
    auto* someFrames = new QRadioButton(tr("Frames"), this);
    auto* group = new QButtonGroup(this);
    group->addButton(m_wholeTake);
    group->addButton(someFrames);
    m_wholeTake->setChecked(true);
    m_first = new QSpinBox(this);
    m_last = new QSpinBox(this);
    m_first->setObjectName("firstFrame");
    m_last->setObjectName("lastFrame");
    for (auto* box : {m_first, m_last}) box->setRange(0, std::max(0, lastFrame));
    m_last->setValue(lastFrame);
    auto* range = new QHBoxLayout;
    range->addWidget(someFrames);
    range->addWidget(m_first);
    range->addWidget(m_last);
    m_fps = new QDoubleSpinBox(this);
    m_fps->setObjectName("fps");
    m_fps->setRange(0.0, 240.0);
    m_fps->setDecimals(2);
    m_fps->setSpecialValueText(tr("the take's rate (%1 Hz)").arg(rateHz));
    m_size = new QComboBox(this);
    m_size->setObjectName("size");
    m_size->addItem(tr("1280 x 720 (HD)"), QSize(1280, 720));
    m_size->addItem(tr("1920 x 1080 (Full HD)"), QSize(1920, 1080));
    m_size->addItem(tr("3840 x 2160 (4K)"), QSize(3840, 2160));
    m_size->setCurrentIndex(std::max(0, m_size->findData(initial.size)));
    m_output = new QLineEdit(this);
    m_output->setObjectName("output");
    auto* browse = new QPushButton(tr("Browse..."), this);
    auto* output = new QHBoxLayout;
    output->addWidget(m_output, 1);
    output->addWidget(browse);

    QSettings settings;
    settings.beginGroup(kGroup);
    m_format->setCurrentIndex(std::max(0, m_format->findData(settings.value("format", int(VideoFormat::Mp4)).toInt())));
    m_fps->setValue(settings.value("fps", 0.0).toDouble());
    if (settings.contains("size")) m_size->setCurrentIndex(std::max(0, m_size->findData(settings.value("size").toSize())));
    m_output->setText(settings.value("output", defaultOutput()).toString());
    settings.endGroup();

    auto* form = new QFormLayout;
    form->addRow(tr("Graphs:"), m_layout);
    form->addRow(tr("Part:"), m_part);
    form->addRow(tr("DOF:"), m_dof);
    form->addRow(QString(), m_thesisTicks);
    form->addRow(tr("Format:"), m_format);
    form->addRow(tr("Range:"), m_wholeTake);
    form->addRow(QString(), range);
    form->addRow(tr("Frame rate:"), m_fps);
    form->addRow(tr("Size:"), m_size);
    form->addRow(tr("Output:"), output);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &MultimodalExportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &MultimodalExportDialog::browse);
    for (auto* box : {m_first, m_last}) connect(box, &QSpinBox::valueChanged, someFrames, [someFrames] { someFrames->setChecked(true); });
}

MultimodalExportChoice MultimodalExportDialog::choice() const
{
    MultimodalExportChoice choice;
    choice.layout.layout = widgets::GraphLayout(m_layout->currentData().toInt());
    choice.layout.part = m_part->currentText().toStdString();
    choice.layout.dof = m_dof->currentText().toStdString();
    choice.layout.thesisTicks = m_thesisTicks->isChecked();
    choice.layout.size = m_size->currentData().toSize();
    choice.video.format = VideoFormat(m_format->currentData().toInt());
    choice.video.firstFrame = m_wholeTake->isChecked() ? 0 : std::min(m_first->value(), m_last->value());
    choice.video.lastFrame = m_wholeTake->isChecked() ? -1 : std::max(m_first->value(), m_last->value());
    choice.video.fps = m_fps->value();
    choice.video.size = choice.layout.size;
    choice.video.output = m_output->text().trimmed();
    choice.video.overwrite = m_overwrite;
    return choice;
}

void MultimodalExportDialog::browse()
{
    const bool mp4 = VideoFormat(m_format->currentData().toInt()) == VideoFormat::Mp4;
    const QString chosen = mp4 ? QFileDialog::getSaveFileName(this, tr("Export multimodal video"), m_output->text(),
                                                               tr("MP4 video (*.mp4)"))
                               : QFileDialog::getExistingDirectory(this, tr("Folder for the PNG frames"),
                                                                   QFileInfo(m_output->text()).absolutePath());
    if (!chosen.isEmpty()) m_output->setText(chosen);
}

void MultimodalExportDialog::accept()
{
    QString output = m_output->text().trimmed();
    if (output.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), tr("Choose where the video goes."));
        return;
    }
    const bool mp4 = VideoFormat(m_format->currentData().toInt()) == VideoFormat::Mp4;
    if (mp4 && !output.endsWith(QStringLiteral(".mp4"), Qt::CaseInsensitive)) output += QStringLiteral(".mp4");
    m_output->setText(output);
    m_overwrite = false;
    if (!mp4) {
        const auto old = existingFrames(output).size();
        if (old > 0) {
            QMessageBox question(QMessageBox::Question, windowTitle(),
                                 tr("%1 already holds %2 of an earlier export. Replace them once the new frames are "
                                    "complete?").arg(output, frameCountText(int(old))),
                                 QMessageBox::Yes | QMessageBox::No, this);
            question.setObjectName("replaceFramesQuestion");
            if (question.exec() != QMessageBox::Yes) return;
            m_overwrite = true;
        }
    }
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue("format", m_format->currentData());
    settings.setValue("fps", m_fps->value());
    settings.setValue("size", m_size->currentData());
    settings.setValue("output", output);
    settings.endGroup();
    QDialog::accept();
}

} // namespace bunraku::app
