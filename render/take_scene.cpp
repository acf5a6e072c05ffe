#include "render/take_scene.h"

#include "analysis/axis/segment_inertia.h"
#include "analysis/body/body_fit.h"

#include <optional>

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
            // A take of a skeleton's joints: the performer's whole-body axis (segment_inertia.h).
            std::optional<analysis::AxisModel> own;
            if (analysis::usesSegmentModel(slot.take)) {
                auto segments = analysis::segmentBody(slot.take, analysis::SegmentModelOptions{options.axis.segments});
                if (!segments.ok()) return segments.error();
                own = std::move(segments->model);
            } else if (slot.body) {
                own = analysis::makeAxisModel(*slot.body, options.axis);
            }
            auto axis = analysis::computeMotionAxis(own ? *own : model, slot.take, options.axis, control);
            if (!axis.ok()) return axis.error();
            slot.world_T_axis = std::move(axis->world_T_axis);
        }
    }
    return scene;
}

} // namespace bunraku::render
