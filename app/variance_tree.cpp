#include "app/variance_tree.h"

#include <QBrush>
#include <QCoreApplication>
#include <QHeaderView>
#include <QLocale>
#include <QTreeWidget>

#include <algorithm>
#include <map>

namespace bunraku::app {

namespace {

constexpr int kWorseRole = Qt::UserRole + 7;
const QColor kWorseText(0xb0, 0x00, 0x20);
const QColor kWorseBackground(0xfd, 0xe7, 0xea);

QString tr(const char* text) { return QCoreApplication::translate("VarianceTree", text); }

QString familyName(const VarianceRow& row)
{
    return row.family == "position" ? tr("position") : row.family == "rotation" ? tr("rotation") : QString::fromStdString(row.family);
}

/// "pos. cm²": short enough for a narrow dock (the tool tip says it in full).
QString familyText(const VarianceRow& row)
{
    const QString name = row.family == "position" ? tr("pos.") : row.family == "rotation" ? tr("rot.") : QString::fromStdString(row.family);
    return row.unit.empty() ? name : QStringLiteral("%1 %2").arg(name, QString::fromStdString(row.unit));
}

/// "-66 %" / "▲ +12 %" (worse) / "–" when there was nothing to change.
QString changeText(const VarianceRow& row)
{
    if (!(row.before > 0.0)) return row.worse() ? QStringLiteral("\u25b2") : QStringLiteral("\u2013");
    const double percent = 100.0 * (row.after - row.before) / row.before;
    const QString number = QLocale().toString(percent, 'f', 0);
    return row.worse() ? QStringLiteral("\u25b2 +%1 %").arg(number) : QStringLiteral("%1 %").arg(number);
}

void mark(QTreeWidgetItem* item)
{
    item->setData(0, kWorseRole, true);
    for (int column = 0; column < item->columnCount(); ++column) {
        item->setForeground(column, kWorseText);
        item->setBackground(column, kWorseBackground);
    }
    QFont font = item->font(0);
    font.setBold(true);
    item->setFont(0, font);
}

} // namespace

QString varianceText(double value) { return QLocale().toString(value, 'f', 1); }

void fillVarianceTree(QTreeWidget* tree, const analysis::VarianceTable& table, const std::vector<analysis::Channel>& channels,
                      const std::vector<QString>& takeLabels)
{
    tree->clear();
    tree->setColumnCount(4);
    tree->setHeaderLabels({tr("Take"), tr("Before"), tr("After"), tr("Change")});
    tree->headerItem()->setToolTip(0, tr("Each take, then its DOF families (positions, rotations), then its parts"));
    const QString worseTip = tr("After normalisation this is further from the reference than before");
    std::map<std::string, QTreeWidgetItem*> takes;
    QTreeWidgetItem* family = nullptr;
    for (const VarianceRow& row : varianceRows(table, channels)) {
        QTreeWidgetItem*& take = takes[row.take];
        if (!take) {
            const auto index = std::size_t(std::find(table.takeNames.begin(), table.takeNames.end(), row.take) - table.takeNames.begin());
            take = new QTreeWidgetItem(tree, {index < takeLabels.size() ? takeLabels[index] : QString::fromStdString(row.take)});
            take->setToolTip(0, QString::fromStdString(row.take));
        }
        QTreeWidgetItem* item = row.part.empty() ? new QTreeWidgetItem(take) : new QTreeWidgetItem(family);
        if (row.part.empty()) family = item;
        item->setText(0, row.part.empty() ? familyText(row) : QString::fromStdString(row.part));
        item->setText(1, varianceText(row.before));
        item->setText(2, varianceText(row.after));
        item->setText(3, changeText(row));
        for (int column = 1; column < 4; ++column) item->setTextAlignment(column, Qt::AlignRight | Qt::AlignVCenter);
        const QString unit = QString::fromStdString(row.unit);
        item->setToolTip(0, tr("%1: squared difference to the reference (%2), summed over frames and the %3 channels%4")
                                .arg(QString::fromStdString(row.take), QString::fromStdString(row.unit), familyName(row),
                                     row.part.empty() ? tr(" of every part") : tr(" of ") + QString::fromStdString(row.part)));
        for (int column = 1; column < 3; ++column) item->setToolTip(column, unit);
        if (row.worse()) {
            mark(item);
            item->setToolTip(3, worseTip);
            if (!isMarkedWorse(take)) mark(take);
        }
    }
    for (auto& [name, take] : takes) {
        take->setExpanded(true);
        if (isMarkedWorse(take)) take->setToolTip(0, tr("%1: worse than before in at least one DOF family or part")
                                                         .arg(QString::fromStdString(name)));
    }
    tree->setIndentation(12);
    tree->header()->setStretchLastSection(false);
    // Every column as wide as its widest text: a narrow dock scrolls sideways rather than cutting
    // a take's name ("take 11 (r...").
    for (int column = 0; column < 4; ++column) tree->header()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
}

bool isMarkedWorse(const QTreeWidgetItem* item) { return item && item->data(0, kWorseRole).toBool(); }

} // namespace bunraku::app
