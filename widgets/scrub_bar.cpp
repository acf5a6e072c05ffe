#include "widgets/scrub_bar.h"

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
    setToolTip(tr("Press or drag to move the time; ticks mark phrase boundaries"));
}

void ScrubBar::setDuration(double seconds)
{
    m_duration = seconds > 0.0 ? seconds : 1.0;
    update();
}

void ScrubBar::setTime(double seconds)
{
    m_time = seconds;
    update();
}

void ScrubBar::setBoundaries(std::vector<double> seconds)
{
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

    // Whole seconds as small ticks, phrase boundaries as tall orange ticks.
    painter.setPen(QPen(palette().color(QPalette::WindowText), 1));
    for (int second = 0; second <= int(m_duration); ++second) {
        const int x = xOfTime(second);
        painter.drawLine(x, track.bottom() + 2, x, track.bottom() + (second % 5 == 0 ? 6 : 4));
    }
    painter.setPen(QPen(QColor(0xe0, 0x80, 0x10), 2));
    for (double boundary : m_boundaries) {
        const int x = xOfTime(boundary);
        painter.drawLine(x, 2, x, track.bottom());
    }
    painter.setPen(QPen(palette().color(QPalette::Dark), 1));
    painter.setBrush(palette().color(QPalette::Button));
    painter.drawEllipse(QPoint(xOfTime(m_time), mid), 7, 7);
}

void ScrubBar::setBoundariesEditable(bool editable)
{
    m_boundariesEditable = editable;
    setToolTip(editable ? tr("Press or drag to move the time; drag an orange tick to move a phrase boundary")
                        : tr("Press or drag to move the time; ticks mark phrase boundaries"));
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
        emit boundaryDragStarted(m_dragged);
        return;
    }
    emit scrubbed(timeAtX(x));
}

void ScrubBar::mouseMoveEvent(QMouseEvent* event)
{
    if (!(event->buttons() & Qt::LeftButton)) return;
    const int x = int(event->position().x());
    if (m_dragged >= 0)
        emit boundaryDragged(m_dragged, timeAtX(x));
    else
        emit scrubbed(timeAtX(x));
}

void ScrubBar::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || m_dragged < 0) return;
    const int index = m_dragged;
    m_dragged = -1;
    emit boundaryDragFinished(index);
}

} // namespace bunraku::widgets
