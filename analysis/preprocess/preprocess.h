#pragma once
/// Preprocessing of a corpus, thesis 2.2: (1) pad every take to the longest with its last frame,
/// (2) unwrap angles (the thesis remapped to 0..360; we unwrap), (3) align the start times of the
/// K takes of each function x emotion cell to the cell's time reference (automatic: the median
/// onset among its longest takes), (4) translate each take so its first-frame position matches
/// that of its function's reference take: by default one rigid translation of the whole body
/// (start_position.h; per-part offsets as an option).
/// Two steps the thesis implies but does not name: after unwrapping, every angle channel is
/// moved by whole turns so its first value lies within 180 deg of the function's reference take
/// (the thesis's 0..360 remapping kept all takes on one branch; per-take unwrapping does not),
/// and (5) the whole-body heading is aligned: all yaw channels of a take are offset so the
/// heading part's (default the shoulder's) start yaw equals the reference's; relative yaw
/// (a head turned away) is kept. For these two steps the reference is the function's take whose
/// start heading is nearest to all the others' (a circular medoid; ties: the position
/// reference), so a turned reference take cannot turn the whole function.
/// Steps run in the order unwrap, pad, align start, heading and angle branches, align position;
/// each is optional and reported per take. "Unwrap" is the discontinuity (Euler) filter on the
/// 6-DOF parts' angle triples (frame by frame the equivalent triple nearest the previous one:
/// whole turns and the mirrored triple yaw + 180, 180 - pitch, roll + 180) and whole turns on
/// lone angle channels; the branch step moves each part by one such change of its triple.
/// A take's full skeleton (Take::skeleton) goes through every step: padded and shifted with its
/// frames, turned with the heading and moved rigidly by the heading part's position offset.

#include "analysis/core/corpus.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/preprocess/start_alignment.h"
#include "analysis/preprocess/start_position.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis::preprocess {

struct PreprocessOptions {
    bool pad = true;
    bool unwrap = true;
    bool alignStart = true;
    bool alignPosition = true;
    bool alignHeading = true;
    /// Step (4): one rigid translation per take (thesis) or one offset per part.
    PositionAlignment positionAlignment = PositionAlignment::Rigid;
    /// The part whose start yaw defines the whole-body heading.
    std::string headingPart = "shoulder";
    StartAlignMethod alignMethod = StartAlignMethod::Onset;
    /// Onset search threshold: the noise floor plus this fraction of (peak - floor) of the
    /// departure from the start pose (departureOnset).
    double onsetFraction = 0.1;
    /// Quantile of the non-zero frames' activity taken as the noise floor (the quietest frames).
    double quietFraction = 0.25;
    /// Start of motion: where the departure from the start pose rises above this multiple of
    /// the noise floor (departureOnset's band; xcorr clips the departure at twice this).
    double noiseBand = 1.5;
    int maxShiftFrames = 30;
    /// Angle weight and smoothing of the activity and departure signals both methods use.
    ActivityOptions activity;
    /// Take index of each cell's time reference. 0 (default) = automatic: the median onset
    /// among the takes at least `longTakeFraction` as long as the cell's longest (thesis 3.6.1,
    /// chooseTimeReference); when a cell lacks the named take, the automatic choice.
    /// The function's position reference (step 4) is the named take of its reference emotion,
    /// or its lowest take index when 0 or absent.
    int referenceTakeIndex = 0;
    /// Takes at least this fraction of the cell's longest (before padding) count as long.
    double longTakeFraction = 0.95;
    /// Emotion whose reference take is the function's position reference; empty = the corpus's
    /// neutral emotion, falling back to the function's first emotion.
    std::string referenceEmotion;
};

/// What was done to one take.
struct TakeReport {
    std::string take;                ///< displayName()
    Eigen::Index framesPadded = 0;   ///< frames appended (last frame repeated)
    int anglesUnwrapped = 0;         ///< discontinuities removed: by the Euler filter (parts) and 360-degree jumps (lone angle channels)
    int shiftFrames = 0;             ///< frames dropped from the start (< 0: first frame repeated in front)
    bool isTimeReference = false;
    double onsetFrame = 0.0;         ///< start of motion before shifting (fractional frame, departureOnset; when aligning start)
    bool isPositionReference = false;
    std::vector<Eigen::Vector3d> positionOffsets; ///< cm added per 6-DOF part (sixDofParts order; all equal when rigid)
    int branchTurns = 0;             ///< whole turns added to angle channels to meet the reference's branch (+1 per part mirrored)
    double headingOffsetDeg = 0.0;   ///< degrees added to every yaw channel, in (-180, 180]
    bool isHeadingReference = false; ///< the function's heading (and angle branch) reference
};

/// The time reference chosen for one function x emotion cell.
struct CellTimeReference {
    std::string function;
    std::string emotion;
    int takeIndex = 0;        ///< the reference's TakeLabels::takeIndex
    bool automatic = true;    ///< chosen by chooseTimeReference (not named by referenceTakeIndex)
    double onsetFrame = 0.0;  ///< its onset (fractional frame)
};

struct PreprocessReport {
    std::vector<TakeReport> takes;   ///< in corpus order
    std::vector<CellTimeReference> timeReferences; ///< per cell, functions() x emotions() order (when aligning start)
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

/// Appends copies of the last frame until `frames` rows (the skeleton too); returns frames appended.
Eigen::Index padToLength(Take& take, Eigen::Index frames);
/// Unwraps the column in place (steps over 180 deg lose 360); returns the number of wraps removed.
int unwrapDegrees(Eigen::Ref<Eigen::VectorXd> column);
/// The discontinuity filter of every 6-DOF part (filterEulerAngles, analysis/core/angle_channels.h)
/// and unwrapDegrees of every other angle channel (unit "deg"); returns the discontinuities
/// removed (a wrap into and back out of a branch counts two). Orientations are unchanged.
int unwrapAngles(Take& take);
/// Moves each angle channel of `take` by whole turns so its first value is within 180 deg of
/// the same channel of `reference`; returns the number of turns added (absolute, summed).
/// preprocessCorpus first moves each 6-DOF part onto the reference's branch as a whole
/// (matchPartBranches: turns or the mirrored triple), then calls this.
int matchAngleBranches(Take& take, const Take& reference);
/// Heading of `reference`'s start relative to `take`'s, degrees in (-180, 180]: for a 6-DOF
/// heading part the twist about the vertical of the turn from the take's start orientation to
/// the reference's (swing-twist decomposition, measured on rotations: independent of the Euler
/// branch and of the part's frame convention; the yaw difference for an upright part), else the
/// difference of the start yaws.
double startHeadingDifference(const Take& reference, const Take& take, const std::string& headingPart);
/// Turns the whole take rigidly about the vertical through the heading part's start position
/// by startHeadingDifference (reference minus take, within (-180, 180]): every yaw channel gets the offset and every 6-DOF part's position is rotated
/// about the pivot. Returns the offset in degrees (0 when the part has no yaw channel). Follow
/// with matchAngleBranches to put every channel on the reference's branch.
double alignStartHeading(Take& take, const Take& reference, const std::string& headingPart);
/// Shift of `take` relative to `reference` by the chosen method (positive: take starts late), on
/// activitySignal(options.activity): onset difference rounded to whole frames, or the xcorr lag.
int estimateStartShift(const Take& take, const Take& reference, const PreprocessOptions& options);

} // namespace bunraku::analysis::preprocess
