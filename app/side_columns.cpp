#include "app/side_columns.h"

#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QStyle>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace bunraku::app {

namespace {

std::vector<QDockWidget*> docksIn(QMainWindow& window, Qt::DockWidgetArea area)
{
    std::vector<QDockWidget*> docks;
    for (QDockWidget* dock : window.findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly))
        // (A tab behind another in a restored layout is "visible" but placed outside the window.)
        if (dock->isVisible() && !dock->isFloating() && window.dockWidgetArea(dock) == area && dock->geometry().intersects(window.rect()))
            docks.push_back(dock);
    return docks;
}

} // namespace

SideColumns::SideColumns(QMainWindow* window) : QObject(window), m_window(window)
{
    window->installEventFilter(this);
    for (QDockWidget* dock : window->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly)) dock->installEventFilter(this);
}

bool SideColumns::eventFilter(QObject* watched, QEvent* event)
{
    // The event's type first: while the window is destroyed its children's removal comes here
    // (ChildRemoved) when it is a QWidget no more a QMainWindow, and reading m_window then is a
    // cast to what the object no longer is (UBSan's vptr check, found by tests/monkey).
    if (event->type() != QEvent::Resize || !m_window) return false;
    if (watched == m_window) {
        // After the layout has placed the docks for the new size: give the left column its width back.
        if (m_window->size() != m_windowSize) QTimer::singleShot(0, this, &SideColumns::keepLeftWidth);
        return false;
    }
    // A left dock resized while the window kept its size: the person (or a layout reset) chose it.
    auto* dock = qobject_cast<QDockWidget*>(watched);
    if (dock && m_window->size() == m_windowSize && !dock->isFloating() && m_window->dockWidgetArea(dock) == Qt::LeftDockWidgetArea)
        m_leftWidth = dock->width();
    return false;
}

int SideColumns::preferredLeftWidth(int width) { return std::clamp(width / 4, 260, 420); }

void SideColumns::reset()
{
    m_leftWidth = 0;
    m_adopt = false;
    m_windowSize = QSize();
    QTimer::singleShot(0, this, &SideColumns::keepLeftWidth);
}

int SideColumns::maxLeftWidth(int width) { return std::max(preferredLeftWidth(width), width * 2 / 5); }

void SideColumns::adoptLayoutNow(int savedWidth, int savedWindowWidth)
{
    m_leftWidth = 0;
    m_adopt = true;
    m_adoptWidth = savedWidth;
    m_adoptWindowWidth = savedWindowWidth;
    m_windowSize = QSize();
    QTimer::singleShot(0, this, &SideColumns::keepLeftWidth);
}

void SideColumns::keepLeftWidth()
{
    if (!m_window) return;
    const bool first = !m_windowSize.isValid();
    m_windowSize = m_window->size();
    const auto left = docksIn(*m_window, Qt::LeftDockWidgetArea);
    if (left.empty()) return;
    // A layout adopted in a window no wider than the one it was saved in keeps its right
    // columns as laid out: the favoured column's share is for a window that grew.
    const bool asLaidOut = m_adopt && m_adoptWindowWidth > 0 && m_window->width() <= m_adoptWindowWidth;
    if (first || m_leftWidth <= 0) {
        const int adopted = m_adoptWidth > 0 ? m_adoptWidth : left.front()->width();
        m_leftWidth = m_adopt ? std::min(adopted, maxLeftWidth(m_window->width())) : preferredLeftWidth(m_window->width());
        m_adopt = false;
        m_adoptWidth = 0;
        m_adoptWindowWidth = 0;
    }
    // The right area's columns (docks side by side; stacked or tabbed docks share a column)
    // share the rest of the window in proportion to their widths. Every dock gets a width and
    // the widths fill the window: QMainWindow has no extra space to hand to the first column.
    std::map<int, std::vector<QDockWidget*>> columns; // by left edge
    for (QDockWidget* dock : docksIn(*m_window, Qt::RightDockWidgetArea)) columns[dock->geometry().x()].push_back(dock);
    const int separator = m_window->style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent, nullptr, m_window);
    const int available = m_window->width() - m_leftWidth - separator * int(columns.size());
    int total = 0;
    for (const auto& [x, column] : columns) total += std::max(1, column.front()->width());
    std::vector<int> columnWidths;
    for (const auto& [x, column] : columns)
        columnWidths.push_back(total > 0 ? int(std::lround(double(available) * std::max(1, column.front()->width()) / total)) : 0);
    // The favoured column (the 3D view) gets at least its share of the window, from the other
    // right columns' width above their minimum.
    std::size_t index = 0;
    for (const auto& [x, column] : columns) {
        if (!asLaidOut && m_favoured && std::find(column.begin(), column.end(), m_favoured.data()) != column.end()) {
            int deficit = int(std::lround(m_favouredFraction * m_window->width())) - columnWidths[index];
            std::size_t other = 0;
            for (const auto& [ox, otherColumn] : columns) {
                if (other != index && deficit > 0) {
                    const int spare = columnWidths[other] - std::max(otherColumn.front()->minimumSizeHint().width(), 1);
                    const int taken = std::clamp(spare, 0, deficit);
                    columnWidths[other] -= taken;
                    columnWidths[index] += taken;
                    deficit -= taken;
                }
                ++other;
            }
        }
        ++index;
    }
    QList<QDockWidget*> docks(left.begin(), left.end());
    QList<int> widths(docks.size(), m_leftWidth);
    index = 0;
    for (const auto& [x, column] : columns) {
        for (QDockWidget* dock : column) {
            docks << dock;
            widths << std::max(1, columnWidths[index]);
        }
        ++index;
    }
    m_window->resizeDocks(docks, widths, Qt::Horizontal);
}

} // namespace bunraku::app
