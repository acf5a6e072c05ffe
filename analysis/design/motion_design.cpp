#include "analysis/design/motion_design.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <algorithm>
#include <cmath>

namespace bunraku::analysis {

namespace {

std::vector<std::string> coordinateNames()
{
    std::vector<std::string> names;
    for (const Channel& channel : axisCoordinateChannels()) names.push_back(channel.name());
    return names;
}

} // namespace

Result<DesignBasis> prepareDesign(const AxisModel& model, const Take& functional, const AxisOptions& options,
                                  const RunControl& control)
{
    Result<MotionAxis> axis = computeMotionAxis(model, functional, options, control);
    if (!axis) return axis.error();
    Result<RelativeMotion> relative = relativeMotion(functional, axis->world_T_axis);
    if (!relative) return relative.error();
    DesignBasis basis;
    basis.functional = functional;
    basis.coordinates = axisCoordinates(axis->world_T_axis);
    basis.axis = std::move(axis).value();
    basis.relative = std::move(relative).value();
    return basis;
}

DesignedMotion designMotion(const DesignBasis& basis, const WarpCurve& warp, const GainSet& gains)
{
    const Eigen::Index sourceFrames = basis.coordinates.rows();
    const Eigen::MatrixXd scaled = applyGains(basis.coordinates, gains);
    const WarpCurve curve = validateWarpCurve(warp).ok() ? warp : identityWarp(sourceFrames);
    const Eigen::VectorXd at = sampleWarp(curve);

    DesignedMotion designed;
    designed.axisCoordinates = resampleRows(scaled, at);
    const Eigen::Index frames = at.size();
    designed.world_T_axis.resize(std::size_t(frames));
    const std::size_t parts = basis.relative.parts.size();
    const std::vector<SixDofPart> layout = sixDofParts(basis.functional);

    Take& take = designed.take;
    take.rateHz = basis.functional.rateHz;
    take.channels = basis.functional.channels;
    take.labels = basis.functional.labels;
    take.labels.source = "design from " + basis.functional.displayName();
    take.values.resize(frames, basis.functional.channelCount());
    const Eigen::Index last = sourceFrames - 1;
    for (Eigen::Index u = 0; u < frames; ++u) {
        const double s = std::clamp(at[u], 0.0, double(last));
        const Eigen::Index k = std::min<Eigen::Index>(Eigen::Index(s), std::max<Eigen::Index>(last - 1, 0));
        const Eigen::Index k1 = std::min(k + 1, last);
        const double w = s - double(k);
        take.values.row(u) = (1.0 - w) * basis.functional.values.row(k) + w * basis.functional.values.row(k1);
        // step 3 at both neighbouring source frames (scaled axis * relative), then interpolated
        const RigidTransform axisK = axisFromCoordinates(scaled.row(k));
        const RigidTransform axisK1 = axisFromCoordinates(scaled.row(k1));
        designed.world_T_axis[std::size_t(u)] = axisFromCoordinates(designed.axisCoordinates.row(u));
        for (std::size_t p = 0; p < parts && p < layout.size(); ++p) {
            const RigidTransform a = axisK * basis.relative.axis_T_part[std::size_t(k)][p];
            const RigidTransform b = axisK1 * basis.relative.axis_T_part[std::size_t(k1)][p];
            const RigidTransform pose{a.rotation.slerp(w, b.rotation).normalized(), (1.0 - w) * a.translation + w * b.translation};
            if (u == 0) {
                const Eigen::Index first = layout[p].firstChannel;
                const YawPitchRoll stored{take.values(0, first + 3), take.values(0, first + 4), take.values(0, first + 5)};
                const YawPitchRoll angles = nearestEquivalent(yawPitchRollFromRotation(pose.rotation), stored);
                take.values.block(0, first, 1, 3) = pose.translation.transpose();
                take.values(0, first + 3) = angles.yaw;
                take.values(0, first + 4) = angles.pitch;
                take.values(0, first + 5) = angles.roll;
            } else {
                setPartPose(take, u, layout[p].firstChannel, pose);
            }
        }
    }
    if (basis.functional.skeleton) designed.take.skeleton = designedSkeleton(basis, at, designed.world_T_axis);
    return designed;
}

SkeletalMotionPtr designedSkeleton(const DesignBasis& basis, const Eigen::VectorXd& at,
                                   const std::vector<RigidTransform>& world_T_designedAxis)
{
    if (!basis.functional.skeleton || basis.functional.skeleton->frameCount() == 0) return nullptr;
    const SkeletalMotion& source = *basis.functional.skeleton;
    // Every joint at the warped time, then the whole body (the roots of the parts' chains) moved
    // by the axis correction world_T_designedAxis * (world_T_axis at the warped time)^-1: the
    // relative motion of every joint in the axis frame is kept, as for the 4 parts.
    SkeletalMotionPtr warped = resampleSkeletalMotion(source, at);
    const Eigen::MatrixXd functionalAxis = resampleRows(basis.coordinates, at);
    std::vector<RigidTransform> corrections(std::size_t(at.size()));
    for (Eigen::Index u = 0; u < at.size(); ++u)
        corrections[std::size_t(u)] = world_T_designedAxis[std::size_t(u)] * axisFromCoordinates(functionalAxis.row(u)).inverse();
    return moveSkeletalRoots(*warped, corrections, partChainRoots(*source.skeleton));
}

Result<GainSet> extractGainsWithWarp(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                                     const Eigen::VectorXd& functionalToEmotional,
                                     const std::vector<Eigen::Index>& boundaries, const GainOptions& options)
{
    if (functionalToEmotional.size() != functional.rows())
        return makeError(ErrorCode::InvalidArgument, "the warp has " + std::to_string(functionalToEmotional.size()) +
                                                         " frames but the functional axis " + std::to_string(functional.rows()));
    return extractGains(functional, resampleRows(emotional, functionalToEmotional), boundaries, coordinateNames(), options);
}

Result<DesignParameters> extractDesign(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                                       const ExtractionOptions& options, const RunControl& control)
{
    const std::vector<Eigen::Index> boundaries =
        options.boundaries.empty() ? suggestPhraseBoundaries(functional, options.phrases) : options.boundaries;
    DesignParameters parameters;
    Eigen::MatrixXd reference = functional;
    for (int pass = 0; pass <= std::max(0, options.refinementPasses); ++pass) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "design extraction cancelled");
        Result<PhaseResult> phase = extractPhase(reference, emotional, options.phase, control);
        if (!phase) return phase.error();
        parameters.phase = std::move(phase).value();
        // the functional -> emotional map consistent with the design curve: invert the curve's samples
        const Eigen::VectorXd designWarp = sampleWarp(parameters.phase.curve);
        const Eigen::VectorXd functionalToEmotional = invertMonotone(designWarp, functional.rows());
        parameters.emotionalOnFunctionalTime = resampleRows(emotional, functionalToEmotional);
        Result<GainSet> gains = extractGains(functional, parameters.emotionalOnFunctionalTime, boundaries, coordinateNames(),
                                             options.gains);
        if (!gains) return gains.error();
        parameters.gains = std::move(gains).value();
        reference = applyGains(functional, parameters.gains);
    }
    return parameters;
}

