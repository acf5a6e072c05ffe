#pragma once
/// The time-warp curve editor (thesis Fig. 5.13): designed frame (x) -> functional frame (y),
/// a monotone cubic through draggable control points (analysis/design/warp_curve.h), with the
/// extracted correspondence drawn faintly behind it and the identity as a dotted diagonal.
/// Drag a point to move it (clamped between its neighbours: monotone by construction; with
/// Shift held it pushes its neighbours' functional frames along instead, so one drag retimes a
/// whole stretch), double
/// click empty space to add a point on the curve, right click a point to delete it (not the
/// ends); "snap to frames" rounds moved points to whole frames. The editor never changes its
/// own curve: it proposes edits (curveEdited) and shows what setCurve gives it.

#include "analysis/design/warp_curve.h"

#include <QWidget>

#include <optional>

class QCheckBox;
class QCustomPlot;
class QCPGraph;
class QMouseEvent;
class QPushButton;

namespace bunraku::widgets {

class WarpCurveEditor : public QWidget {
    Q_OBJECT
public:
    explicit WarpCurveEditor(QWidget* parent = nullptr);

    void setCurve(const analysis::WarpCurve& curve);
    const analysis::WarpCurve& curve() const { return m_curve; }
    /// The extracted correspondence (output frame -> source frame samples), drawn behind; empty hides it.
    void setExtracted(const Eigen::VectorXd& sourceOfOutput);
    /// The current time as a designed frame (a vertical marker).
    void setCurrentFrame(double frame);
    void setSnapToFrames(bool snap);
    bool snapToFrames() const;

    /// Widget pixel position of control point `index` (tests and tooltips).
    QPoint pointPosition(std::size_t index) const;
    /// Frames (output, source) under a widget pixel position.
    analysis::WarpPoint frameAt(const QPoint& position) const;
    /// The curve with a point added on the curve at `output` (or unchanged when too close to another).
    analysis::WarpCurve withPointAdded(double output) const;
    /// The curve without point `index` (unchanged for the first and last point).
    analysis::WarpCurve withPointRemoved(std::size_t index) const;

    QCustomPlot* plot() const { return m_plot; }

signals:
    /// A drag begins (the app opens an undo interaction) or ends.
    void dragStarted();
    void dragFinished();
    /// The user edited the curve (drag step, add, delete, reset).
    void curveEdited(const bunraku::analysis::WarpCurve& curve);
    void resetToIdentityRequested();
    void resetToExtractedRequested();

private:
    void onPress(QMouseEvent* event);
    void onMove(QMouseEvent* event);
    void onRelease(QMouseEvent* event);
    void onDoubleClick(QMouseEvent* event);
    std::optional<std::size_t> pointNear(const QPoint& position) const;
    void redraw();

    QCustomPlot* m_plot = nullptr;
    QCPGraph* m_extracted = nullptr;
    QCPGraph* m_identity = nullptr;
    QCPGraph* m_curveGraph = nullptr;
    QCPGraph* m_points = nullptr;
    QCPGraph* m_marker = nullptr;
    QCheckBox* m_snap = nullptr;
    analysis::WarpCurve m_curve;
    Eigen::VectorXd m_extractedSamples;
    double m_currentFrame = 0.0;
    std::optional<std::size_t> m_dragged;
};

} // namespace bunraku::widgets
