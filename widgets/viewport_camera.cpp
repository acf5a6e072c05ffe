// The 3D view's camera framing: Frame All, Frame Selected, Reset Camera (Home with the view
// focused) and the automatic framing of a new scene (widgets/viewport_widget.h).
#include "widgets/viewport_widget.h"

#include "render/offscreen_renderer.h"

#include <QKeyEvent>

namespace bunraku::widgets {

render::Bounds ViewportWidget::sceneBounds(const render::BoundsQuery& query)
{
    if (!makeCurrent()) return {};
    prepareFrame();
    const render::Renderer& renderer = m_offscreen->renderer();
    return renderer.hasScene() ? renderer.displayedBounds(m_camera, query) : render::Bounds{};
}

namespace {

/// What automatic framing and Reset Camera fit: the figures over the whole take (the partner
/// marker stands apart; Frame All includes it).
render::BoundsQuery figures()
{
    render::BoundsQuery query;
    query.figuresOnly = true;
    return query;
}

/// The box a new scene is compared with: coarser (a scene is replaced on every step of a drag,
/// and a size change of 30 % does not need every frame).
render::BoundsQuery quickFigures()
{
    render::BoundsQuery query = figures();
    query.sampledFrames = 24;
    return query;
}

} // namespace

void ViewportWidget::adaptCameraToScene()
{
    const render::Bounds bounds = m_offscreen->renderer().displayedBounds(m_camera, quickFigures());
    if (bounds.empty()) return;
    if (!m_cameraChosen) {
        m_camera = render::resetCamera(m_offscreen->renderer().displayedBounds(m_camera, figures()), pixelSize());
    } else if (!m_framedFor) {
        m_framedFor = bounds; // a camera set before its scene (a project's) fits that scene
        return;
    } else if (render::boundsDiffer(*m_framedFor, bounds)) {
        m_camera = render::framedCamera(m_camera, bounds, pixelSize());
    } else {
        return;
    }
    m_framedFor = bounds;
    emit cameraChanged();
}

void ViewportWidget::frameAll()
{
    const render::Bounds bounds = sceneBounds({});
    if (bounds.empty()) return;
    m_camera = render::framedCamera(m_camera, bounds, pixelSize());
    m_cameraChosen = true;
    m_framedFor = sceneBounds(figures());
    emit cameraChanged();
    invalidate();
}

void ViewportWidget::frameSelected(const QString& part)
{
    render::BoundsQuery query;
    query.span = render::FramingSpan::CurrentFrame;
    query.part = part.toStdString();
    render::Bounds bounds = sceneBounds(query);
    if (bounds.empty()) {
        query.part.clear();
        bounds = sceneBounds(query);
    }
    if (bounds.empty()) return;
    m_camera = render::framedCamera(m_camera, bounds, pixelSize());
    m_cameraChosen = true;
    m_framedFor = sceneBounds(figures());
    emit cameraChanged();
    invalidate();
}

void ViewportWidget::resetCamera()
{
    const render::Bounds bounds = sceneBounds(figures());
    if (bounds.empty()) return;
    m_camera = render::resetCamera(bounds, pixelSize());
    m_cameraChosen = false;
    m_framedFor = bounds;
    emit cameraChanged();
    invalidate();
}

bool ViewportWidget::event(QEvent* event)
{
    // Home resets the camera while the view has the focus; elsewhere it goes to the start.
    if (event->type() == QEvent::ShortcutOverride) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Home && key->modifiers() == Qt::NoModifier) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

void ViewportWidget::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Home && event->modifiers() == Qt::NoModifier) {
        resetCamera();
        event->accept();
        return;
    }
    QWidget::keyPressEvent(event);
}

} // namespace bunraku::widgets
