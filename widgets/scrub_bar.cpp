#include "widgets/scrub_bar.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace bunraku::widgets {
namespace {
constexpr int kMargin = 8;
}

ScrubBar::ScrubBar(QWidget* parent) : QWidget(parent)
{
    setMinimumHeight(28);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setCursor(Qt::PointingHandCursor);
    setMouseTracking(true); // the hovered tick
    setFocusPolicy(Qt::ClickFocus); // Delete removes the selected tick
    setToolTip(tr("Press or drag to move the time; ticks mark phrase boundaries"));
}

void ScrubBar::setDuration(double seconds)
{
    m_duration = std::isfinite(seconds) && seconds > 0.0 ? seconds : 1.0;
    update();
}

void ScrubBar::setTime(double seconds)
{
    m_time = seconds;
    update();
}

void ScrubBar::setBoundaries(std::vector<double> seconds)
{
    if (seconds.size() != m_boundaries.size()) m_selected = m_hovered = -1; // a tick came or went
    m_boundaries = std::move(seconds);
    update();
}

double ScrubBar::timeAtX(int x) const
{
    const int span = std::max(1, width() - 2 * kMargin);
    return std::clamp(double(x - kMargin) / span, 0.0, 1.0) * m_duration;
}

int ScrubBar::xOfTime(double seconds) const
{
    const int span = std::max(1, width() - 2 * kMargin);
    return kMargin + int(std::lround(std::clamp(seconds / m_duration, 0.0, 1.0) * span));
}

double ScrubBar::tickSeconds() const
{
    const int span = std::max(1, width() - 2 * kMargin);
    const double fewest = m_duration * kMinTickPixels / span; // seconds the closest two ticks may be
    double step = 1.0;
    for (int k = 0; step < fewest && std::isfinite(step); k = (k + 1) % 3)
        step *= k == 1 ? 2.5 : 2.0; // 1, 2, 5, 10, 20, 50 ...
    return step;
}

void ScrubBar::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const int mid = height() / 2 + 3;
    const QRect track(kMargin, mid - 3, width() - 2 * kMargin, 6);
    painter.setPen(Qt::NoPen);
    painter.setBrush(palette().color(QPalette::Mid));
    painter.drawRoundedRect(track, 3, 3);
    painter.setBrush(palette().color(QPalette::Highlight));
    painter.drawRoundedRect(QRect(track.left(), track.top(), xOfTime(m_time) - track.left(), track.height()), 3, 3);

    // Whole seconds (or every tickSeconds) as small ticks, every fifth taller; phrase boundaries
    // as tall orange ticks. At most one tick per kMinTickPixels, whatever the take's span.
    painter.setPen(QPen(palette().color(QPalette::WindowText), 1));
    const double step = tickSeconds();
    const long ticks = long(std::min(m_duration / step, double(track.width() + 1)));
    for (long tick = 0; tick <= ticks; ++tick) {
        const int x = xOfTime(double(tick) * step);
        painter.drawLine(x, track.bottom() + 2, x, track.bottom() + (tick % 5 == 0 ? 6 : 4));
    }
    for (std::size_t i = 0; i < m_boundaries.size(); ++i) {
        const bool marked = m_boundariesEditable && (int(i) == m_selected || int(i) == m_hovered);
        painter.setPen(QPen(marked ? QColor(0xff, 0x50, 0x00) : QColor(0xe0, 0x80, 0x10), marked ? 4 : 2));
        const int x = xOfTime(m_boundaries[i]);
        painter.drawLine(x, 2, x, track.bottom());
    }
    painter.setPen(QPen(palette().color(QPalette::Dark), 1));
    painter.setBrush(palette().color(QPalette::Button));
    painter.drawEllipse(QPoint(xOfTime(m_time), mid), 7, 7);
}

