#include "render/offscreen_renderer.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>

namespace bunraku::render {

QSurfaceFormat rendererSurfaceFormat(int samples)
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(samples);
    return format;
}

OffscreenRenderer::OffscreenRenderer(const OffscreenOptions& options) : m_options(options) {}

analysis::Result<std::unique_ptr<OffscreenRenderer>> OffscreenRenderer::create(const OffscreenOptions& options)
{
    using analysis::ErrorCode;
    std::unique_ptr<OffscreenRenderer> result(new OffscreenRenderer(options));
    result->m_context = std::make_unique<QOpenGLContext>();
    result->m_context->setFormat(rendererSurfaceFormat());
    if (!result->m_context->create())
        return analysis::makeError(ErrorCode::Unsupported, "could not create an OpenGL context on this platform");
    const QSurfaceFormat actual = result->m_context->format();
    result->m_surface = std::make_unique<QOffscreenSurface>();
    result->m_surface->setFormat(actual);
    result->m_surface->create();
    if (!result->m_surface->isValid())
        return analysis::makeError(ErrorCode::Unsupported, "could not create an offscreen surface");
    if (!result->makeCurrent())
        return analysis::makeError(ErrorCode::Unsupported, "could not make the OpenGL context current");
    if (auto status = result->m_renderer.initialize(); !status.ok())
        return analysis::makeError(ErrorCode::Unsupported,
                                   status.error().message + " (platform offered OpenGL " +
                                       std::to_string(actual.majorVersion()) + "." +
                                       std::to_string(actual.minorVersion()) + ")");
    return result;
}

OffscreenRenderer::~OffscreenRenderer()
{
    if (m_context && makeCurrent()) {
        m_framebuffers.clear();
        m_renderer.release();
        m_context->doneCurrent();
    }
}

bool OffscreenRenderer::makeCurrent() { return m_context && m_context->makeCurrent(m_surface.get()); }

void OffscreenRenderer::doneCurrent()
{
    if (m_context) m_context->doneCurrent();
}

analysis::Status OffscreenRenderer::setScene(const SceneContent& scene, const LayoutOptions& layout)
{
    if (!makeCurrent()) return analysis::makeError(analysis::ErrorCode::Unsupported, "lost the OpenGL context");
    return m_renderer.setScene(scene, layout);
}

QOpenGLFramebufferObject& OffscreenRenderer::framebuffer(QSize size, int samples)
{
    auto& framebuffer = m_framebuffers[samples];
    if (!framebuffer || framebuffer->size() != size) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::Depth);
        format.setSamples(samples);
        format.setInternalTextureFormat(GL_RGBA8);
        framebuffer = std::make_unique<QOpenGLFramebufferObject>(size, format);
    }
    return *framebuffer;
}

QImage OffscreenRenderer::render(const Camera& camera, QSize size) { return render(camera, size, m_options.samples); }

QImage OffscreenRenderer::render(const Camera& camera, QSize size, int samples)
{
    if (size.isEmpty() || !makeCurrent()) return {};
    QOpenGLFramebufferObject& target = framebuffer(size, samples);
    target.bind();
    m_renderer.render(camera, size);
    QImage image = target.toImage();
    target.release();
    return image.convertToFormat(QImage::Format_RGB32);
}

void OffscreenRenderer::draw(const Camera& camera, QSize size)
{
    if (size.isEmpty() || !makeCurrent()) return;
    QOpenGLFramebufferObject& target = framebuffer(size, m_options.samples);
    target.bind();
    m_renderer.render(camera, size);
    target.release();
}

std::optional<PickResult> OffscreenRenderer::pick(const Camera& camera, QSize size, QPoint pixel)
{
    if (!makeCurrent()) return std::nullopt;
    return m_renderer.pick(camera, size, pixel);
}

QImage OffscreenRenderer::partIdImage(const Camera& camera, QSize size)
{
    if (!makeCurrent()) return {};
    return m_renderer.partIdImage(camera, size);
}

void OffscreenRenderer::finish()
{
    if (makeCurrent()) m_context->functions()->glFinish();
}

} // namespace bunraku::render
