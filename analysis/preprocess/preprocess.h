#pragma once
/// Preprocessing of a corpus, thesis 2.2: (1) pad every take to the longest with its last frame,
/// (2) unwrap angles (the thesis remapped to 0..360; we unwrap), (3) align the start times of the
/// K takes of each function x emotion cell to the cell's reference take, (4) translate each take
/// so each part's first-frame position equals that of its function's reference take.
/// Two steps the thesis implies but does not name: after unwrapping, every angle channel is
/// moved by whole turns so its first value lies within 180 deg of the function's reference take
/// (the thesis's 0..360 remapping kept all takes on one branch; per-take unwrapping does not),
/// and (5) the whole-body heading is aligned: all yaw channels of a take are offset so the
/// heading part's (default the shoulder's) start yaw equals the reference's; relative yaw
/// (a head turned away) is kept. For these two steps the reference is the function's take whose
/// start heading is nearest to all the others' (a circular medoid; ties: the position
/// reference), so a turned reference take cannot turn the whole function.
/// Steps run in the order unwrap, pad, align start, heading and angle branches, align position;
/// each is optional and reported per take.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis::preprocess {

enum class StartAlignMethod {
    /// Onset: first frame where the summed speed exceeds `onsetFraction` of its maximum; the
    /// shift is onset(take) - onset(reference).
    Onset,
    /// Cross-correlation of the (mean-removed) summed speed with the reference's; the shift is
    /// the lag in [-maxShiftFrames, maxShiftFrames] of the largest normalised correlation.
    CrossCorrelation,
};

struct PreprocessOptions {
    bool pad = true;
    bool unwrap = true;
    bool alignStart = true;
    bool alignPosition = true;
    bool alignHeading = true;
    /// The part whose start yaw defines the whole-body heading.
    std::string headingPart = "shoulder";
    StartAlignMethod alignMethod = StartAlignMethod::Onset;
    double onsetFraction = 0.1;
    int maxShiftFrames = 30;
    /// Take index of the reference of each cell; when absent in a cell, its lowest take index.
    int referenceTakeIndex = 1;
    /// Emotion whose reference take is the function's position reference; empty = the corpus's
    /// neutral emotion, falling back to the function's first emotion.
    std::string referenceEmotion;
};

/// What was done to one take.
struct TakeReport {
    std::string take;                ///< displayName()
    Eigen::Index framesPadded = 0;   ///< frames appended (last frame repeated)
    int anglesUnwrapped = 0;         ///< 360-degree jumps removed over all angle channels
    int shiftFrames = 0;             ///< frames dropped from the start (< 0: first frame repeated in front)
    bool isTimeReference = false;
    bool isPositionReference = false;
    std::vector<Eigen::Vector3d> positionOffsets; ///< cm added per 6-DOF part (sixDofParts order)
    int branchTurns = 0;             ///< whole turns added to angle channels to meet the reference's branch
    double headingOffsetDeg = 0.0;   ///< degrees added to every yaw channel, in (-180, 180]
    bool isHeadingReference = false; ///< the function's heading (and angle branch) reference
};

struct PreprocessReport {
    std::vector<TakeReport> takes;   ///< in corpus order
    Eigen::Index paddedFrames = 0;   ///< common length after padding (0 when not padded)
};

struct PreprocessResult {
    Corpus corpus;
    PreprocessReport report;
};

/// Runs the selected steps; checks `control` between steps. Validates the corpus first.
Result<PreprocessResult> preprocessCorpus(const Corpus& corpus, const PreprocessOptions& options = {},
                                          const RunControl& control = {});

// The single steps, on plain data, for reuse and tests.

/// Appends copies of the last frame until `frames` rows; returns frames appended.
Eigen::Index padToLength(Take& take, Eigen::Index frames);
/// Unwraps the column in place (steps over 180 deg lose 360); returns the number of wraps removed.
int unwrapDegrees(Eigen::Ref<Eigen::VectorXd> column);
/// Unwraps every angle channel (unit "deg"); returns the total number of wraps removed.
int unwrapAngles(Take& take);
/// Moves each angle channel of `take` by whole turns so its first value is within 180 deg of
/// the same channel of `reference`; returns the number of turns added (absolute, summed).
int matchAngleBranches(Take& take, const Take& reference);
/// Adds to every yaw channel the difference of the heading part's start yaw, reference minus
/// take, taken within (-180, 180]; returns that offset in degrees (0 when the part has no yaw
/// channel). Follow with matchAngleBranches to put every channel on the reference's branch.
double alignStartHeading(Take& take, const Take& reference, const std::string& headingPart);
/// Summed speed per frame (length frames): sum over 6-DOF parts of the position speed (cm/frame),
/// or when the take has none, the sum of absolute differences of all channels. speed(0) = 0.
Eigen::VectorXd summedSpeed(const Take& take);
/// First frame where `speed` reaches fraction * max(speed); 0 for a motionless signal.
Eigen::Index onsetFrame(const Eigen::VectorXd& speed, double fraction);
/// Lag s in [-maxShift, maxShift] maximising the normalised correlation of signal(t + s) with
/// reference(t) over their overlap.
int crossCorrelationShift(const Eigen::VectorXd& signal, const Eigen::VectorXd& reference, int maxShift);
/// Shift of `take` relative to `reference` by the chosen method (positive: take starts late).
int estimateStartShift(const Take& take, const Take& reference, const PreprocessOptions& options);
/// Drops `shift` frames at the start and repeats the last frame at the end (shift < 0: repeats
/// the first frame in front and drops at the end); the frame count is unchanged.
void shiftTake(Take& take, int shift);

} // namespace bunraku::analysis::preprocess
