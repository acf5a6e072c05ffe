#pragma once
/// Placing the body description in a take: one world_T_part per body part per frame, the left
/// arm and hand mirrored across the sagittal plane of the shoulder frame (thesis 5.2.1), and the
/// mass points the motion axis integrates over.

#include "analysis/body/body_description.h"
#include "analysis/core/pose.h"
#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

/// Which take columns drive the body: per body part the first of its 6 channels
/// (x y z yaw pitch roll), and the mirror frame's.
struct BodyBinding {
    std::vector<Eigen::Index> partFirstChannel; ///< one per BodyDescription::parts
    Eigen::Index mirrorFrameFirstChannel = -1;  ///< -1 when no part is mirrored
};

/// Finds every part's `drivenBy` take part (6 consecutive channels x..roll); the error names the
/// missing part and the take.
Result<BodyBinding> bindBody(const BodyDescription& body, const Take& take);

/// The mirror of world_T_source across the sagittal (x-z) plane of world_T_mirrorFrame, as the
/// pose of a part whose geometry is the source's reflected in its y axis:
///   rotation R_s F R_s^T R_src F (proper), translation p_s + R_s F R_s^T (p_src - p_s),
/// with F = diag(1, -1, 1). Applying it to the reflected local point F q gives the mirror image
/// of world_T_source applied to q.
RigidTransform mirroredPose(const RigidTransform& world_T_source, const RigidTransform& world_T_mirrorFrame);

/// world_T_part for every body part at `frame` (same order as body.parts); mirrored parts via
/// mirroredPose. Parts whose driving channels are missing from the take get the identity (call
/// bindBody first to find out).
std::vector<RigidTransform> worldPartPoses(const BodyDescription& body, const Take& take, Eigen::Index frame);
/// The same with a binding computed once (no name lookups per frame).
std::vector<RigidTransform> worldPartPoses(const BodyDescription& body, const BodyBinding& binding, const Take& take,
                                           Eigen::Index frame);

/// Where the motion axis's masses come from.
enum class MassSource {
    /// The modelled puppet's solid cut into its parts (puppet_mass.h): the default for a body
    /// with the puppet's six parts.
    Model,
    /// The body description's primitives (sampleMassPoints), as before the modelled puppet; the
    /// only source for a body with other parts.
    Primitives,
    /// A performer's body segments from published human parameters (analysis/axis/segment_inertia.h):
    /// the axis of a take of a skeleton's joints, chosen by the take, never by a parameter.
    Segments,
};
/// "model", "primitives", "segments".
const char* massSourceName(MassSource source);

struct MassPointOptions {
    double spacing = 1.0; ///< cm, grid step of the sampling lattice (inside each primitive, or the model's solid)
    MassSource source = MassSource::Model;
};

/// Point masses of one part in its own frame: a regular lattice (step `spacing`) inside each
/// primitive, each primitive's analytic mass shared equally by its points (thesis 5.2.1: K_p
/// points of mass M_p / K_p). A primitive thinner than the step still gets its centre point.
struct MassPoints {
    Eigen::Matrix3Xd positions; ///< 3 x K, cm, in the part frame
    Eigen::VectorXd masses;     ///< K, g
};

/// Mass points of every body part (same order as body.parts), in part frames.
std::vector<MassPoints> sampleMassPoints(const BodyDescription& body, const MassPointOptions& options = {});

/// Mass, first and second moments of one part's points in its own frame: everything the inertia
/// of the posed body needs, so a frame costs O(parts) instead of O(points).
struct PartMoments {
    double mass = 0.0;                                         ///< g
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();          ///< cm, centre of mass in the part frame
    Eigen::Matrix3d secondMoment = Eigen::Matrix3d::Zero();    ///< g cm^2, sum m q q^T about the part origin
};
PartMoments partMoments(const MassPoints& points);

} // namespace bunraku::analysis
