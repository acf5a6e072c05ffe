#pragma once
/// A copy of the 3D view drawn offscreen at any size, for video export at a resolution other
/// than the view's own: the same takes (with their motion axes when the axis is shown), camera
/// and object toggles, rendered by render::OffscreenRenderer in its own OpenGL context.

#include "analysis/core/result.h"
#include "analysis/core/take.h"
#include "render/camera.h"
#include "render/offscreen_renderer.h"
#include "render/scene.h"

#include <QImage>
#include <QSize>

#include <memory>
#include <optional>
#include <vector>

namespace bunraku::app {

class OffscreenView {
public:
    /// The takes (one or two, each with the puppet layout) on the default body; the motion axes
    /// are computed here when `visibility.axis` is set. Without a camera, the renderer's
    /// framingCamera. `kimonos` (per take, may be shorter or hold nulls): the kimono each take's
    /// puppet wears as cloth, as the 3D view draws it (ViewportPanel::drawnKimonos). Errors: no
    /// takes, no OpenGL 3.3 context.
    static analysis::Result<std::unique_ptr<OffscreenView>> create(std::vector<analysis::Take> takes,
                                                                   const std::optional<render::Camera>& camera,
                                                                   const render::SceneVisibility& visibility, QSize size,
                                                                   const std::vector<std::shared_ptr<const analysis::KimonoSimulation>>& kimonos = {});

    /// The scene at `seconds` (the frame nearest it in every take), `size` pixels, opaque.
    QImage render(double seconds);
    QSize size() const { return m_size; }

private:
    OffscreenView() = default;

    std::unique_ptr<render::OffscreenRenderer> m_renderer;
    render::Camera m_camera;
    QSize m_size;
};

} // namespace bunraku::app
