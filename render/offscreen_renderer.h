#pragma once
/// The Renderer without a window: its own OpenGL 3.3 core context on a QOffscreenSurface and a
/// framebuffer object, for tests, screenshots, frame sequences and the `bunraku render` command.
/// Needs a QGuiApplication (any platform with OpenGL: xcb under Xvfb, or offscreen with Mesa).

#include "analysis/core/result.h"
#include "render/renderer.h"

#include <QImage>

#include <map>
#include <memory>

class QOffscreenSurface;
class QOpenGLContext;
class QOpenGLFramebufferObject;

namespace bunraku::render {

struct OffscreenOptions {
    int samples = 4; ///< multisampling of the colour image (0 = none: exact pixels for tests)
};

class OffscreenRenderer {
public:
    /// Creates the context and initialises the renderer; Unsupported when OpenGL 3.3 core is
    /// not available (the message says what the platform offered).
    static analysis::Result<std::unique_ptr<OffscreenRenderer>> create(const OffscreenOptions& options = {});
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    /// The renderer, for setScene / setVisibility / setFrame. Its GL calls need makeCurrent().
    Renderer& renderer() { return m_renderer; }
    /// Makes the offscreen context current (the methods below do it themselves).
    bool makeCurrent();
    /// Releases the offscreen context from this thread (after makeCurrent, when done).
    void doneCurrent();

    analysis::Status setScene(const SceneContent& scene, const LayoutOptions& layout = {});
    /// One image of `size` pixels (ARGB32, opaque).
    QImage render(const Camera& camera, QSize size);
    /// The same with `samples` multisampling instead of OffscreenOptions::samples (an
    /// interactive view draws moving frames with 0, then the still frame with its usual count);
    /// one framebuffer is kept per sample count.
    QImage render(const Camera& camera, QSize size, int samples);
    /// Draws into the framebuffer without reading it back (what a widget's frame costs).
    void draw(const Camera& camera, QSize size);
    std::optional<PickResult> pick(const Camera& camera, QSize size, QPoint pixel);
    QImage partIdImage(const Camera& camera, QSize size);
    /// Waits for the GPU to finish (for timing).
    void finish();

private:
    explicit OffscreenRenderer(const OffscreenOptions& options);
    QOpenGLFramebufferObject& framebuffer(QSize size, int samples);

    OffscreenOptions m_options;
    std::unique_ptr<QOffscreenSurface> m_surface;
    std::unique_ptr<QOpenGLContext> m_context;
    std::map<int, std::unique_ptr<QOpenGLFramebufferObject>> m_framebuffers; ///< by sample count
    Renderer m_renderer;
};

/// The surface format the renderer needs: OpenGL 3.3 core, 24-bit depth.
QSurfaceFormat rendererSurfaceFormat(int samples = 0);

} // namespace bunraku::render
