#pragma once
/// Keeps the left column of docks (the corpus, inspector and analysis panels) at the width the
/// person gave it when the window is resized, so a larger window widens the 3D view and the
/// graphs, as in Blender or MotionBuilder. (Without a central widget QMainWindow gives a
/// window's extra width to the first dock column: at 2560 pixels the panels took half of it.)
/// Widths the person sets by dragging a separator are kept from then on.

#include <QObject>
#include <QPointer>
#include <QSize>

class QMainWindow;

namespace bunraku::app {

class SideColumns : public QObject {
    Q_OBJECT
public:
    explicit SideColumns(QMainWindow* window);

    /// The left column's width being kept (0 before the window was laid out).
    int leftWidth() const { return m_leftWidth; }
    /// The default width of the left column in a window `width` pixels wide: a quarter of it,
    /// between 260 and 420 pixels.
    static int preferredLeftWidth(int width);
    /// Back to the default width (a fresh window, View > Reset Layout), once the layout settled.
    void reset();
    /// Keeps the width a restored layout gives the column (the layout saved at the last quit).
    void adoptRestoredLayout() { m_adopt = true; }
    /// Keeps the width a layout restored now gives the column (a project's), once laid out.
    void adoptLayoutNow();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void keepLeftWidth();

    QPointer<QMainWindow> m_window;
    QSize m_windowSize; ///< the window's size when the left width was last kept
    int m_leftWidth = 0;
    bool m_adopt = false; ///< the first width kept is the one laid out (a restored layout)
};

} // namespace bunraku::app
