#include "widgets/warp_curve_editor.h"

#include "widgets/flow_layout.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace bunraku::widgets {
namespace {
constexpr double kGrabRadiusPixels = 9.0;
}

WarpCurveEditor::WarpCurveEditor(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    m_plot->setObjectName("warpPlot");
    m_plot->setMinimumSize(220, 180);
    m_plot->xAxis->setLabel(tr("designed frame"));
    m_plot->yAxis->setLabel(tr("functional frame"));
    m_identity = m_plot->addGraph();
    m_identity->setPen(QPen(QColor(0xb0, 0xb0, 0xb0), 1, Qt::DotLine));
    m_extracted = m_plot->addGraph();
    m_extracted->setPen(QPen(QColor(0xe0, 0x9a, 0x50), 3));
    m_extracted->setName(tr("extracted"));
    m_curveGraph = m_plot->addGraph();
    m_curveGraph->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 2));
    m_points = m_plot->addGraph();
    m_points->setLineStyle(QCPGraph::lsNone);
    m_points->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(0x10, 0x40, 0x80), 1.5), Qt::white, 9));
    m_marker = m_plot->addGraph();
    m_marker->setPen(QPen(QColor(0xc0, 0x20, 0x20), 1));

    m_snap = new QCheckBox(tr("Snap to frames"), this);
    m_snap->setChecked(true);
    auto* identity = new QPushButton(tr("Reset to identity"), this);
    auto* extracted = new QPushButton(tr("Reset to extracted"), this);
    identity->setObjectName("resetIdentity");
    extracted->setObjectName("resetExtracted");
    // Wrapped onto more rows in a narrow dock rather than clipped.
    auto* buttons = new FlowLayout;
    buttons->addWidget(m_snap);
    buttons->addWidget(identity);
    buttons->addWidget(extracted);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot, 1);
    layout->addLayout(buttons);
    setToolTip(tr("Drag a point to move it (Shift+drag pushes the points it meets along); double click to add one; "
                  "right click a point to delete it"));

    connect(identity, &QPushButton::clicked, this, &WarpCurveEditor::resetToIdentityRequested);
    connect(extracted, &QPushButton::clicked, this, &WarpCurveEditor::resetToExtractedRequested);
    connect(m_plot, &QCustomPlot::mousePress, this, &WarpCurveEditor::onPress);
    connect(m_plot, &QCustomPlot::mouseMove, this, &WarpCurveEditor::onMove);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &WarpCurveEditor::onRelease);
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, &WarpCurveEditor::onDoubleClick);
}

void WarpCurveEditor::setCurve(const analysis::WarpCurve& curve)
{
    m_curve = curve;
    redraw();
}

void WarpCurveEditor::setExtracted(const Eigen::VectorXd& sourceOfOutput)
{
    m_extractedSamples = sourceOfOutput;
    redraw();
}

