#pragma once
/// Builds a scene from takes: each take with the motion axis of the same body (thesis 5.2.1)
/// computed by the axis module, ready for Renderer::setScene. For the app and the command line.

#include "analysis/axis/inertia_axis.h"
#include "analysis/body/body_description.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"
#include "render/scene.h"

#include <vector>

namespace bunraku::render {

struct TakeSceneOptions {
    bool computeAxes = true;      ///< the motion axis of every take (else no axis is drawn)
    /// A take with a skeleton gets the body fitted to it (else every take is on `body` as given).
    bool fitToSkeleton = true;
    analysis::AxisOptions axis;   ///< mass-point lattice of the axis computation
};

/// One or two takes on `body`: a take with a skeleton whose parts are bound gets `body` fitted
/// to its performer (analysis/body/body_fit.h) as its own body, and its motion axis is computed
/// over that body. validateScene's errors, or the axis module's.
analysis::Result<SceneContent> makeTakeScene(const analysis::BodyDescription& body, std::vector<analysis::Take> takes,
                                             const TakeSceneOptions& options = {},
                                             const analysis::RunControl& control = {});

} // namespace bunraku::render
