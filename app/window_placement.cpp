#include "app/window_placement.h"

#include <QApplication>
#include <QEvent>
#include <QPointer>
#include <QScreen>
#include <QWidget>
#include <QWindow>

#include <algorithm>

namespace bunraku::app {

QRect fittedFrame(QSize requested, QSize decoration, QPoint position, const QRect& available)
{
    const QSize client = requested.boundedTo(available.size() - decoration).expandedTo(QSize(1, 1));
    const QSize frame = client + decoration;
    const int x = std::clamp(position.x(), available.left(), std::max(available.left(), available.right() + 1 - frame.width()));
    const int y = std::clamp(position.y(), available.top(), std::max(available.top(), available.bottom() + 1 - frame.height()));
    return QRect(QPoint(x, y), frame);
}

namespace {

/// Moves and shrinks a shown window so that its frame lies inside its screen's available area.
void keepInside(QWidget& window)
{
    QScreen* screen = window.screen() ? window.screen() : QApplication::primaryScreen();
    if (!screen) return;
    const QRect frame = window.frameGeometry();
    const QSize decoration = frame.size() - window.size();
    const QRect fitted = fittedFrame(window.size(), decoration, frame.topLeft(), screen->availableGeometry());
    if (fitted.size() != frame.size()) window.resize(fitted.size() - decoration);
    if (fitted.topLeft() != frame.topLeft()) window.move(fitted.topLeft()); // move() places the frame
}

/// The window manager frames a window after it is shown (on X11, asynchronously): its title bar
/// is known at the first expose. Keeps the window inside then, once, and goes.
class KeepInsideOnExpose : public QObject {
public:
    /// `window` has its platform window (windowHandle()), which receives the expose events.
    explicit KeepInsideOnExpose(QWidget& window) : QObject(&window), m_window(&window), m_handle(window.windowHandle())
    {
        if (m_handle) m_handle->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == m_handle && event->type() == QEvent::Expose && m_window) {
            m_handle->removeEventFilter(this);
            keepInside(*m_window);
            deleteLater();
        }
        return false;
    }

private:
    QPointer<QWidget> m_window;
    QPointer<QWindow> m_handle;
};

} // namespace

void showInsideScreen(QWidget& window, QSize requested)
{
    QScreen* screen = window.screen() ? window.screen() : QApplication::primaryScreen();
    const QSize size = requested.isValid() ? requested : window.size();
    if (screen) {
        // Before showing: fit the client area and place it, so no frame is shown off the screen;
        // the frame's decoration is known afterwards.
        const QRect fitted = fittedFrame(size, QSize(0, 0), window.pos(), screen->availableGeometry());
        window.resize(fitted.size());
        window.move(fitted.topLeft());
    } else {
        window.resize(size);
    }
    window.winId(); // the platform window, to watch its first expose
    new KeepInsideOnExpose(window);
    window.show();
    keepInside(window);
}

} // namespace bunraku::app
