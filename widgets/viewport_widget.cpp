#include "widgets/viewport_widget.h"

#include "render/offscreen_renderer.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>

#include <cmath>

namespace bunraku::widgets {

namespace {
constexpr float kDegreesPerPixel = 0.4f;
constexpr int kClickSlopPixels = 4; // a press and release closer than this is a click
} // namespace

ViewportWidget::ViewportWidget(QWidget* parent, int samples) : QOpenGLWidget(parent)
{
    setFormat(render::rendererSurfaceFormat(samples));
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus);
}

ViewportWidget::~ViewportWidget() { releaseRenderer(); }

void ViewportWidget::releaseRenderer()
{
    if (!m_renderer) return;
    if (context() != nullptr) {
        makeCurrent();
        m_renderer->release();
        doneCurrent();
    }
    m_renderer.reset();
}

void ViewportWidget::setScene(render::SceneContent scene, const render::LayoutOptions& layout)
{
    m_scene = std::move(scene);
    m_sceneUploaded = false;
    m_layout = layout;
    update();
}

void ViewportWidget::setVisibility(const render::SceneVisibility& visibility)
{
    m_visibility = visibility;
    update();
}

void ViewportWidget::setCamera(const render::Camera& camera)
{
    m_camera = camera;
    m_cameraChosen = true;
    emit cameraChanged();
    update();
}

void ViewportWidget::setCameraPreset(render::CameraPreset preset) { setCamera(m_camera.withPreset(preset)); }

void ViewportWidget::setFrame(int frame)
{
    m_frame = frame;
    m_time.reset();
    update();
}

void ViewportWidget::setTime(double seconds)
{
    m_time = seconds;
    update();
}

void ViewportWidget::initializeGL()
{
    m_renderer = std::make_unique<render::Renderer>();
    m_sceneUploaded = false;
    if (auto status = m_renderer->initialize(); !status.ok()) {
        emit renderError(QString::fromStdString(status.error().message));
        m_renderer.reset();
        return;
    }
    // The context goes away with the widget's window: free GL objects while it is current.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseRenderer,
            Qt::UniqueConnection);
}

QSize ViewportWidget::pixelSize() const
{
    const qreal ratio = devicePixelRatioF();
    return {int(std::lround(width() * ratio)), int(std::lround(height() * ratio))};
}

void ViewportWidget::paintGL()
{
    if (!m_renderer) return;
    if (m_scene && !m_sceneUploaded) {
        const auto status = m_renderer->setScene(*m_scene, m_layout);
        m_sceneUploaded = true;
        if (!status.ok()) emit renderError(QString::fromStdString(status.error().message));
        else if (!m_cameraChosen) {
            m_camera = m_renderer->framingCamera();
            emit cameraChanged();
        }
    }
    if (m_renderer->hasScene()) {
        m_renderer->setVisibility(m_visibility);
        if (m_time) m_renderer->setTime(*m_time);
        else m_renderer->setFrame(m_frame);
    }
    m_renderer->render(m_camera, pixelSize());
}

void ViewportWidget::mousePressEvent(QMouseEvent* event)
{
    m_pressPosition = m_lastPosition = event->position().toPoint();
    m_dragButton = event->button();
    m_dragged = false;
    event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastPosition;
    m_lastPosition = position;
    if ((position - m_pressPosition).manhattanLength() >= kClickSlopPixels) m_dragged = true;
    if (!m_dragged || m_dragButton == Qt::NoButton) return;
    if (m_dragButton == Qt::LeftButton)
        m_camera.orbitBy(-float(delta.x()) * kDegreesPerPixel, float(delta.y()) * kDegreesPerPixel);
    else
        m_camera.panBy(QPointF(delta) * devicePixelRatioF(), pixelSize());
    m_cameraChosen = true;
    emit cameraChanged();
    update();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    const bool click = !m_dragged && m_dragButton == Qt::LeftButton && event->button() == Qt::LeftButton;
    m_dragButton = Qt::NoButton;
    if (!click || !m_renderer || !m_renderer->hasScene()) return;
    makeCurrent();
    m_renderer->setVisibility(m_visibility);
    const qreal ratio = devicePixelRatioF();
    const QPoint pixel(int(event->position().x() * ratio), int(event->position().y() * ratio));
    const auto picked = m_renderer->pick(m_camera, pixelSize(), pixel);
    doneCurrent();
    if (picked) emit partPicked(picked->takeSlot, QString::fromStdString(picked->partName));
    else emit backgroundPicked();
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    const float steps = float(event->angleDelta().y()) / 120.0f;
    if (steps == 0.0f) return;
    m_camera.zoomBy(std::pow(1.12f, steps));
    m_cameraChosen = true;
    emit cameraChanged();
    update();
    event->accept();
}

} // namespace bunraku::widgets
