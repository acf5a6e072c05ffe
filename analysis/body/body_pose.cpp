#include "analysis/body/body_pose.h"

#include "analysis/core/puppet_layout.h"

#include <algorithm>
#include <cmath>

namespace bunraku::analysis {

namespace {

std::optional<Eigen::Index> sixDofStart(const Take& take, const std::string& part)
{
    for (const SixDofPart& candidate : sixDofParts(take))
        if (candidate.part == part) return candidate.firstChannel;
    return std::nullopt;
}

const Eigen::Matrix3d& flipY()
{
    static const Eigen::Matrix3d flip = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
    return flip;
}

} // namespace

Result<BodyBinding> bindBody(const BodyDescription& body, const Take& take)
{
    BodyBinding binding;
    bool any_mirrored = false;
    for (const BodyPart& part : body.parts) {
        const auto first = sixDofStart(take, part.drivenBy);
        if (!first)
            return makeError(ErrorCode::NotFound, "take " + take.displayName() + " has no 6 channels " + part.drivenBy +
                                                      ".x..roll to drive body part \"" + part.name + "\" of " + body.source);
        binding.partFirstChannel.push_back(*first);
        any_mirrored = any_mirrored || part.mirrored;
    }
    if (any_mirrored) {
        const auto first = sixDofStart(take, body.mirrorFramePart);
        if (!first)
            return makeError(ErrorCode::NotFound, "take " + take.displayName() + " has no 6 channels " + body.mirrorFramePart +
                                                      ".x..roll for the mirror frame of " + body.source);
        binding.mirrorFrameFirstChannel = *first;
    }
    return binding;
}

RigidTransform mirroredPose(const RigidTransform& world_T_source, const RigidTransform& world_T_mirrorFrame)
{
    const Eigen::Matrix3d frame = world_T_mirrorFrame.rotation.toRotationMatrix();
    const Eigen::Matrix3d reflection = frame * flipY() * frame.transpose();
    const Eigen::Matrix3d rotation = reflection * world_T_source.rotation.toRotationMatrix() * flipY();
    RigidTransform mirrored;
    mirrored.rotation = Eigen::Quaterniond(rotation).normalized();
    mirrored.translation =
        world_T_mirrorFrame.translation + reflection * (world_T_source.translation - world_T_mirrorFrame.translation);
    return mirrored;
}

std::vector<RigidTransform> worldPartPoses(const BodyDescription& body, const BodyBinding& binding, const Take& take,
                                           Eigen::Index frame)
{
    std::vector<RigidTransform> poses(body.parts.size());
    RigidTransform world_T_mirror;
    if (binding.mirrorFrameFirstChannel >= 0) world_T_mirror = partPose(take, frame, binding.mirrorFrameFirstChannel);
    for (std::size_t i = 0; i < body.parts.size(); ++i) {
        if (i >= binding.partFirstChannel.size() || binding.partFirstChannel[i] < 0) continue;
        const RigidTransform world_T_driver = partPose(take, frame, binding.partFirstChannel[i]);
        poses[i] = body.parts[i].mirrored ? mirroredPose(world_T_driver, world_T_mirror) : world_T_driver;
    }
    return poses;
}

std::vector<RigidTransform> worldPartPoses(const BodyDescription& body, const Take& take, Eigen::Index frame)
{
    BodyBinding binding;
    for (const BodyPart& part : body.parts) binding.partFirstChannel.push_back(sixDofStart(take, part.drivenBy).value_or(-1));
    binding.mirrorFrameFirstChannel = sixDofStart(take, body.mirrorFramePart).value_or(-1);
    return worldPartPoses(body, binding, take, frame);
}

const char* massSourceName(MassSource source)
{
    switch (source) {
    case MassSource::Model: return "model";
    case MassSource::Primitives: return "primitives";
    case MassSource::Segments: return "segments";
    }
    return "model";
}

std::vector<MassPoints> sampleMassPoints(const BodyDescription& body, const MassPointOptions& options)
{
    const double spacing = options.spacing > 0.0 ? options.spacing : 1.0;
    std::vector<MassPoints> result;
    result.reserve(body.parts.size());
    for (const BodyPart& part : body.parts) {
        std::vector<Eigen::Vector3d> positions;
        std::vector<double> masses;
        for (const Primitive& primitive : part.primitives) {
            const Eigen::Vector3d half = primitive.halfExtents();
            Eigen::Vector3i count;
            Eigen::Vector3d step;
            for (int axis = 0; axis < 3; ++axis) {
                count[axis] = std::max(1, int(std::lround(2.0 * half[axis] / spacing)));
                step[axis] = 2.0 * half[axis] / count[axis];
            }
            const std::size_t first = positions.size();
            for (int i = 0; i < count.x(); ++i)
                for (int j = 0; j < count.y(); ++j)
                    for (int k = 0; k < count.z(); ++k) {
                        const Eigen::Vector3d local = -half + step.cwiseProduct(Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5));
                        if (primitive.containsLocal(local)) positions.push_back(primitive.part_T_primitive.apply(local));
                    }
            if (positions.size() == first) positions.push_back(primitive.part_T_primitive.translation);
            const double each = primitive.mass() / double(positions.size() - first);
            masses.resize(positions.size(), each);
        }
        MassPoints points;
        points.positions.resize(3, Eigen::Index(positions.size()));
        points.masses.resize(Eigen::Index(masses.size()));
        for (std::size_t k = 0; k < positions.size(); ++k) {
            points.positions.col(Eigen::Index(k)) = positions[k];
            points.masses[Eigen::Index(k)] = masses[k];
        }
        result.push_back(std::move(points));
    }
    return result;
}

PartMoments partMoments(const MassPoints& points)
{
    PartMoments moments;
    moments.mass = points.masses.sum();
    if (moments.mass <= 0.0) return moments;
    moments.centre = points.positions * points.masses / moments.mass;
    moments.secondMoment = points.positions * points.masses.asDiagonal() * points.positions.transpose();
    return moments;
}

} // namespace bunraku::analysis
