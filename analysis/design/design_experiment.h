#pragma once
/// The design experiment (thesis 5.5, "a generated friendly tea matched the measured one"):
/// extract phase and gains of an emotional take against its functional take, design from the
/// functional take with them, and compare the designed axis with the measured emotional axis
/// (relative error of eq. 5.18's form) and, when known, the phase with the true one.

#include "analysis/axis/inertia_axis.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"
#include "analysis/design/motion_design.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

struct DesignCell {
    std::string function;
    std::string emotion;
    Take functional; ///< e.g. the function's mean
    Take emotional;  ///< e.g. the cell's mean
    /// Optional truth: for each emotional frame the functional frame it shows (empty if unknown).
    Eigen::VectorXd trueEmotionalToFunctional;
};

struct DesignCellResult {
    std::string function;
    std::string emotion;
    /// eq. 5.18 form over the 6 axis coordinates: designed take's axis vs measured emotional axis.
    double axisRelativeError = 0.0;
    /// The same for the undesigned functional axis (what design improves on).
    double functionalRelativeError = 0.0;
    /// Per axis coordinate (x y z rot_x rot_y rot_z): eq. 5.18 per DOF.
    Eigen::VectorXd dofRelativeError;
    /// Mean |extracted - true| emotional->functional correspondence, frames (NaN without truth).
    double phaseMeanAbsErrorFrames = 0.0;
    std::vector<Eigen::Index> boundaries;
    DesignParameters parameters;
};

/// Runs extraction and design for one cell. The designed take's axis is recomputed from its
/// poses (not taken from the design's own axis), so the comparison is end to end.
Result<DesignCellResult> evaluateDesignCell(const AxisModel& model, const DesignCell& cell,
                                            const ExtractionOptions& options = {}, const AxisOptions& axisOptions = {},
                                            const RunControl& control = {});

} // namespace bunraku::analysis
