#pragma once
/// A horizontal time bar: the take's duration, the current time as a handle, phrase boundaries
/// as ticks. Pressing or dragging on it requests a time (scrubbed); it never sets its own time.
/// When the boundaries are editable, pressing on a tick (within kBoundaryGrabPixels) drags that
/// boundary instead: boundaryDragStarted, boundaryDragged (per move), boundaryDragFinished. The
/// owner moves the boundary and sets the new ticks back. Editable ticks are also added and
/// removed one at a time: a double click where there is no tick, or the context menu's "Add
/// phrase boundary here", requests a new one (boundaryAddRequested); the context menu's "Remove
/// phrase boundary" on a tick, or Delete / Backspace with the bar focused, removes the tick under
/// the mouse, else the selected one (the last tick pressed) (boundaryRemoveRequested).

#include <QWidget>

class QMenu;

#include <vector>

namespace bunraku::widgets {

class ScrubBar : public QWidget {
    Q_OBJECT
public:
    explicit ScrubBar(QWidget* parent = nullptr);

    void setDuration(double seconds);
    void setTime(double seconds);
    /// Phrase boundaries, seconds, drawn as ticks above the bar.
    void setBoundaries(std::vector<double> seconds);

    double duration() const { return m_duration; }
    double time() const { return m_time; }
    const std::vector<double>& boundaries() const { return m_boundaries; }
    /// Whether ticks can be dragged (off by default).
    void setBoundariesEditable(bool editable);
    bool boundariesEditable() const { return m_boundariesEditable; }
    /// The index of the tick under `x` (nearest within the grab distance), -1 when none.
    int boundaryAtX(int x) const;
    static constexpr int kBoundaryGrabPixels = 4;
    /// The selected tick (the last editable tick pressed), -1 when none.
    int selectedBoundary() const { return m_selected; }
    /// The tick under the mouse, -1 when none.
    int hoveredBoundary() const { return m_hovered; }
    /// The context menu at `position` (widget coordinates): "Remove phrase boundary" on an
    /// editable tick, else "Add phrase boundary here"; null when the ticks are not editable. The
    /// caller owns the menu; its actions emit the requests when triggered.
    QMenu* createContextMenu(QPoint position);
    /// The time under the x pixel coordinate `x`, clamped to [0, duration].
    double timeAtX(int x) const;
    /// The x pixel coordinate of `seconds`.
    int xOfTime(double seconds) const;
    /// Seconds between two time ticks over the bar's width: 1 s, or the first of 2, 5, 10, 20,
    /// 50, 100 ... s that keeps the ticks kMinTickPixels apart. The ticks follow the pixels, not
    /// the span: a take of 1e8 s draws as many as one of 100 s on the same width.
    double tickSeconds() const;
    static constexpr int kMinTickPixels = 4;

    QSize sizeHint() const override { return {400, 34}; }

signals:
    void scrubbed(double seconds);
    void boundaryDragStarted(int index);
    /// Boundary `index` dragged to `seconds` (clamped to [0, duration]).
    void boundaryDragged(int index, double seconds);
    void boundaryDragFinished(int index);
    /// A new boundary is asked for at `seconds`.
    void boundaryAddRequested(double seconds);
    /// Boundary `index` is asked to go.
    void boundaryRemoveRequested(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    /// Ends a tick drag (boundaryDragFinished) if one is under way.
    void finishBoundaryDrag();

    double m_duration = 1.0;
    double m_time = 0.0;
    std::vector<double> m_boundaries;
    bool m_boundariesEditable = false;
    int m_dragged = -1; ///< the boundary being dragged, -1 when scrubbing
    int m_selected = -1; ///< the last tick pressed, -1 when none
    int m_hovered = -1;  ///< the tick under the mouse, -1 when none
};

} // namespace bunraku::widgets
