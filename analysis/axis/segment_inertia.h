#pragma once
/// The whole-body motion axis of a performer (issue 25): the thesis's inertia axis (5.2.1)
/// integrated over the performer's body segments instead of the puppet's four parts, with
/// published human segment parameters: P. de Leva, "Adjustments to Zatsiorsky-Seluyanov's segment
/// inertia parameters", Journal of Biomechanics 29(9), 1223-1230, 1996, Table 4 (mass fractions,
/// centres of mass along the segment, radii of gyration about the sagittal, transverse and
/// longitudinal axes; male and female). docs/MOTION-AXIS.md, "The whole body".
///
/// The segments are found on the take's skeleton (any family): the chains of
/// skeleton_chains.h give the spine and the limbs; in each limb the upper arm and forearm (thigh
/// and shank) are the two consecutive bones of the largest summed length, so a collar, a hip
/// joint at the pelvis, zero-length helpers and the fingers are told apart from them. The ends
/// de Leva measures between are the skeleton's joint centres where a skeleton has them:
///   head   vertex -> C7 (the cervicale: the point of the spine nearest the shoulders' midpoint;
///          the vertex: the farthest point the head carries, else estimated from the trunk's length)
///   trunk  C7 -> the midpoint of the hip joints
///   upper arm, forearm, thigh, shank: joint centre to joint centre
///   hand   wrist -> the third metacarpal, its length the table's hand : forearm ratio
///   foot   ankle -> the toe tip (de Leva's heel is not a joint of a skeleton)
/// Each segment is the six point masses that have its mass, centre and principal moments
/// exactly (along its longitudinal axis, the body's left-right axis and the third), carried by
/// the joint whose bone they lie on; the points of each joint reduce to its PartMoments, so the
/// axis of a frame costs O(joints) (inertia_axis.h). "Sagittal" is the radius about the axis
/// that lies in the sagittal plane across the segment (front-back for an upright segment),
/// "transverse" about the left-right axis.

#include "analysis/axis/inertia_axis.h"
#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

/// "male", "female" (SegmentTable: inertia_axis.h).
const char* segmentTableName(SegmentTable table);
std::optional<SegmentTable> segmentTableFromName(std::string_view name);

enum class SegmentKind { Head, Trunk, UpperArm, Forearm, Hand, Thigh, Shank, Foot };
/// "head", "trunk", "upper_arm", "forearm", "hand", "thigh", "shank", "foot".
const char* segmentKindName(SegmentKind kind);

struct SegmentParameters {
    double massFraction = 0.0;     ///< of the body's mass
    double centreFraction = 0.0;   ///< centre of mass from the proximal end, fraction of the length
    double radiusSagittal = 0.0;   ///< radius of gyration / length, about the sagittal-plane cross axis
    double radiusTransverse = 0.0; ///< about the left-right axis
    double radiusLongitudinal = 0.0;
    double lengthCm = 0.0;         ///< the sample's mean length (estimates of ends a skeleton lacks)
};
const SegmentParameters& segmentParameters(SegmentTable table, SegmentKind kind);
/// The sample's mean body mass, kg.
double segmentTableBodyMassKg(SegmentTable table);

struct SegmentModelOptions {
    SegmentTable table = SegmentTable::DeLevaMale;
    /// 0: the table's mean. The axis does not depend on it; the moments scale with it. The
    /// table's fractions (which add up to 99.99-100.00 % after rounding) are scaled to it.
    double bodyMassKg = 0.0;
};

/// One segment placed on the skeleton at the take's first frame (world, cm).
struct BodySegment {
    SegmentKind kind = SegmentKind::Trunk;
    std::string chain;          ///< the skeleton chain it lies in ("spine", "left_arm", ...)
    Eigen::Vector3d proximal = Eigen::Vector3d::Zero();
    Eigen::Vector3d distal = Eigen::Vector3d::Zero();
    bool distalEstimated = false; ///< the end came from the table's proportions (no joint there)
    double mass = 0.0;            ///< g
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero(); ///< g cm^2 about its centre, world axes
    std::vector<std::string> joints; ///< the joints that carry its mass points
};

struct SegmentBody {
    std::vector<BodySegment> segments; ///< head, trunk, then per arm and leg chain its three segments
    /// One part per joint that carries mass (body.parts driven by the joints' 6 channels), the
    /// facing in the joint where the arms branch (body.mirrorFramePart).
    AxisModel model;
};

/// True when `take` has no 6-DOF part of the puppet's four but a skeleton whose joints are its
/// parts: the takes the whole-body axis is for.
bool usesSegmentModel(const Take& take);

/// The segments of `take`'s skeleton at its first frame and the axis model they make. Errors
/// (InvalidArgument) name the take and what is missing: a skeleton, a spine, the two arms and
/// legs with three joints each, a joint's 6 channels.
Result<SegmentBody> segmentBody(const Take& take, const SegmentModelOptions& options = {});

} // namespace bunraku::analysis
