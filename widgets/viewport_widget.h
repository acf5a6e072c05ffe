#pragma once
/// The 3D view as a widget: a raster QWidget that shows render::Renderer's image, drawn by an
/// OffscreenRenderer (its own OpenGL context on a QOffscreenSurface and a framebuffer object),
/// and drives it with the mouse (left drag orbits the camera, right or middle drag pans, the
/// wheel zooms, a click picks the body part under the pointer; Frame All, Frame Selected and
/// Reset Camera fit the camera to the scene's box, and a take of another size is framed again).
///
/// Why not a QOpenGLWidget: Qt composes a whole top-level window holding one through OpenGL on
/// every flush, so with a software rasteriser (Mesa llvmpipe under Xvfb or in a VM) every repaint
/// of any other view (24-48 graphs) paid a full-window GL composition. Here only this view uses
/// OpenGL; the window stays raster, docking and floating need no context migration, and
/// QWidget::grab() (screenshots) shows the puppet.
///
/// Cost model: scene uploads happen once, at the next paint after setScene; changing the frame
/// only updates uniforms, then one offscreen draw and one read-back of the view's pixels. A paint
/// without a change (expose, a neighbour's repaint) reuses the last image. A frame that follows
/// the previous one within kSettleMs (playback, a warp drag, orbiting) is drawn without
/// multisampling, about 3x cheaper on a software rasteriser; kSettleMs after the last change the
/// still frame is redrawn with the view's multisampling. grabFramebuffer always uses it.

#include "render/camera.h"
#include "render/framing.h"
#include "render/renderer.h"
#include "render/scene.h"

#include <QImage>
#include <QPoint>
#include <QTimer>

#include "widgets/clock.h"
#include <QWidget>

#include <memory>
#include <optional>

namespace bunraku::render {
class OffscreenRenderer;
}

namespace bunraku::widgets {

class ViewportWidget : public QWidget {
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
    /// Frame All (F): the camera keeps its angle and elevation and fits everything the scene
    /// draws over the whole take (viewport_camera.cpp).
    void frameAll();
    /// Frame Selected (Shift+F): fits take part `part` ("hand": the body parts it drives) of
    /// every shown take at the current frame; every figure at the current frame when `part` is
    /// empty or not drawn.
    void frameSelected(const QString& part);
    /// Reset Camera (Home with the view focused): the first view of a scene (angle 340 deg,
    /// elevation 15 deg) framing the whole take; new scenes are framed again until the camera
    /// is moved.
    void resetCamera();
    /// Follow: while on, every frame shown carries the camera along the floor to the middle of
    /// the figures at that frame (render::followingCamera: a walking take stays in frame at the
    /// size it was framed); orbiting and zooming still turn around it. Off by default.
    void setFollow(bool follow);
    bool follow() const { return m_follow; }
    /// Whether the camera was moved or set (then a new scene keeps its angle and elevation, and
    /// is reframed only when its box differs from the one the camera was framed for).
    bool cameraChosen() const { return m_cameraChosen; }
    /// The box the camera was last framed for (empty before a scene was shown).
    render::Bounds framedBounds() const { return m_framedFor.value_or(render::Bounds{}); }
    /// The renderer, for queries (displayed transforms, floor height); null before the first
    /// paint (or grabFramebuffer / makeCurrent) and when OpenGL 3.3 core is unavailable.
    const render::Renderer* renderer() const;

    /// Renders the current pose now and returns it: an opaque image of size() x
    /// devicePixelRatioF() pixels with that device pixel ratio (null without OpenGL). The same
    /// contract as QOpenGLWidget::grabFramebuffer, for screenshots and frame sequences.
    QImage grabFramebuffer();
    /// Makes the view's OpenGL context current (creating it on first use), e.g. to call the
    /// renderer's GL methods (partIdImage); false when OpenGL is unavailable.
    bool makeCurrent();
    void doneCurrent();
    /// Frames drawn by OpenGL so far (paints that reused the last image do not count).
    int renderedFrameCount() const { return m_renderedFrames; }
    /// Multisampling of the image shown now (0 while the view moves, else the view's samples).
    int shownSamples() const { return m_imageSamples; }
    /// A frame drawn this soon (ms) after the previous one is a moving frame.
    static constexpr int kSettleMs = 150;
    /// The clock that decides what "soon" is and times the still frame (null: the steady clock);
    /// tests inject a ManualClock.
    void setClock(Clock* clock);

public slots:
    /// Shows frame `frame` of every take.
    void setFrame(int frame);
    /// Shows the frame nearest `seconds` of every take.
    void setTime(double seconds);

signals:
    /// A click (no drag) on a body part of take `takeSlot` (0 = left/first, 1 = right/second).
    void partPicked(int takeSlot, const QString& partName);
    /// A click on a bone of take `takeSlot`'s skeleton: its joint, and the puppet part the joint
    /// carries ("" when none; partPicked follows when there is one).
    void bonePicked(int takeSlot, const QString& jointName, const QString& partName);
    /// A click on the background.
    void backgroundPicked();
    void cameraChanged();
    void renderError(const QString& message);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    QSize pixelSize() const;
    /// Creates the offscreen renderer on first use; false when OpenGL is unavailable.
    bool ensureRenderer();
    /// Uploads a pending scene and poses the renderer at the current frame (context current).
    void prepareFrame();
    /// Draws the current frame into m_image with `samples` (context made current here).
    void renderImage(int samples);
    /// Marks the image stale and schedules a paint.
    void invalidate();
    /// After a scene upload: a camera never moved frames the scene from the first view; a
    /// chosen one keeps its angle and is refitted when the scene's box differs from the one it
    /// was framed for (a take of another size, or walking elsewhere).
    void adaptCameraToScene();
    /// The renderer's box for `query` with the pending scene uploaded; empty without OpenGL.
    render::Bounds sceneBounds(const render::BoundsQuery& query);

    std::unique_ptr<render::OffscreenRenderer> m_offscreen;
    int m_samples = 4;
    bool m_unavailable = false; ///< creating the OpenGL context failed (message in m_error)
    QString m_error;
    QImage m_image; ///< the last rendered frame
    int m_imageSamples = 0;
    bool m_imageStale = true;
    Clock* m_clock = &steadyClock();
    std::optional<qint64> m_lastFrameMs; ///< when the last frame was drawn (m_clock)
    ClockTimer m_settle;                 ///< redraws the still frame with multisampling
    int m_renderedFrames = 0;
    std::optional<render::SceneContent> m_scene; ///< kept until uploaded
    bool m_sceneUploaded = false;
    render::LayoutOptions m_layout;
    render::SceneVisibility m_visibility;
    render::Camera m_camera;
    bool m_cameraChosen = false; ///< set by setCamera or the mouse: scenes no longer reset it
    bool m_follow = false;
    std::optional<render::Bounds> m_framedFor; ///< the box the camera fits; none: adopt the next scene's
    bool m_reframe = false; ///< a new scene, or figures shown or hidden: adapt the camera at the next paint
    int m_frame = 0;
    std::optional<double> m_time; ///< when set, wins over m_frame
    QPoint m_pressPosition;
    QPoint m_lastPosition;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    bool m_dragged = false;
};

} // namespace bunraku::widgets
