#include "render/take_scene.h"

#include "analysis/body/body_fit.h"

namespace bunraku::render {

analysis::Result<SceneContent> makeTakeScene(const analysis::BodyDescription& body, std::vector<analysis::Take> takes,
                                             const TakeSceneOptions& options, const analysis::RunControl& control)
{
    SceneContent scene;
    scene.body = body;
    for (analysis::Take& take : takes) {
        TakeSlot slot{std::move(take), {}};
        if (options.fitToSkeleton && slot.take.skeleton) slot.body = std::make_shared<const analysis::BodyDescription>(analysis::bodyForTake(body, slot.take));
        scene.takes.push_back(std::move(slot));
    }
    if (auto status = validateScene(scene); !status.ok()) return status.error();
    if (options.computeAxes) {
        const analysis::AxisModel model = analysis::makeAxisModel(body, options.axis);
        for (TakeSlot& slot : scene.takes) {
            const analysis::AxisModel own = slot.body ? analysis::makeAxisModel(*slot.body, options.axis) : analysis::AxisModel{};
            auto axis = analysis::computeMotionAxis(slot.body ? own : model, slot.take, options.axis, control);
            if (!axis.ok()) return axis.error();
            slot.world_T_axis = std::move(axis->world_T_axis);
        }
    }
    return scene;
}

} // namespace bunraku::render
