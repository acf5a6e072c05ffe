#pragma once
/// Keeps the left column of docks (the corpus, inspector and analysis panels) at the width the
/// person gave it when the window is resized, so a larger window widens the 3D view and the
/// graphs, as in Blender or MotionBuilder. (Without a central widget QMainWindow gives a
/// window's extra width to the first dock column: at 2560 pixels the panels took half of it.)
/// Widths the person sets by dragging a separator are kept from then on.

#include <QObject>
#include <QPointer>
#include <QSize>

class QDockWidget;
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
    /// Keeps the width a layout restored now gives the column (a project's), once laid out:
    /// `savedWidth` when the project says what it was (a layout restored into a window of
    /// another size gives the left column the difference), else what the layout gives it. Either
    /// is kept within maxLeftWidth. `savedWindowWidth`: the window's width when the layout was
    /// saved (0: unknown); in a window no wider the right columns keep their widths as laid out
    /// (a 3D view narrowed by the person stays narrow), in a wider one the favoured column gets
    /// its share first.
    void adoptLayoutNow(int savedWidth = 0, int savedWindowWidth = 0);
    /// The widest the left column is adopted in a window `width` pixels wide: 40 % of it, at
    /// least the preferred width (a wider column was the layout of a smaller window stretched).
    static int maxLeftWidth(int width);
    /// The dock whose column gets at least `fraction` of the window's width whenever the other
    /// right columns can give it (the 3D view: a larger window widens the view first).
    void setFavoured(QDockWidget* dock, double fraction)
    {
        m_favoured = dock;
        m_favouredFraction = fraction;
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void keepLeftWidth();

    QPointer<QMainWindow> m_window;
    QSize m_windowSize; ///< the window's size when the left width was last kept
    int m_leftWidth = 0;
    bool m_adopt = false; ///< the first width kept is the one laid out (a restored layout)
    int m_adoptWidth = 0; ///< or this width, when a project said it
    int m_adoptWindowWidth = 0; ///< the width of the window the adopted layout was saved in
    QPointer<QDockWidget> m_favoured;
    double m_favouredFraction = 0.0;
};

} // namespace bunraku::app
