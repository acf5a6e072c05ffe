#pragma once
/// Start-time alignment, thesis 2.2 step (3): per take an activity signal (frame-to-frame
/// change) and a departure signal (distance from the start pose) that see rotation as well as
/// translation (angles weighted in cm per degree), the activity's noise floor, the onset of the
/// departure, the start edge cross-correlated by the alternative method, the choice of a cell's
/// time reference (thesis 3.6.1) and the shift of a take. Format notes: docs/FORMATS.md.

#include "analysis/core/take.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis::preprocess {

enum class StartAlignMethod {
    /// Onset: departureOnset of the departure from the start pose with the activity's noise
    /// floor; the shift is onset(take) - onset(reference), rounded to whole frames.
    Onset,
    /// Cross-correlation of the take's start edge (startEdge of its departure signal) with the
    /// reference's: the lag in [-maxShiftFrames, maxShiftFrames] of the largest normalised
    /// correlation of the mean-removed signals.
    CrossCorrelation,
};

/// A rotation of 1 deg moves a point 20 cm from the rotation axis (about a puppet part's reach:
/// head, shoulder span, forearm, hand) by 20 * pi / 180 = 0.349 cm: the default weight of angles.
inline constexpr double kDefaultCmPerDegree = 0.349;

struct ActivityOptions {
    /// Weight of an angle change in the activity, cm per degree (see kDefaultCmPerDegree).
    double cmPerDegree = kDefaultCmPerDegree;
    /// Width of the centred moving average, frames (1 = no smoothing; shrinks at the ends).
    int smoothingFrames = 3;
};

/// Summed speed per frame (length frames): sum over 6-DOF parts of the position speed (cm/frame),
/// or when the take has none, the sum of absolute differences of all channels. speed(0) = 0.
/// Blind to rotation: kept for callers that want translation only; alignment uses activitySignal.
Eigen::VectorXd summedSpeed(const Take& take);

/// Raw activity per frame (length frames, cm/frame, activity(0) = 0): for each 6-DOF part
/// sqrt(|dp|^2 + (c da)^2) with dp the position change (cm), da the angle of the part's turn
/// between the frames (deg, measured on rotations: no Euler branch, gimbal region or part frame
/// convention changes it) and c = cmPerDegree, summed over parts; channels outside 6-DOF parts
/// add |change| (angles within (-180, 180], weighted by c).
Eigen::VectorXd rawActivity(const Take& take, double cmPerDegree = kDefaultCmPerDegree);
/// Centred moving average of width `window` (odd widths are symmetric; the window shrinks at the
/// ends so the mean is always over existing frames). window <= 1 returns the signal.
Eigen::VectorXd movingAverage(const Eigen::VectorXd& signal, int window);
/// rawActivity smoothed by movingAverage(options.smoothingFrames).
Eigen::VectorXd activitySignal(const Take& take, const ActivityOptions& options = {});

/// Departure from the start pose per frame (cm, smoothed like activitySignal): per 6-DOF part
/// sqrt(|p(t) - p(0)|^2 + (c angle(R(t), R(0)))^2), summed over parts.
Eigen::VectorXd departureSignal(const Take& take, const ActivityOptions& options = {});

/// Noise floor of an activity: its `quietFraction` quantile over the frames with activity > 0
/// (exact zeros are held or padded frames, which carry no sensor noise); 0 when there are none.
double noiseFloor(const Eigen::VectorXd& activity, double quietFraction = 0.1);
/// Fractional frame where `activity` first reaches floor + fraction * (peak - floor), linearly
/// interpolated between the frame before and the crossing frame; 0 for a flat signal.
double onsetTime(const Eigen::VectorXd& activity, double fraction, double quietFraction = 0.1);
/// Fractional onset of a departure signal: find the first frame where `departure` reaches
/// noise + fraction * (peak - noise) (noise cannot reach it), then go back to where it last was
/// within `band` * noise and interpolate the upward crossing of that level; 0 when the departure
/// never was within the band before (the take moves from its first frame) or is flat.
double departureOnset(const Eigen::VectorXd& departure, double noise, double fraction, double band = 1.5);
/// The start edge of a departure signal: clipped at `ceiling` and made non-decreasing (running
/// maximum), so only its rise from the start pose remains (what CrossCorrelation correlates).
Eigen::VectorXd startEdge(const Eigen::VectorXd& departure, double ceiling);
/// First whole frame where `speed` reaches floor + fraction * (peak - floor) (noise floor as in
/// noiseFloor with quietFraction 0.1; 0 for a noiseless signal); 0 for a motionless signal.
Eigen::Index onsetFrame(const Eigen::VectorXd& speed, double fraction);
/// Lag s in [-maxShift, maxShift] maximising the normalised correlation of signal(t + s) with
/// reference(t) over their overlap (ties: the smaller |s|).
int crossCorrelationShift(const Eigen::VectorXd& signal, const Eigen::VectorXd& reference, int maxShift);

/// One candidate of a cell's time reference.
struct ReferenceCandidate {
    Eigen::Index frames = 0; ///< length before padding
    double onset = 0.0;      ///< onsetTime of its activity, frames
};
/// Index into `candidates` of a cell's automatic time reference, thesis 3.6.1 ("a long take with
/// an early start"; there take 1 started late and was an outlier): among the takes at least
/// `longFraction` as long as the cell's longest, the one with the median onset (the lower median
/// for an even count; ties: the longer, then the first). The median rather than the earliest:
/// it avoids late-start takes as long as fewer than half the takes start late, and it is not
/// drawn to a take whose onset estimate came out early by noise; the earliest of K noisy
/// onsets is biased early, which shifts every other take of the cell by about a frame the same
/// way. The cost: takes that start earlier than the reference get a negative shift (the first
/// frame repeated in front). -1 for no candidates.
int chooseTimeReference(const std::vector<ReferenceCandidate>& candidates, double longFraction = 0.95);

/// Drops `shift` frames at the start and repeats the last frame at the end (shift < 0: repeats
/// the first frame in front and drops at the end); the frame count is unchanged. The take's
/// skeleton (when it has one) is shifted with it.
void shiftTake(Take& take, int shift);

} // namespace bunraku::analysis::preprocess
