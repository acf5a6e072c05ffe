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
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
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
                auto* item = new QTableWidgetItem;
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                m_table->setItem(row, column, item);
            }
        }
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
    const auto* item = m_table->item(row, 2 + slot);
    if (!item || item->text().isEmpty()) return std::nullopt;
    return item->data(Qt::UserRole).toDouble();
}

void InspectorWidget::refresh()
{
    const auto* takeA = m_takes[0].get();
    if (!takeA) return;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto& channel = takeA->channels[std::size_t(row)];
        for (int slot = 0; slot < 2; ++slot) {
            auto* item = m_table->item(row, 2 + slot);
            const auto* take = m_takes[slot].get();
            std::optional<double> value;
            if (take) {
                if (auto column = slot == 0 ? std::optional<Eigen::Index>(row) : findChannel(*take, channel.part, channel.dof))
                    value = valueAt(*take, *column, m_time);
            }
            item->setText(value ? QString::number(*value, 'f', 2) : QString());
            item->setData(Qt::UserRole, value ? *value : 0.0);
        }
    }
}

} // namespace bunraku::widgets
