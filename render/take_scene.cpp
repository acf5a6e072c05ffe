#include "render/take_scene.h"

namespace bunraku::render {

analysis::Result<SceneContent> makeTakeScene(const analysis::BodyDescription& body, std::vector<analysis::Take> takes,
                                             const TakeSceneOptions& options, const analysis::RunControl& control)
{
    SceneContent scene;
    scene.body = body;
    for (analysis::Take& take : takes) scene.takes.push_back(TakeSlot{std::move(take), {}});
    if (auto status = validateScene(scene); !status.ok()) return status.error();
    if (options.computeAxes) {
        const analysis::AxisModel model = analysis::makeAxisModel(body, options.axis);
        for (TakeSlot& slot : scene.takes) {
            auto axis = analysis::computeMotionAxis(model, slot.take, options.axis, control);
            if (!axis.ok()) return axis.error();
            slot.world_T_axis = std::move(axis->world_T_axis);
        }
    }
    return scene;
}

} // namespace bunraku::render
