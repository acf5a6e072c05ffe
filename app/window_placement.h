#pragma once
/// Where the workbench's window opens: inside the screen's available geometry (the screen less
/// panels and docks), whatever size was asked for. `--window-size 1920x1080` on a 1920x1080
/// screen with a top panel would otherwise put the status bar below the screen's edge.

#include <QRect>
#include <QSize>

class QWidget;

namespace bunraku::app {

/// The frame geometry a window of `requested` client size, whose frame adds `decoration` (the
/// title bar and borders: frame size - client size), takes inside `available`: the requested
/// size shrunk to fit, at `position` (the frame's top-left) moved as little as needed to
/// bring the whole frame inside.
QRect fittedFrame(QSize requested, QSize decoration, QPoint position, const QRect& available);

/// Resizes `window` to `requested` (its current size when invalid) and shows it, then keeps its
/// frame inside the available geometry of the screen it is on (the window manager's frame is
/// known only once shown).
void showInsideScreen(QWidget& window, QSize requested = {});

} // namespace bunraku::app
