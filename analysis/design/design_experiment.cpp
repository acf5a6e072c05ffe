#include "analysis/design/design_experiment.h"

#include "analysis/axis/axis_channels.h"

#include <cmath>
#include <limits>

namespace bunraku::analysis {

Result<DesignCellResult> evaluateDesignCell(const AxisModel& model, const DesignCell& cell, const ExtractionOptions& options,
                                            const AxisOptions& axisOptions, const RunControl& control)
{
    Result<DesignBasis> basis = prepareDesign(model, cell.functional, axisOptions, control);
    if (!basis) return basis.error();
    Result<MotionAxis> emotionalAxis = computeMotionAxis(model, cell.emotional, axisOptions, control);
    if (!emotionalAxis) return emotionalAxis.error();
    const Eigen::MatrixXd measured = axisCoordinates(emotionalAxis->world_T_axis);
    Result<DesignParameters> parameters = extractDesign(basis->coordinates, measured, options, control);
    if (!parameters) return parameters.error();

    WarpCurve warp = parameters->phase.curve;
    warp.outputFrames = measured.rows();
    const DesignedMotion designed = designMotion(*basis, warp, parameters->gains);
    Result<MotionAxis> designedAxis = computeMotionAxis(model, designed.take, axisOptions, control);
    if (!designedAxis) return designedAxis.error();
    const Eigen::MatrixXd designedCoordinates = axisCoordinates(designedAxis->world_T_axis);

    DesignCellResult result;
    result.function = cell.function;
    result.emotion = cell.emotion;
    result.axisRelativeError = relativeError(designedCoordinates, measured);
    result.functionalRelativeError = relativeError(basis->coordinates, measured);
    result.dofRelativeError.resize(measured.cols());
    for (Eigen::Index d = 0; d < measured.cols(); ++d)
        result.dofRelativeError[d] = relativeError(designedCoordinates.col(d), measured.col(d));
    result.phaseMeanAbsErrorFrames = std::numeric_limits<double>::quiet_NaN();
    if (cell.trueEmotionalToFunctional.size() > 0) {
        const Eigen::VectorXd extracted = sampleWarp(warp);
        const Eigen::Index n = std::min(extracted.size(), cell.trueEmotionalToFunctional.size());
        result.phaseMeanAbsErrorFrames = (extracted.head(n) - cell.trueEmotionalToFunctional.head(n)).cwiseAbs().mean();
    }
    for (const PhraseGains& phrase : parameters->gains.phrases) result.boundaries.push_back(phrase.begin);
    if (!parameters->gains.phrases.empty()) result.boundaries.push_back(parameters->gains.phrases.back().end);
    result.parameters = std::move(parameters).value();
    return result;
}

} // namespace bunraku::analysis
