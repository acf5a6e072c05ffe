#pragma once
/// Motion design (thesis 5.5): from a functional (no emotion) take, 1) its axis and relative
/// motion, 2) per-phrase gains on the axis, 3) axis and relative motion recombined, 4) time
/// warped by the edited correspondence curve. The expensive part (axis, relative motion) is
/// prepared once in a DesignBasis; designMotion re-synthesises in well under a millisecond
/// for a 106-frame take, so an editor can re-run it on every control-point drag.
/// extractDesign gives the defaults from a measured emotional take: designing with them
/// reproduces that take's axis.

#include "analysis/axis/axis_channels.h"
#include "analysis/axis/inertia_axis.h"
#include "analysis/axis/relative_motion.h"
#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/core/take.h"
#include "analysis/design/phase_extraction.h"
#include "analysis/design/phrase_gains.h"
#include "analysis/design/warp_curve.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

/// What design needs from the functional take, computed once.
struct DesignBasis {
    Take functional;             ///< the source take (layout of the output)
    MotionAxis axis;             ///< its motion axis
    Eigen::MatrixXd coordinates; ///< frames x 6 axis coordinates (axis_channels.h)
    RelativeMotion relative;     ///< parts in the axis frame
};

Result<DesignBasis> prepareDesign(const AxisModel& model, const Take& functional, const AxisOptions& options = {},
                                  const RunControl& control = {});

struct DesignedMotion {
    Take take;                                ///< the designed take, functional's channels, warp's frames
    Eigen::MatrixXd axisCoordinates;          ///< output frames x 6: the designed axis
    std::vector<RigidTransform> world_T_axis; ///< the designed axis per output frame
};

/// thesis 5.5 steps 2-4: gains on the axis coordinates per phrase (functional time), recombined
/// with the relative motion, then output frame u shows functional time warp(u) (axis
/// coordinates and part positions interpolated linearly, rotations by slerp). An empty gain set
/// scales nothing; the warp must be valid (validateWarpCurve) or the identity is used. The
/// warp may change the length by any amount (outputFrames). When the functional take carries
/// its full skeleton, the designed take carries it too (designedSkeleton).
DesignedMotion designMotion(const DesignBasis& basis, const WarpCurve& warp, const GainSet& gains);

/// The designed full skeleton (docs/MOTION-AXIS.md, "The skeleton in a design"): every joint of
/// the functional take's skeleton at the warped time `at` (functional frames, one per output
/// frame; slerp, linear root translation), and the roots of the 4 parts' chains moved by the
/// axis correction C(u) = world_T_designedAxis(u) * world_T_axis(at(u))^-1 - the one rigid
/// transform that takes every part from its warped to its designed pose, since design keeps
/// each part's motion relative to the axis. Every other joint follows through its unchanged
/// local motion, so bone lengths stay those of the source; a root without a part in its tree
/// keeps its warped motion. Null when the functional take has no skeleton.
SkeletalMotionPtr designedSkeleton(const DesignBasis& basis, const Eigen::VectorXd& at,
                                   const std::vector<RigidTransform>& world_T_designedAxis);

struct ExtractionOptions {
    PhaseOptions phase;
    GainOptions gains;
    /// Phrase boundaries in functional frames (0 ... last); empty = suggestPhraseBoundaries.
    std::vector<Eigen::Index> boundaries;
    PhraseOptions phrases;
    /// Extra rounds of phase matching against the functional axis with the gains of the
    /// previous round applied: amplitude differences (a hostile bow half as deep) otherwise
    /// mislead the shape matching. 0 = the thesis's single pass.
    int refinementPasses = 2;
};

struct DesignParameters {
    PhaseResult phase;
    Eigen::MatrixXd emotionalOnFunctionalTime; ///< the phase-adjusted emotional axis (Fig. 5.14)
    GainSet gains;
};

/// Phase then amplitude components of emotional against functional (frames x 6 axis coordinates
/// each): the design parameters that turn the functional axis into the emotional one. Phrase
/// boundaries are suggested on the functional axis when not given; with refinementPasses > 0
/// the phase is re-matched against the gain-adjusted functional axis and the gains re-extracted.
Result<DesignParameters> extractDesign(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                                       const ExtractionOptions& options = {}, const RunControl& control = {});

/// Gains of a known phase: the emotional axis resampled at `functionalToEmotional` (one
/// emotional frame per functional frame) compared with the functional axis per phrase.
Result<GainSet> extractGainsWithWarp(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                                     const Eigen::VectorXd& functionalToEmotional,
                                     const std::vector<Eigen::Index>& boundaries, const GainOptions& options = {});

/// Gains for other phrase boundaries with an extraction's phase kept (the workbench re-extracts
/// them when the user edits the boundaries): extractGains of `functional` against
/// parameters.emotionalOnFunctionalTime over `boundaries` (0 ... frames - 1). The phase and its
/// refinement passes are not re-run; for the boundaries the parameters were extracted with it
/// reproduces parameters.gains. thesis eqs. 5.22, 5.23.
Result<GainSet> extractGainsForBoundaries(const Eigen::MatrixXd& functional, const DesignParameters& parameters,
                                          const std::vector<Eigen::Index>& boundaries, const GainOptions& options = {});

/// Relative error of thesis eq. 5.18's form: sqrt(sum |designed - measured|^2) / sqrt(sum |measured|^2)
/// over all frames and columns (rows beyond the shorter are ignored).
double relativeError(const Eigen::MatrixXd& designed, const Eigen::MatrixXd& measured);

} // namespace bunraku::analysis
