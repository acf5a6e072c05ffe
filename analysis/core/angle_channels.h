#pragma once
/// The angle channels of a take's 6-DOF parts (yaw, pitch, roll: intrinsic Z-Y'-X'' Euler
/// angles, degrees) and their continuous counterpart. Euler numbers have many equivalent triples
/// per orientation (whole turns; the mirrored yaw + 180, 180 - pitch, roll + 180) and steep
/// regions near pitch = +-90 (gimbal), so nothing that averages, subtracts, scales or matches
/// orientations works on them. Instead every such computation maps a part's orientation R to its
/// rotation coordinates: the rotation vector r of the turn R base^-1 from a base orientation of
/// the part (a chart) to R, in world axes (degrees, continuous in time), written into the
/// part's angle columns as yaw <- r_z (about the vertical), pitch <- r_y (about the lateral
/// axis), roll <- r_x (about the axis towards the partner). In world axes the coordinates do not
/// depend on the part's own frame either: a part frame rotated by a constant C (another
/// calibration of the same skeleton) has base C and the same turns. Results are mapped back
/// with the Euler filter: the triple nearest the previous frame's. Charts are mean orientations, so a part's turns
/// about them stay well within half a turn in real motion; past half a turn the coordinates stay
/// continuous but stretch (the exp map folds the sphere of radius 360 deg onto the base).
/// docs/FORMATS.md ("Angles").

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/take.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace bunraku::analysis {

/// Base rotations of `tracks` rotation tracks (a take's 6-DOF parts, a skeleton's joints):
/// one per frame, or one for the whole take (`frames` = 1).
struct RotationChart {
    Eigen::Index frames = 0;              ///< rows of base (at least 1 when tracks > 0); 1 = the same base at every frame
    int tracks = 0;
    std::vector<Eigen::Quaterniond> base; ///< frames x tracks, base[frame * tracks + track]

    /// The base of `track` at `frame`; frames past the chart's last use its last row.
    const Eigen::Quaterniond& at(Eigen::Index frame, int track) const
    {
        const Eigen::Index row = frame < frames ? frame : frames - 1;
        return base[std::size_t(row) * std::size_t(tracks) + std::size_t(track)];
    }
};

enum class ChartTime {
    Constant, ///< one base per track: the mean over every frame of every take
    PerFrame, ///< a base per frame: the mean over the takes at that frame (equal lengths)
};

/// world_R_part of one 6-DOF part at every frame.
std::vector<Eigen::Quaterniond> partRotations(const Take& take, const SixDofPart& part);

/// The mean orientation of each 6-DOF part of the first take over `takes`, over all their
/// frames (Constant) or at each frame (PerFrame; the frames of the shortest take): the chordal
/// mean (chordalMeanRotation), as central as a chart needs and unchanged by a constant turn of
/// the part frames (it maps q C to mean C). Tracks in sixDofParts order. Empty chart
/// (tracks 0) for no takes or no 6-DOF parts.
RotationChart meanPartChart(const std::vector<const Take*>& takes, ChartTime time = ChartTime::Constant);

/// The take's values (frames x channels) with each 6-DOF part's angle columns replaced by its
/// rotation coordinates about `chart`: log(R base^-1) in degrees, continuous over frames
/// (frame 0 the principal vector, |r| <= 180). Positions and channels outside 6-DOF parts are copied. The chart's
/// tracks follow sixDofParts(take); a take with other parts than the chart's is a programming
/// error (asserted).
Eigen::MatrixXd rotationCoordinates(const Take& take, const RotationChart& chart);

/// The inverse of rotationCoordinates (R = exp(r) base): `coordinates` (frames x channels of
/// `layout`) with each 6-DOF part's rotation coordinates turned back into Euler angles, filtered: frame 0 the
/// triple nearest `firstAngles`' (a row with the layout's channels, e.g. the source take's
/// first frame) or the principal triple without it, then each frame nearest the previous.
Eigen::MatrixXd eulerFromRotationCoordinates(const Take& layout, const Eigen::MatrixXd& coordinates, const RotationChart& chart,
                                             const std::optional<Eigen::RowVectorXd>& firstAngles = std::nullopt);

/// A copy of `take` whose 6-DOF parts' angle columns hold rotation coordinates (degrees,
/// continuous, never winding or jumping at gimbal) about the mean orientation of `reference`'s
/// parts (meanPartChart, Constant) - so two takes shown together share one base - or about the
/// take's own when `reference` is null or has other 6-DOF parts. What the graphs show with
/// "Angles: rotation coordinates". Positions are copied.
Take rotationCoordinateTake(const Take& take, const Take* reference = nullptr);

/// The discontinuity (Euler) filter: every 6-DOF part's angle triple replaced, frame by frame,
/// by the equivalent triple (whole turns, mirrored pitch) nearest the previous frame's
/// (nearestEquivalent); the first frame is kept. The orientations are unchanged. Returns the
/// number of discontinuities removed: the frames where the correction (mirrored or not, whole
/// turns per angle) differs from the frame before's (a wrap into and back out of a branch is two).
int filterEulerAngles(Take& take);

/// Moves each 6-DOF part of `take` onto the branch of `reference`: the equivalent-triple change
/// (whole turns and, when nearer, the mirrored triple) that brings its first frame nearest the
/// reference's first frame, applied to every frame (continuity and orientations are kept).
/// Returns the whole turns added over the angle channels plus one per part mirrored.
int matchPartBranches(Take& take, const Take& reference);

} // namespace bunraku::analysis
