#pragma once
/// Phase components (thesis 5.3.3-5.3.4): the emotional axis (sample) matched to the functional
/// axis (reference) on all 6 axis DOF together with wavelet coefficients plus the approximation
/// term (eq. 5.16 summed over DOF, eq. 5.17), never running backwards. The result is the
/// time-correspondence graph of Fig. 5.13, as frames and as a monotone curve with control
/// points for design (output = emotional frame -> source = functional frame).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/design/warp_curve.h"
#include "analysis/normalise/wavelet_matching.h"

#include <Eigen/Core>

namespace bunraku::analysis {

struct PhaseOptions {
    /// Thesis 5.3.4: scales 1..16, approximation weight M = 8 (per unit weight of a scale),
    /// tau = 4, raw coefficients, the greedy scan. Decision: T_cmp = 30 frames, since emotional
    /// phrases shift by up to ~27 frames on the synthetic corpus (measured in
    /// docs/MOTION-AXIS.md, with the other settings compared).
    MatchOptions match = [] {
        MatchOptions m;
        m.scales = integerScales(16);
        m.approximationWeight = 8.0;
        m.tau = 4;
        m.searchBand = 30;
        m.path = PathMethod::Greedy;
        m.weighting = ChannelWeighting::None;
        return m;
    }();
    int controlPointSpacing = 8; ///< frames between the curve's control points
};

struct PhaseResult {
    /// Functional frame -> emotional frame (matchChannels' correspondence), non-decreasing.
    Eigen::VectorXi correspondence;
    /// Functional frame -> emotional frame, sub-frame and monotone.
    Eigen::VectorXd functionalToEmotional;
    /// Emotional frame -> functional frame (the inverse), monotone: the design warp's samples.
    Eigen::VectorXd emotionalToFunctional;
    /// Control points summarising emotionalToFunctional (Fritsch-Carlson between them).
    WarpCurve curve;
    double cost = 0.0;
};

/// functional, emotional: frames x 6 axis coordinates (axis_channels.h). Errors from the
/// matcher (too short for the largest scale, NaN) pass through; Cancelled via control.
Result<PhaseResult> extractPhase(const Eigen::MatrixXd& functional, const Eigen::MatrixXd& emotional,
                                 const PhaseOptions& options = {}, const RunControl& control = {});

/// The inverse of a non-decreasing sampled map f (frame -> value) evaluated at 0..targetFrames-1:
/// for each value v the (interpolated) frame where f reaches v, clamped to f's range.
Eigen::VectorXd invertMonotone(const Eigen::VectorXd& map, Eigen::Index targetFrames);

/// Rows of `signal` linearly interpolated at fractional frames `at` (clamped).
Eigen::MatrixXd resampleRows(const Eigen::MatrixXd& signal, const Eigen::VectorXd& at);

} // namespace bunraku::analysis
