#include "widgets/inspector_widget.h"

#include "widgets/take_series.h"

#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

namespace bunraku::widgets {

InspectorWidget::InspectorWidget(QWidget* parent) : QWidget(parent), m_table(new QTableWidget(this))
{
    m_table->setColumnCount(4);
    m_table->setHorizontalHeaderLabels({tr("Channel"), tr("Unit"), tr("A"), tr("B")});
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    // Fixed widths, set from the contents when the rows change: sizing to contents on every
    // value update would measure every cell each frame.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
}

void InspectorWidget::setTakes(std::shared_ptr<const analysis::Take> takeA, std::shared_ptr<const analysis::Take> takeB)
{
    const bool sameRows = m_takes[0] && takeA && m_takes[0]->channels == takeA->channels;
    m_takes[0] = std::move(takeA);
    m_takes[1] = std::move(takeB);
    if (sameRows) { // a new version of the same layout: only the values change
        refresh();
        return;
    }
    const auto* take = m_takes[0].get();
    m_table->setRowCount(take ? int(take->channelCount()) : 0);
    if (take) {
        for (int row = 0; row < int(take->channelCount()); ++row) {
            const auto& channel = take->channels[std::size_t(row)];
            m_table->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(channel.name())));
            m_table->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(channel.unit)));
            for (int column : {2, 3}) {
                // Sized for the widest value expected, e.g. "-1234.56".
                auto* item = new QTableWidgetItem(QStringLiteral("-1234.56"));
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                m_table->setItem(row, column, item);
            }
        }
        m_table->resizeColumnsToContents();
    }
    refresh();
}

void InspectorWidget::setTime(double seconds)
{
    m_time = seconds;
    refresh();
}

int InspectorWidget::rowCount() const { return m_table->rowCount(); }

std::optional<double> InspectorWidget::shownValue(int row, int slot) const
{
    if (slot < 0 || slot > 1 || row < 0 || row >= int(m_values[slot].size())) return std::nullopt;
    return m_values[slot][std::size_t(row)];
}

void InspectorWidget::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    showValues();
}

void InspectorWidget::refresh()
{
    const auto* takeA = m_takes[0].get();
    const auto rows = std::size_t(m_table->rowCount());
    for (int slot = 0; slot < 2; ++slot) {
        m_values[slot].assign(rows, std::nullopt);
        const auto* take = m_takes[slot].get();
        if (!takeA || !take) continue;
        for (std::size_t row = 0; row < rows; ++row) {
            const auto& channel = takeA->channels[row];
            if (auto column = slot == 0 ? std::optional<Eigen::Index>(Eigen::Index(row)) : findChannel(*take, channel.part, channel.dof))
                m_values[slot][row] = valueAt(*take, *column, m_time);
        }
    }
    if (isVisible()) showValues();
}

void InspectorWidget::showValues()
{
    for (int slot = 0; slot < 2; ++slot)
        for (int row = 0; row < int(m_values[slot].size()); ++row) {
            auto* item = m_table->item(row, 2 + slot);
            if (!item) continue;
            const auto& value = m_values[slot][std::size_t(row)];
            const QString text = value ? QString::number(*value, 'f', 2) : QString();
            if (item->text() != text) item->setText(text);
        }
}

} // namespace bunraku::widgets