void WarpCurveEditor::setCurrentFrame(double frame)
{
    m_currentFrame = frame;
    const QCPRange range = m_plot->yAxis->range();
    m_marker->setData(QVector<double>{frame, frame}, QVector<double>{range.lower, range.upper});
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void WarpCurveEditor::setSnapToFrames(bool snap) { m_snap->setChecked(snap); }
bool WarpCurveEditor::snapToFrames() const { return m_snap->isChecked(); }

void WarpCurveEditor::redraw()
{
    QVector<double> x, y, px, py, ex, ey;
    if (m_curve.points.size() >= 2) {
        // Four samples per output frame, but no more than the plot's pixels can show (a design
        // warp reaching output frame 1e8 would ask for 4e8 samples); the points themselves are
        // always samples, so no kink is cut off.
        const double last = m_curve.points.back().output;
        const double pixels = std::max(100, m_plot->width());
        const int samples = int(std::clamp(last * 4.0, 1.0, 4.0 * pixels)) + 1;
        std::size_t next = 0; // the next curve point not yet sampled
        const auto sample = [&](double output) {
            x << output;
            y << analysis::evaluateWarp(m_curve, output);
        };
        for (int i = 0; i < samples; ++i) {
            const double output = last * i / (samples - 1);
            for (; next < m_curve.points.size() && m_curve.points[next].output < output; ++next)
                if (x.isEmpty() || m_curve.points[next].output > x.back()) sample(m_curve.points[next].output);
            sample(output);
        }
        for (const auto& point : m_curve.points) {
            px << point.output;
            py << point.source;
        }
    }
    for (Eigen::Index i = 0; i < m_extractedSamples.size(); ++i) {
        ex << double(i);
        ey << m_extractedSamples[i];
    }
    m_curveGraph->setData(x, y, true);
    m_points->setData(px, py, true);
    m_extracted->setData(ex, ey, true);
    double xMax = x.isEmpty() ? 1.0 : x.back();
    double yMax = 1.0;
    for (double v : y) yMax = std::max(yMax, v);
    for (double v : ey) yMax = std::max(yMax, v);
    if (!ex.isEmpty()) xMax = std::max(xMax, ex.back());
    const double diagonal = std::min(xMax, yMax);
    m_identity->setData(QVector<double>{0.0, diagonal}, QVector<double>{0.0, diagonal});
    m_plot->xAxis->setRange(-0.02 * xMax, 1.02 * xMax);
    m_plot->yAxis->setRange(-0.02 * yMax, 1.02 * yMax);
    m_marker->setData(QVector<double>{m_currentFrame, m_currentFrame}, QVector<double>{-0.02 * yMax, 1.02 * yMax});
    // Queued: an immediate replot would repaint (and flush the window) once per drag step on top
    // of the paint the event loop does anyway.
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QPoint WarpCurveEditor::pointPosition(std::size_t index) const
{
    const auto& point = m_curve.points.at(index);
    const QPointF inPlot(m_plot->xAxis->coordToPixel(point.output), m_plot->yAxis->coordToPixel(point.source));
    return m_plot->mapTo(this, inPlot.toPoint());
}

analysis::WarpPoint WarpCurveEditor::frameAt(const QPoint& position) const
{
    const QPoint inPlot = m_plot->mapFrom(this, position);
    return {m_plot->xAxis->pixelToCoord(inPlot.x()), m_plot->yAxis->pixelToCoord(inPlot.y())};
}

std::optional<std::size_t> WarpCurveEditor::pointNear(const QPoint& plotPosition) const
{
    std::optional<std::size_t> best;
    double bestDistance = kGrabRadiusPixels;
    for (std::size_t i = 0; i < m_curve.points.size(); ++i) {
        const QPointF pixel(m_plot->xAxis->coordToPixel(m_curve.points[i].output),
                            m_plot->yAxis->coordToPixel(m_curve.points[i].source));
        const double distance = std::hypot(pixel.x() - plotPosition.x(), pixel.y() - plotPosition.y());
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = i;
        }
    }
    return best;
}

analysis::WarpCurve WarpCurveEditor::withPointAdded(double output) const
{
    analysis::WarpCurve curve = m_curve;
    if (curve.points.size() < 2) return curve;
    if (snapToFrames()) output = std::round(output);
    if (output <= curve.points.front().output || output >= curve.points.back().output) return curve;
    for (const auto& point : curve.points)
        if (std::abs(point.output - output) < 1.0) return curve;
    const analysis::WarpPoint added{output, analysis::evaluateWarp(m_curve, output)};
    const auto at = std::upper_bound(curve.points.begin(), curve.points.end(), added,
                                     [](const auto& a, const auto& b) { return a.output < b.output; });
    curve.points.insert(at, added);
    return curve;
}

analysis::WarpCurve WarpCurveEditor::withPointRemoved(std::size_t index) const
{
    analysis::WarpCurve curve = m_curve;
    if (index == 0 || index + 1 >= curve.points.size()) return curve;
    curve.points.erase(curve.points.begin() + std::ptrdiff_t(index));
    return curve;
}

void WarpCurveEditor::onPress(QMouseEvent* event)
{
    const auto near = pointNear(event->position().toPoint());
    if (event->button() == Qt::RightButton) {
        if (near && *near > 0 && *near + 1 < m_curve.points.size()) emit curveEdited(withPointRemoved(*near));
        return;
    }
    if (event->button() != Qt::LeftButton || !near) return;
    m_dragged = near;
    emit dragStarted();
}

void WarpCurveEditor::onMove(QMouseEvent* event)
{
    if (!m_dragged || !(event->buttons() & Qt::LeftButton)) return;
    const QPoint position = event->position().toPoint();
    analysis::WarpPoint proposed{m_plot->xAxis->pixelToCoord(position.x()), m_plot->yAxis->pixelToCoord(position.y())};
    if (snapToFrames()) proposed = {std::round(proposed.output), std::round(proposed.source)};
    // Shift pushes the neighbours along instead of stopping at them.
    const auto mode = (event->modifiers() & Qt::ShiftModifier) ? analysis::WarpMove::Push : analysis::WarpMove::Clamp;
    const auto moved = analysis::moveControlPoint(m_curve, *m_dragged, proposed, snapToFrames() ? 1.0 : 0.5, mode);
    if (moved.points != m_curve.points) emit curveEdited(moved);
}

void WarpCurveEditor::onRelease(QMouseEvent*)
{
    if (!m_dragged) return;
    m_dragged.reset();
    emit dragFinished();
}

void WarpCurveEditor::onDoubleClick(QMouseEvent* event)
{
    if (pointNear(event->position().toPoint())) return;
    const auto added = withPointAdded(m_plot->xAxis->pixelToCoord(event->position().x()));
    if (added.points.size() != m_curve.points.size()) emit curveEdited(added);
}

} // namespace bunraku::widgets
