#include "analysis/body/puppet_mass.h"

#include "analysis/body/puppet_model.h"
#include "analysis/core/parallel.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace bunraku::analysis {
namespace {

/// The part frame a joint's points are carried into: the kimono hangs from the shoulder's dō-wa
/// and a sleeve from its arm, so their solid is the shoulder's and the arm's.
PuppetJoint framePartOf(PuppetJoint joint)
{
    switch (joint) {
    case PuppetJoint::Kimono: return PuppetJoint::Shoulder;
    case PuppetJoint::RightSleeve: return PuppetJoint::RightArm;
    case PuppetJoint::LeftSleeve: return PuppetJoint::LeftArm;
    default: return joint;
    }
}

PuppetSolidSample sampleSolid(double spacing)
{
    PuppetSolidSample sample;
    sample.spacing = spacing;
    PuppetBounds bounds = puppetModelBounds();
    // The lattice is symmetric about the sagittal plane (y = 0), as the solid is, so the mirrored
    // left arm and hand get exactly the right ones' masses.
    const int halfCount = std::max(1, int(std::ceil(double(std::max(-bounds.lower.y(), bounds.upper.y())) / spacing)));
    bounds.lower.y() = -float(halfCount * spacing);
    const Eigen::Vector3f extent = bounds.upper - bounds.lower;
    Eigen::Vector3i count;
    for (int axis = 0; axis < 3; ++axis) count[axis] = std::max(1, int(std::ceil(double(extent[axis]) / spacing)));
    count.y() = 2 * halfCount;
    // The rest poses of the part frames (the fit and the skin use the same ones).
    const std::array<RigidTransform, 6> model_T_part = puppetPartBindPoses();
    std::array<RigidTransform, 6> part_T_model;
    for (int j = 0; j < 6; ++j) part_T_model[std::size_t(j)] = model_T_part[std::size_t(j)].inverse();

    // One slab of the lattice (fixed x index) per item: the points come out in lattice order
    // whatever the thread count.
    const int threads = std::max(1, int(std::thread::hardware_concurrency()));
    std::vector<std::array<std::vector<Eigen::Vector3d>, 6>> slabs(std::size_t(count.x()));
    (void)parallelFor(std::size_t(count.x()), threads, [&](std::size_t i) {
        auto& slab = slabs[i];
        for (int j = 0; j < count.y(); ++j)
            for (int k = 0; k < count.z(); ++k) {
                const Eigen::Vector3f p = bounds.lower + float(spacing) * Eigen::Vector3f(float(i) + 0.5f, float(j) + 0.5f, float(k) + 0.5f);
                if (puppetSignedDistance(p) >= 0.0f) continue;
                const int part = int(framePartOf(puppetDominantJointAt(p)));
                slab[std::size_t(part)].push_back(part_T_model[std::size_t(part)].apply(p.cast<double>()));
            }
        return okStatus();
    });
    for (int part = 0; part < 6; ++part) {
        std::size_t total = 0;
        for (const auto& slab : slabs) total += slab[std::size_t(part)].size();
        Eigen::Matrix3Xd points(3, Eigen::Index(total));
        Eigen::Index column = 0;
        for (const auto& slab : slabs)
            for (const Eigen::Vector3d& q : slab[std::size_t(part)]) points.col(column++) = q;
        sample.partPoints[std::size_t(part)] = std::move(points);
    }
    return sample;
}

/// Distance (cm) from a point in the primitive's own frame to its bounding box; 0 inside it.
double boxDistance(const Primitive& primitive, const Eigen::Vector3d& local)
{
    return (local.cwiseAbs() - primitive.halfExtents()).cwiseMax(0.0).norm();
}

/// The density of the primitive of `part` holding the part-frame point q, else of the nearest.
double densityAt(const BodyPart& part, const std::vector<RigidTransform>& primitive_T_part, const Eigen::Vector3d& q)
{
    double best = 1e300;
    double density = part.density;
    for (std::size_t k = 0; k < part.primitives.size(); ++k) {
        const Eigen::Vector3d local = primitive_T_part[k].apply(q);
        if (part.primitives[k].containsLocal(local)) return part.primitives[k].density;
        const double d = boxDistance(part.primitives[k], local);
        if (d < best) {
            best = d;
            density = part.primitives[k].density;
        }
    }
    return density;
}

} // namespace

const PuppetSolidSample& puppetSolidSample(double spacing)
{
    spacing = std::clamp(std::isfinite(spacing) ? spacing : 1.0, 0.25, 100.0);
    static std::mutex mutex;
    static std::map<double, std::unique_ptr<PuppetSolidSample>> samples;
    const std::lock_guard lock(mutex);
    auto& sample = samples[spacing];
    if (!sample) sample = std::make_unique<PuppetSolidSample>(sampleSolid(spacing));
    return *sample;
}

Result<std::vector<MassPoints>> modelMassPoints(const BodyDescription& body, const MassPointOptions& options)
{
    const auto partOf = puppetJointPartIndices(body);
    for (int j = 0; j < 6; ++j)
        if (partOf[std::size_t(j)] < 0)
            return makeError(ErrorCode::InvalidArgument, body.source + ": the modelled puppet's masses need the part '" +
                                                              std::string(kPuppetJointParts[std::size_t(j)]) + "'");
    const PuppetSolidSample& sample = puppetSolidSample(options.spacing);
    std::vector<MassPoints> result(body.parts.size());
    for (int j = 0; j < 6; ++j) {
        const BodyPart& part = body.parts[std::size_t(partOf[std::size_t(j)])];
        std::vector<RigidTransform> primitive_T_part;
        for (const Primitive& primitive : part.primitives) primitive_T_part.push_back(primitive.part_T_primitive.inverse());
        const Eigen::Matrix3Xd& rest = sample.partPoints[std::size_t(j)];
        // The fit maps the shipped puppet's part onto this body's, as it does the drawn surface;
        // a lattice cell's volume changes by |det| of its linear part.
        const double cell = sample.cellVolume() * std::abs(part.fit.linear().determinant());
        MassPoints& points = result[std::size_t(partOf[std::size_t(j)])];
        points.positions.resize(3, rest.cols());
        points.masses.resize(rest.cols());
        for (Eigen::Index k = 0; k < rest.cols(); ++k) {
            const Eigen::Vector3d q = part.fit * Eigen::Vector3d(rest.col(k));
            points.positions.col(k) = q;
            points.masses[k] = cell * densityAt(part, primitive_T_part, q);
        }
    }
    return result;
}

std::vector<MassPoints> bodyMassPoints(const BodyDescription& body, const MassPointOptions& options, MassSource* used)
{
    if (options.source == MassSource::Model && bodyHasPuppetParts(body)) {
        auto points = modelMassPoints(body, options);
        if (points) {
            if (used) *used = MassSource::Model;
            return std::move(*points);
        }
    }
    if (used) *used = MassSource::Primitives;
    return sampleMassPoints(body, options);
}

} // namespace bunraku::analysis