void ScrubBar::setBoundariesEditable(bool editable)
{
    m_boundariesEditable = editable;
    if (!editable) m_selected = m_hovered = -1;
    setToolTip(editable ? tr("Press or drag to move the time; drag an orange tick to move a phrase boundary, "
                             "double-click to add one, right-click or Delete to remove one")
                        : tr("Press or drag to move the time; ticks mark phrase boundaries"));
    update();
}

int ScrubBar::boundaryAtX(int x) const
{
    int best = -1;
    int bestDistance = kBoundaryGrabPixels + 1;
    for (std::size_t i = 0; i < m_boundaries.size(); ++i) {
        const int distance = std::abs(xOfTime(m_boundaries[i]) - x);
        if (distance < bestDistance) {
            best = int(i);
            bestDistance = distance;
        }
    }
    return best;
}

void ScrubBar::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    const int x = int(event->position().x());
    m_dragged = m_boundariesEditable ? boundaryAtX(x) : -1;
    if (m_dragged >= 0) {
        m_selected = m_dragged;
        update();
        emit boundaryDragStarted(m_dragged);
        return;
    }
    emit scrubbed(timeAtX(x));
}

void ScrubBar::mouseMoveEvent(QMouseEvent* event)
{
    const int x = int(event->position().x());
    if (!(event->buttons() & Qt::LeftButton)) {
        finishBoundaryDrag(); // the release went elsewhere (e.g. to a popup menu)
        const int hovered = m_boundariesEditable ? boundaryAtX(x) : -1;
        if (hovered != m_hovered) {
            m_hovered = hovered;
            update();
        }
        return;
    }
    if (m_dragged >= 0)
        emit boundaryDragged(m_dragged, timeAtX(x));
    else
        emit scrubbed(timeAtX(x));
}

void ScrubBar::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton) finishBoundaryDrag();
}

void ScrubBar::finishBoundaryDrag()
{
    if (m_dragged < 0) return;
    const int index = m_dragged;
    m_dragged = -1;
    emit boundaryDragFinished(index);
}

void ScrubBar::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    const int x = int(event->position().x());
    if (!m_boundariesEditable || boundaryAtX(x) >= 0) {
        mousePressEvent(event); // as a second press: scrub, or drag the tick
        return;
    }
    emit boundaryAddRequested(timeAtX(x));
}

QMenu* ScrubBar::createContextMenu(QPoint position)
{
    if (!m_boundariesEditable) return nullptr;
    auto* menu = new QMenu(this);
    const int index = boundaryAtX(position.x());
    if (index >= 0) {
        menu->addAction(tr("Remove phrase boundary"), this, [this, index] { emit boundaryRemoveRequested(index); });
    } else {
        const double seconds = timeAtX(position.x());
        menu->addAction(tr("Add phrase boundary here"), this, [this, seconds] { emit boundaryAddRequested(seconds); });
    }
    return menu;
}

void ScrubBar::contextMenuEvent(QContextMenuEvent* event)
{
    finishBoundaryDrag(); // the menu takes the mouse: the left release would never arrive
    QMenu* menu = createContextMenu(event->pos());
    if (!menu) {
        QWidget::contextMenuEvent(event);
        return;
    }
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->popup(event->globalPos());
}

void ScrubBar::keyPressEvent(QKeyEvent* event)
{
    const int index = m_hovered >= 0 ? m_hovered : m_selected;
    if (m_boundariesEditable && (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) && index >= 0 &&
        index < int(m_boundaries.size())) {
        emit boundaryRemoveRequested(index);
        return;
    }
    QWidget::keyPressEvent(event);
}

void ScrubBar::hideEvent(QHideEvent* event)
{
    finishBoundaryDrag();
    QWidget::hideEvent(event);
}

void ScrubBar::leaveEvent(QEvent* event)
{
    if (m_hovered >= 0) {
        m_hovered = -1;
        update();
    }
    QWidget::leaveEvent(event);
}

} // namespace bunraku::widgets
