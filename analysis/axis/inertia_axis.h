#pragma once
/// The motion axis (thesis 5.2.1): the puppet as one rigid body per frame, its principal axes of
/// inertia about the centre of mass. Axis z = least moment (the body's long axis, up), x =
/// front-back; eigenvector signs fixed so z points up and x forward on the first frame, then
/// kept continuous from frame to frame (no flips over a full turn).

#include "analysis/body/body_description.h"
#include "analysis/body/body_pose.h"
#include "analysis/core/pose.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis {

/// How axis x (front-back) is chosen in the plane perpendicular to axis z.
enum class FrontBackAxis {
    /// The forward (x) direction of the mirror-frame part (the shoulder) projected onto the
    /// plane perpendicular to z; the principal axis when the take has no such part or the
    /// shoulder faces along z. Decision (default): the puppet's two larger moments differ by
    /// only a few percent and cross when an arm moves forward, so the principal x, y swing by up
    /// to 90 degrees within a frame or two; "front-back" is then taken literally.
    ShoulderForward,
    /// The thesis-literal principal axis of the two larger moments nearest the previous x.
    Principal,
};

/// Which of de Leva's (1996) tables gives a performer's body segments (segment_inertia.h; his
/// samples: 100 men of 73.0 kg and 174.1 cm, 15 women of 61.9 kg and 173.5 cm).
enum class SegmentTable { DeLevaMale, DeLevaFemale };

struct AxisOptions {
    MassPointOptions massPoints;       ///< where the mass points come from and their lattice step
    /// The segment table of a take of a skeleton's joints (the puppet's masses ignore it).
    SegmentTable segments = SegmentTable::DeLevaMale;
    FrontBackAxis frontBack = FrontBackAxis::ShoulderForward;
    /// Two principal moments whose difference is below this fraction of the largest moment are
    /// "equal": the axes in their plane are not determined by the inertia (reported per frame).
    double degenerateTolerance = 1e-3;
};

/// The body's mass points reduced to per-part moments, computed once per body description.
struct AxisModel {
    BodyDescription body;
    std::vector<PartMoments> parts; ///< one per body.parts
    double totalMass = 0.0;         ///< g
    MassSource massSource = MassSource::Model; ///< where the masses came from (the model's when the body has the puppet's parts)
    /// The body's forward direction in the frame of its mirror-frame part (the puppet's shoulder
    /// faces along its x; a skeleton's chest joint along whatever its bone frame makes forward:
    /// segment_inertia.h).
    Eigen::Vector3d facing = Eigen::Vector3d::UnitX();
};
AxisModel makeAxisModel(const BodyDescription& body, const AxisOptions& options = {});

/// Which principal moments coincide.
enum class Degeneracy {
    None,
    LongAxis,  ///< least and middle moments equal: axis z is not determined (kept from the previous frame)
    CrossAxes, ///< middle and largest moments equal: x and y are not determined (x kept from the previous frame)
    Spherical, ///< all three equal: the previous frame's axes are kept
};

/// The inertia of the posed body at one frame.
struct InertiaAxes {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();       ///< cm, world centre of mass
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();      ///< g cm^2, world frame, about the centre
    Eigen::Matrix3d world_R_axis = Eigen::Matrix3d::Identity(); ///< columns: axis x, y, z in world
    Eigen::Vector3d moments = Eigen::Vector3d::Zero();      ///< g cm^2 about axis x, y, z
    Degeneracy degeneracy = Degeneracy::None;
    double relativeGap = 1.0; ///< smallest gap between moments / largest moment
};

/// Inertia of parts (moments in part frames) placed by world_T_part, about their common centre
/// of mass: I = tr(C) 1 - C with C = sum_p m (R q + t)(R q + t)^T - M c c^T (exact for the
/// mass points, O(parts)).
std::pair<Eigen::Vector3d, Eigen::Matrix3d> inertiaAboutCentre(const std::vector<PartMoments>& parts,
                                                               const std::vector<RigidTransform>& world_T_part);

/// Principal axes (Eigen::SelfAdjointEigenSolver) ordered and signed: z = least moment, x the
/// other axis closest to `guide`'s x (or to `forward` when there is no guide), signs so that z
/// and x agree with the guide's (or z with world up and x with `forward`); y = z cross x.
InertiaAxes principalAxes(const Eigen::Vector3d& centre, const Eigen::Matrix3d& inertia, double degenerateTolerance,
                          const std::optional<Eigen::Matrix3d>& guide, const Eigen::Vector3d& forward);

struct DegenerateFrame {
    Eigen::Index frame = 0;
    Degeneracy degeneracy = Degeneracy::None;
    double relativeGap = 0.0;
    /// False when the undetermined axes did not matter: equal x/y moments while x is taken from
    /// the shoulder's facing (FrontBackAxis::ShoulderForward).
    bool affectsAxis = true;
};

/// The motion axis of a whole take.
struct MotionAxis {
    std::vector<RigidTransform> world_T_axis; ///< per frame; rotation columns = axis x, y, z
    Eigen::MatrixX3d moments;                 ///< frames x 3, g cm^2 about axis x, y, z
    double totalMass = 0.0;                   ///< g
    double rateHz = 5.0;
    TakeLabels labels;                        ///< of the source take
    std::vector<DegenerateFrame> degenerateFrames;

    Eigen::Index frameCount() const { return Eigen::Index(world_T_axis.size()); }
    /// "" when no degenerate frame affected the axis, else a one-line summary naming frames and kinds.
    std::string degeneracyReport() const;
};

/// thesis 5.2.1: the axis of every frame (z always the principal axis of least moment; x per
/// options.frontBack; moments are the diagonal of the inertia in the axis frame). The take must have the 6 channels of every part the
/// body is driven by (NotFound otherwise); the first frame's x follows the forward (x) direction
/// of the take's mirror-frame part (the shoulder; `model.facing` in its frame) when it has one, else world x. Cancelled via control.
Result<MotionAxis> computeMotionAxis(const AxisModel& model, const Take& take, const AxisOptions& options = {},
                                     const RunControl& control = {});

} // namespace bunraku::analysis
