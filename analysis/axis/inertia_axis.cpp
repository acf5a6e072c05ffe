#include "analysis/axis/inertia_axis.h"

#include "analysis/body/puppet_mass.h"

#include "analysis/core/puppet_layout.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <sstream>

namespace bunraku::analysis {

namespace {

Eigen::Vector3d signedLike(const Eigen::Vector3d& v, const Eigen::Vector3d& reference)
{
    return v.dot(reference) < 0.0 ? Eigen::Vector3d(-v) : v;
}

/// `v` without its component along unit `normal`, normalised; `fallback` when that is too short.
Eigen::Vector3d projectedUnit(const Eigen::Vector3d& v, const Eigen::Vector3d& normal, const Eigen::Vector3d& fallback)
{
    const Eigen::Vector3d p = v - v.dot(normal) * normal;
    return p.norm() > 1e-9 ? Eigen::Vector3d(p.normalized()) : fallback;
}

const char* degeneracyName(Degeneracy degeneracy)
{
    switch (degeneracy) {
    case Degeneracy::None: return "none";
    case Degeneracy::LongAxis: return "least = middle moment (z undetermined)";
    case Degeneracy::CrossAxes: return "middle = largest moment (x, y undetermined)";
    case Degeneracy::Spherical: return "all moments equal";
    }
    return "none";
}

} // namespace

AxisModel makeAxisModel(const BodyDescription& body, const AxisOptions& options)
{
    AxisModel model;
    model.body = body;
    for (const MassPoints& points : bodyMassPoints(body, options.massPoints, &model.massSource)) {
        model.parts.push_back(partMoments(points));
        model.totalMass += model.parts.back().mass;
    }
    return model;
}

std::pair<Eigen::Vector3d, Eigen::Matrix3d> inertiaAboutCentre(const std::vector<PartMoments>& parts,
                                                               const std::vector<RigidTransform>& world_T_part)
{
    double mass = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    for (std::size_t p = 0; p < parts.size() && p < world_T_part.size(); ++p) {
        const PartMoments& part = parts[p];
        if (part.mass <= 0.0) continue;
        const Eigen::Matrix3d r = world_T_part[p].rotation.toRotationMatrix();
        const Eigen::Vector3d& t = world_T_part[p].translation;
        const Eigen::Vector3d rc = part.mass * (r * part.centre); // sum m R q
        second += r * part.secondMoment * r.transpose() + rc * t.transpose() + t * rc.transpose() + part.mass * t * t.transpose();
        first += rc + part.mass * t;
        mass += part.mass;
    }
    if (mass <= 0.0) return {Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()};
    const Eigen::Vector3d centre = first / mass;
    const Eigen::Matrix3d aboutCentre = second - mass * centre * centre.transpose();
    const Eigen::Matrix3d inertia = aboutCentre.trace() * Eigen::Matrix3d::Identity() - aboutCentre;
    return {centre, inertia};
}

InertiaAxes principalAxes(const Eigen::Vector3d& centre, const Eigen::Matrix3d& inertia, double degenerateTolerance,
                          const std::optional<Eigen::Matrix3d>& guide, const Eigen::Vector3d& forward)
{
    InertiaAxes axes;
    axes.centre = centre;
    axes.inertia = inertia;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(inertia);
    const Eigen::Vector3d lambda = solver.eigenvalues(); // ascending
    const Eigen::Matrix3d v = solver.eigenvectors();
    const double scale = std::max(std::abs(lambda[2]), 1e-300);
    const double gapLow = (lambda[1] - lambda[0]) / scale;
    const double gapHigh = (lambda[2] - lambda[1]) / scale;
    axes.relativeGap = std::min(gapLow, gapHigh);
    const bool lowEqual = gapLow < degenerateTolerance;
    const bool highEqual = gapHigh < degenerateTolerance;
    axes.degeneracy = lowEqual && highEqual ? Degeneracy::Spherical
                      : lowEqual            ? Degeneracy::LongAxis
                      : highEqual           ? Degeneracy::CrossAxes
                                            : Degeneracy::None;

    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d refZ = guide ? Eigen::Vector3d(guide->col(2)) : up;
    const Eigen::Vector3d refX = guide ? Eigen::Vector3d(guide->col(0)) : projectedUnit(forward, up, Eigen::Vector3d::UnitX());

    Eigen::Vector3d z;
    Eigen::Vector3d x;
    switch (axes.degeneracy) {
    case Degeneracy::None: {
        z = signedLike(v.col(0), refZ);
        const bool firstIsX = std::abs(v.col(1).dot(refX)) >= std::abs(v.col(2).dot(refX));
        x = signedLike(firstIsX ? v.col(1) : v.col(2), refX);
        break;
    }
    case Degeneracy::CrossAxes:
        z = signedLike(v.col(0), refZ);
        x = signedLike(projectedUnit(refX, z, v.col(1)), refX);
        break;
    case Degeneracy::LongAxis: {
        const Eigen::Vector3d distinct = v.col(2);
        z = signedLike(projectedUnit(refZ, distinct, v.col(0)), refZ);
        const Eigen::Vector3d other = z.cross(distinct);
        const bool distinctIsX = std::abs(distinct.dot(refX)) >= std::abs(other.dot(refX));
        x = signedLike(distinctIsX ? distinct : other, refX);
        break;
    }
    case Degeneracy::Spherical:
        z = refZ.normalized();
        x = projectedUnit(refX, z, z.unitOrthogonal());
        break;
    }
    axes.world_R_axis.col(0) = x;
    axes.world_R_axis.col(2) = z;
    axes.world_R_axis.col(1) = z.cross(x);
    axes.moments = (axes.world_R_axis.transpose() * inertia * axes.world_R_axis).diagonal();
    return axes;
}

std::string MotionAxis::degeneracyReport() const
{
    std::vector<DegenerateFrame> affecting;
    for (const DegenerateFrame& frame : degenerateFrames)
        if (frame.affectsAxis) affecting.push_back(frame);
    if (affecting.empty()) return {};
    std::ostringstream text;
    text << affecting.size() << " of " << frameCount() << " frames have degenerate inertia (two equal moments):";
    const std::size_t shown = std::min<std::size_t>(affecting.size(), 5);
    for (std::size_t i = 0; i < shown; ++i)
        text << (i ? "," : "") << " frame " << affecting[i].frame << " " << degeneracyName(affecting[i].degeneracy);
    if (shown < affecting.size()) text << ", ...";
    text << "; the undetermined axes were carried over from the previous frame";
    return text.str();
}

Result<MotionAxis> computeMotionAxis(const AxisModel& model, const Take& take, const AxisOptions& options,
                                     const RunControl& control)
{
    if (take.frameCount() < 1) return makeError(ErrorCode::InvalidArgument, "take " + take.displayName() + " has no frames");
    if (model.totalMass <= 0.0) return makeError(ErrorCode::InvalidArgument, "body " + model.body.source + " has no mass");
    Result<BodyBinding> binding = bindBody(model.body, take);
    if (!binding) return binding.error();
    if (!take.values.allFinite()) return makeError(ErrorCode::Numerical, "take " + take.displayName() + " has non-finite values");

    MotionAxis axis;
    axis.totalMass = model.totalMass;
    axis.rateHz = take.rateHz;
    axis.labels = take.labels;
    axis.world_T_axis.resize(std::size_t(take.frameCount()));
    axis.moments.resize(take.frameCount(), 3);

    // the first frame's forward: the mirror-frame part's (shoulder's) x when the take has it
    std::optional<Eigen::Index> forwardPart;
    for (const SixDofPart& part : sixDofParts(take))
        if (part.part == model.body.mirrorFramePart) forwardPart = part.firstChannel;
    std::optional<Eigen::Matrix3d> guide;
    for (Eigen::Index frame = 0; frame < take.frameCount(); ++frame) {
        if ((frame & 4095) == 0) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "motion axis cancelled");
            control.report(double(frame) / double(take.frameCount()));
        }
        const std::vector<RigidTransform> poses = worldPartPoses(model.body, *binding, take, frame);
        Eigen::Vector3d forward = Eigen::Vector3d::UnitX();
        if (!guide && forwardPart) forward = partPose(take, frame, *forwardPart).rotation * model.facing;
        const auto [centre, inertia] = inertiaAboutCentre(model.parts, poses);
        InertiaAxes axes = principalAxes(centre, inertia, options.degenerateTolerance, guide, forward);
        bool xFromShoulder = false;
        if (options.frontBack == FrontBackAxis::ShoulderForward && forwardPart) {
            const Eigen::Vector3d z = axes.world_R_axis.col(2);
            const Eigen::Vector3d facing = partPose(take, frame, *forwardPart).rotation * model.facing;
            const Eigen::Vector3d inPlane = facing - facing.dot(z) * z;
            if (inPlane.norm() > 0.1) {
                axes.world_R_axis.col(0) = inPlane.normalized();
                axes.world_R_axis.col(1) = z.cross(axes.world_R_axis.col(0));
                axes.moments = (axes.world_R_axis.transpose() * inertia * axes.world_R_axis).diagonal();
                xFromShoulder = true;
            }
        }
        guide = axes.world_R_axis;
        axis.world_T_axis[std::size_t(frame)] = RigidTransform{Eigen::Quaterniond(axes.world_R_axis).normalized(), centre};
        axis.moments.row(frame) = axes.moments.transpose();
        if (axes.degeneracy != Degeneracy::None)
            axis.degenerateFrames.push_back(
                {frame, axes.degeneracy, axes.relativeGap, !(xFromShoulder && axes.degeneracy == Degeneracy::CrossAxes)});
    }
    control.report(1.0);
    return axis;
}

} // namespace bunraku::analysis