Result<GainSet> extractGainsForBoundaries(const Eigen::MatrixXd& functional, const DesignParameters& parameters,
                                          const std::vector<Eigen::Index>& boundaries, const GainOptions& options)
{
    if (parameters.emotionalOnFunctionalTime.rows() != functional.rows() ||
        parameters.emotionalOnFunctionalTime.cols() != functional.cols())
        return makeError(ErrorCode::InvalidArgument,
                         "the extraction has " + std::to_string(parameters.emotionalOnFunctionalTime.rows()) + " x " +
                             std::to_string(parameters.emotionalOnFunctionalTime.cols()) + " axis samples but the functional axis " +
                             std::to_string(functional.rows()) + " x " + std::to_string(functional.cols()));
    const std::vector<std::string> names =
        parameters.gains.dofNames.size() == std::size_t(functional.cols()) ? parameters.gains.dofNames : coordinateNames();
    return extractGains(functional, parameters.emotionalOnFunctionalTime, boundaries, names, options);
}

double relativeError(const Eigen::MatrixXd& designed, const Eigen::MatrixXd& measured)
{
    const Eigen::Index rows = std::min(designed.rows(), measured.rows());
    const Eigen::Index cols = std::min(designed.cols(), measured.cols());
    const double denominator = measured.topLeftCorner(rows, cols).norm();
    if (denominator <= 0.0) return designed.topLeftCorner(rows, cols).norm() > 0.0 ? INFINITY : 0.0;
    return (designed.topLeftCorner(rows, cols) - measured.topLeftCorner(rows, cols)).norm() / denominator;
}

} // namespace bunraku::analysis
