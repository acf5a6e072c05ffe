#include "app/offscreen_view.h"

#include "analysis/body/body_description.h"
#include "render/take_scene.h"

namespace bunraku::app {

analysis::Result<std::unique_ptr<OffscreenView>> OffscreenView::create(std::vector<analysis::Take> takes,
                                                                       const std::optional<render::Camera>& camera,
                                                                       const render::SceneVisibility& visibility, QSize size,
                                                                       const std::vector<std::shared_ptr<const analysis::KimonoSimulation>>& kimonos)
{
    if (takes.empty())
        return analysis::makeError(analysis::ErrorCode::InvalidArgument, "no take that can pose the puppet is shown");
    if (size.isEmpty()) return analysis::makeError(analysis::ErrorCode::InvalidArgument, "the image size is empty");
    render::TakeSceneOptions sceneOptions;
    sceneOptions.computeAxes = visibility.axis;
    auto scene = render::makeTakeScene(analysis::defaultBodyDescription(), std::move(takes), sceneOptions);
    if (!scene) return scene.error();
    for (std::size_t t = 0; t < kimonos.size() && t < scene->takes.size(); ++t) scene->takes[t].kimono = kimonos[t];
    auto renderer = render::OffscreenRenderer::create();
    if (!renderer) return renderer.error();
    std::unique_ptr<OffscreenView> view(new OffscreenView);
    view->m_renderer = std::move(renderer.value());
    if (auto status = view->m_renderer->setScene(scene.value()); !status.ok()) return status.error();
    view->m_renderer->renderer().setVisibility(visibility);
    view->m_camera = camera.value_or(view->m_renderer->renderer().framingCamera());
    view->m_size = size;
    return view;
}

QImage OffscreenView::render(double seconds)
{
    if (!m_renderer->makeCurrent()) return {};
    m_renderer->renderer().setTime(seconds);
    return m_renderer->render(m_camera, m_size);
}

} // namespace bunraku::app
