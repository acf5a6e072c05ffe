#include "app/import_takes_dialog.h"

#include "app/joint_map_dialog.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh_joint_map.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <filesystem>

namespace bunraku::app {

namespace {

enum Column { FileColumn, JointsColumn, HeightColumn, ChooseColumn, ColumnCount };

QString jointsText(const analysis::io::JointMap& map)
{
    QStringList items;
    for (std::size_t part = 0; part < 4; ++part)
        items << QStringLiteral("%1 %2").arg(QString::fromLatin1(analysis::kPuppetParts[part]), QString::fromStdString(map.joints[part]));
    return items.join(QStringLiteral(", "));
}

} // namespace

ImportTakesDialog::ImportTakesDialog(const QStringList& files, QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Import %n take(s)", nullptr, int(files.size())));
    for (const QString& file : files) {
        Row row;
        row.file = file;
        auto start = analysis::io::readBvhStart(std::filesystem::path(file.toStdString()));
        if (start) row.start = std::move(start).value();
        else row.readError = QString::fromStdString(start.error().message);
        m_rows.push_back(std::move(row));
    }
    m_side = new QComboBox(this);
    m_side->setObjectName(QStringLiteral("side"));
    m_side->addItems({tr("Right arm and hand"), tr("Left arm and hand")});
    m_units = makeUnitsBox(this);
    auto* form = new QFormLayout;
    form->addRow(tr("Side"), m_side);
    form->addRow(tr("Units"), m_units);

    m_table = new QTableWidget(int(m_rows.size()), ColumnCount, this);
    m_table->setObjectName(QStringLiteral("takes"));
    m_table->setHorizontalHeaderLabels({tr("File"), tr("Joints (head, shoulder, arm, hand)"), tr("Height"), QString()});
    m_table->horizontalHeader()->setSectionResizeMode(JointsColumn, QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int r = 0; r < int(m_rows.size()); ++r) {
        m_table->setItem(r, FileColumn, new QTableWidgetItem(QFileInfo(m_rows[std::size_t(r)].file).fileName()));
        m_table->item(r, FileColumn)->setToolTip(m_rows[std::size_t(r)].file);
        m_table->setItem(r, JointsColumn, new QTableWidgetItem);
        m_table->setItem(r, HeightColumn, new QTableWidgetItem);
        auto* choose = new QPushButton(tr("Joints..."), m_table);
        choose->setObjectName(QStringLiteral("choose_%1").arg(r));
        choose->setEnabled(m_rows[std::size_t(r)].start.has_value());
        connect(choose, &QPushButton::clicked, this, [this, r] { chooseJoints(r); });
        m_table->setCellWidget(r, ChooseColumn, choose);
    }
    m_table->resizeColumnToContents(FileColumn);
    m_table->resizeColumnToContents(ChooseColumn);
    m_table->setMinimumWidth(720);

    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_side, &QComboBox::currentIndexChanged, this, &ImportTakesDialog::remap);
    connect(m_units, &QComboBox::currentIndexChanged, this, &ImportTakesDialog::refresh);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Each file's joints drive the puppet's head, shoulder, arm and hand: found by the automatic "
                                    "part map, or chosen with Joints..."),
                                 this));
    layout->addLayout(form);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_message);
    layout->addWidget(buttons);
    remap();
}

analysis::io::BvhImportOptions ImportTakesDialog::options(int row) const
{
    analysis::io::BvhImportOptions options;
    const Row& r = m_rows.at(std::size_t(row));
    if (r.chosen) options.jointMap = r.chosen;
    else if (r.automatic) options.jointMap = r.automatic;
    options.side = m_side->currentIndex() == 1 ? analysis::BodySide::Left : analysis::BodySide::Right;
    applyUnitsChoice(*m_units, options);
    return options;
}

void ImportTakesDialog::chooseJoints(int row)
{
    Row& r = m_rows.at(std::size_t(row));
    if (!r.start) return;
    JointMapDialog dialog(*r.start, QFileInfo(r.file).fileName(), this);
    dialog.sideBox()->setCurrentIndex(m_side->currentIndex());
    dialog.unitsBox()->setCurrentIndex(m_units->currentIndex());
    if (r.chosen) {
        for (std::size_t part = 0; part < 4; ++part) dialog.partBox(int(part))->setCurrentText(QString::fromStdString(r.chosen->joints[part]));
    }
    if (dialog.exec() != QDialog::Accepted) return;
    r.chosen = dialog.jointMap();
    refresh();
}

void ImportTakesDialog::remap()
{
    analysis::io::PartMapOptions options;
    options.side = m_side->currentIndex() == 1 ? analysis::BodySide::Left : analysis::BodySide::Right;
    for (Row& row : m_rows) {
        row.automatic.reset();
        row.automaticError.clear();
        if (!row.start) continue;
        const auto map = analysis::io::mapPuppetParts(*row.start, std::nullopt, options);
        if (map) row.automatic = map->names;
        else row.automaticError = QString::fromStdString(map.error().message);
    }
    refresh();
}

void ImportTakesDialog::refresh()
{
    m_problem.clear();
    for (int r = 0; r < int(m_rows.size()); ++r) {
        const Row& row = m_rows[std::size_t(r)];
        QString joints, height;
        if (!row.start) {
            joints = row.readError;
        } else if (row.chosen) {
            joints = tr("chosen: %1").arg(jointsText(*row.chosen));
        } else if (row.automatic) {
            joints = jointsText(*row.automatic);
        } else {
            joints = tr("not found: choose with Joints... (%1)").arg(row.automaticError);
        }
        if (row.start) {
            const auto guess = analysis::io::guessBvhUnits(*row.start);
            const double cmPerUnit = m_units->currentIndex() > 0 ? m_units->currentData().toDouble() : guess.cmPerUnit;
            height = tr("%1 m").arg(guess.height * cmPerUnit / 100.0, 0, 'f', 2);
        }
        m_table->item(r, JointsColumn)->setText(joints);
        m_table->item(r, JointsColumn)->setToolTip(joints);
        m_table->item(r, HeightColumn)->setText(height);
        const bool ready = row.start && (row.chosen || row.automatic);
        m_table->item(r, JointsColumn)->setForeground(ready ? palette().text() : QBrush(QColor(0xb0, 0x00, 0x20)));
        if (!ready && m_problem.isEmpty())
            m_problem = row.start ? tr("Choose the joints of %1.").arg(QFileInfo(row.file).fileName())
                                  : tr("%1 cannot be read: %2").arg(QFileInfo(row.file).fileName(), row.readError);
    }
    m_message->setText(m_problem);
    m_message->setStyleSheet(m_problem.isEmpty() ? QString() : QStringLiteral("color: #b00020"));
    m_ok->setEnabled(m_problem.isEmpty());
}

} // namespace bunraku::app
