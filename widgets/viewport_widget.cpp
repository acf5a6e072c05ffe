#include "widgets/viewport_widget.h"

#include "render/offscreen_renderer.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

namespace bunraku::widgets {

namespace {
constexpr float kDegreesPerPixel = 0.4f;
constexpr int kClickSlopPixels = 4; // a press and release closer than this is a click
} // namespace

ViewportWidget::ViewportWidget(QWidget* parent, int samples) : QWidget(parent), m_samples(samples)
{
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus);
    // Every paint covers the whole widget with the rendered image: no background fill needed.
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &ClockTimer::timeout, this, [this] {
        if (m_imageSamples == m_samples || !isVisible()) return;
        renderImage(m_samples); // the still, full-quality frame
        update();
    });
}

ViewportWidget::~ViewportWidget() = default; // the OffscreenRenderer frees its GL objects

void ViewportWidget::setClock(Clock* clock)
{
    m_clock = clock ? clock : &steadyClock();
    m_settle.setClock(m_clock);
    m_lastFrameMs.reset();
}

const render::Renderer* ViewportWidget::renderer() const { return m_offscreen ? &m_offscreen->renderer() : nullptr; }

bool ViewportWidget::ensureRenderer()
{
    if (m_offscreen) return true;
    if (m_unavailable) return false;
    auto made = render::OffscreenRenderer::create(render::OffscreenOptions{m_samples});
    if (!made) {
        m_unavailable = true;
        m_error = QString::fromStdString(made.error().message);
        emit renderError(m_error);
        return false;
    }
    m_offscreen = std::move(*made);
    m_sceneUploaded = false;
    return true;
}

bool ViewportWidget::makeCurrent() { return ensureRenderer() && m_offscreen->makeCurrent(); }

void ViewportWidget::doneCurrent()
{
    if (m_offscreen) m_offscreen->doneCurrent();
}

void ViewportWidget::invalidate()
{
    m_imageStale = true;
    update();
}

void ViewportWidget::setScene(render::SceneContent scene, const render::LayoutOptions& layout)
{
    m_scene = std::move(scene);
    m_sceneUploaded = false;
    m_layout = layout;
    invalidate();
}

void ViewportWidget::setVisibility(const render::SceneVisibility& visibility)
{
    m_visibility = visibility;
    m_reframe = true; // a figure shown or hidden may change what the framing camera fits
    invalidate();
}

void ViewportWidget::setCamera(const render::Camera& camera)
{
    m_camera = camera;
    m_cameraChosen = true;
    // The camera fits the scene shown now, or (none uploaded yet: a project's camera) the next.
    m_framedFor.reset();
    if (!m_scene && m_offscreen && m_offscreen->renderer().hasScene()) {
        render::BoundsQuery figures;
        figures.figuresOnly = true;
        m_framedFor = sceneBounds(figures);
    }
    emit cameraChanged();
    invalidate();
}

void ViewportWidget::setCameraPreset(render::CameraPreset preset) { setCamera(m_camera.withPreset(preset)); }

void ViewportWidget::setFrame(int frame)
{
    m_frame = frame;
    m_time.reset();
    invalidate();
}

void ViewportWidget::setTime(double seconds)
{
    m_time = seconds;
    invalidate();
}

QSize ViewportWidget::pixelSize() const
{
    const qreal ratio = devicePixelRatioF();
    return {int(std::lround(width() * ratio)), int(std::lround(height() * ratio))};
}

void ViewportWidget::prepareFrame()
{
    render::Renderer& renderer = m_offscreen->renderer();
    if (m_scene && !m_sceneUploaded) {
        const auto status = m_offscreen->setScene(*m_scene, m_layout);
        m_sceneUploaded = true;
        m_scene.reset(); // the renderer keeps what it needs; the context never changes
        if (!status.ok()) emit renderError(QString::fromStdString(status.error().message));
        else m_reframe = true;
    }
    if (renderer.hasScene()) {
        renderer.setVisibility(m_visibility);
        if (m_time) renderer.setTime(*m_time);
        else renderer.setFrame(m_frame);
        if (m_reframe) adaptCameraToScene();
        m_reframe = false;
        if (m_follow) {
            render::BoundsQuery now;
            now.span = render::FramingSpan::CurrentFrame;
            now.figuresOnly = true;
            m_camera = render::followingCamera(m_camera, renderer.displayedBounds(m_camera, now));
        }
    }
}

void ViewportWidget::setFollow(bool follow)
{
    if (m_follow == follow) return;
    m_follow = follow;
    invalidate();
}

void ViewportWidget::renderImage(int samples)
{
    if (!makeCurrent()) return;
    prepareFrame();
    // A moving view's frames (fewer samples) are drafts: cheaper shadows (Renderer::setDraft).
    m_offscreen->renderer().setDraft(samples < m_samples);
    m_image = m_offscreen->render(m_camera, pixelSize(), samples);
    m_image.setDevicePixelRatio(devicePixelRatioF());
    m_imageSamples = samples;
    m_imageStale = false;
    ++m_renderedFrames;
    m_lastFrameMs = m_clock->milliseconds();
    if (samples != m_samples) m_settle.start();
    else m_settle.stop();
}

QImage ViewportWidget::grabFramebuffer()
{
    renderImage(m_samples);
    return m_image;
}

void ViewportWidget::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    if (m_imageStale || m_image.size() != pixelSize()) {
        const bool moving = m_lastFrameMs && m_clock->milliseconds() - *m_lastFrameMs < kSettleMs;
        renderImage(moving ? 0 : m_samples);
    }
    if (m_image.isNull()) {
        painter.fillRect(rect(), palette().color(QPalette::Dark));
        if (m_unavailable)
            painter.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap,
                             tr("The 3D view needs OpenGL 3.3: %1").arg(m_error));
        return;
    }
    // Into the whole widget: with a fractional device pixel ratio the image's pixel size is
    // rounded, and the widget is opaque (nothing else paints a strip the image misses).
    painter.drawImage(QRectF(rect()), m_image);
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
    invalidate();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event)
{
    const bool click = !m_dragged && m_dragButton == Qt::LeftButton && event->button() == Qt::LeftButton;
    m_dragButton = Qt::NoButton;
    if (!click || !makeCurrent()) return;
    prepareFrame();
    if (!m_offscreen->renderer().hasScene()) return;
    const qreal ratio = devicePixelRatioF();
    const QPoint pixel(int(event->position().x() * ratio), int(event->position().y() * ratio));
    const auto picked = m_offscreen->pick(m_camera, pixelSize(), pixel);
    if (!picked) {
        emit backgroundPicked();
        return;
    }
    if (picked->joint >= 0)
        emit bonePicked(picked->takeSlot, QString::fromStdString(picked->jointName), QString::fromStdString(picked->partName));
    // A bone selects the graphs of the puppet part it carries, when it carries one.
    if (!picked->partName.empty()) emit partPicked(picked->takeSlot, QString::fromStdString(picked->partName));
}

void ViewportWidget::wheelEvent(QWheelEvent* event)
{
    const float steps = float(event->angleDelta().y()) / 120.0f;
    if (steps == 0.0f) return;
    m_camera.zoomBy(std::pow(1.12f, steps));
    m_cameraChosen = true;
    emit cameraChanged();
    invalidate();
    event->accept();
}

} // namespace bunraku::widgets
