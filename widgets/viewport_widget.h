#pragma once
/// The 3D view as a widget: a thin QOpenGLWidget that drives render::Renderer with the mouse
/// (left drag orbits the camera, right or middle drag pans, the wheel zooms, a click picks the
/// body part under the pointer). Scene uploads happen once, at the next paint after setScene;
/// changing the frame only updates uniforms.

#include "render/camera.h"
#include "render/renderer.h"
#include "render/scene.h"

#include <QOpenGLWidget>
#include <QPoint>

#include <memory>
#include <optional>

namespace bunraku::widgets {

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    /// `samples`: multisampling of the view (4 looks best; 0 is about 2.5x faster on a software
    /// rasteriser such as llvmpipe, see docs/PERFORMANCE.md).
    explicit ViewportWidget(QWidget* parent = nullptr, int samples = 4);
    ~ViewportWidget() override;

    /// Replaces the scene (one or two takes); uploaded at the next paint. Errors are reported
    /// by renderError (validateScene's message).
    void setScene(render::SceneContent scene, const render::LayoutOptions& layout = {});
    void setVisibility(const render::SceneVisibility& visibility);
    render::SceneVisibility visibility() const { return m_visibility; }
    /// Until a camera is set, each new scene is framed by Renderer::framingCamera.
    void setCamera(const render::Camera& camera);
    const render::Camera& camera() const { return m_camera; }
    void setCameraPreset(render::CameraPreset preset);
    /// The renderer, for queries (displayed transforms, floor height); null before the first paint.
    const render::Renderer* renderer() const { return m_renderer.get(); }

public slots:
    /// Shows frame `frame` of every take.
    void setFrame(int frame);
    /// Shows the frame nearest `seconds` of every take.
    void setTime(double seconds);

signals:
    /// A click (no drag) on a body part of take `takeSlot` (0 = left/first, 1 = right/second).
    void partPicked(int takeSlot, const QString& partName);
    /// A click on the background.
    void backgroundPicked();
    void cameraChanged();
    void renderError(const QString& message);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    QSize pixelSize() const;
    void releaseRenderer();

    std::unique_ptr<render::Renderer> m_renderer;
    std::optional<render::SceneContent> m_scene; ///< kept to re-upload into a new context
    bool m_sceneUploaded = false;
    render::LayoutOptions m_layout;
    render::SceneVisibility m_visibility;
    render::Camera m_camera;
    bool m_cameraChosen = false; ///< set by setCamera or the mouse: scenes no longer reframe it
    int m_frame = 0;
    std::optional<double> m_time; ///< when set, wins over m_frame
    QPoint m_pressPosition;
    QPoint m_lastPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_dragged = false;
};

} // namespace bunraku::widgets
