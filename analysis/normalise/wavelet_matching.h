#pragma once
/// Time normalisation by wavelet matching (thesis 3.3-3.6, 5.3.3): for every reference frame
/// t_ref find the sample frame t_smp whose local shape - the CWT coefficients over the scales in
/// a window of +-tau frames - is closest, within the band t_ref +- T_cmp, never running
/// backwards. Several channels may share one correspondence (coupling, thesis eqs. 3.28/3.29):
/// their costs are summed. Chapter 5 adds the approximation term (eq. 5.17).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/wavelet/cwt.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

enum class PathMethod {
    Greedy,  ///< thesis 3.5.3: scan t_ref upward, search only t_smp >= the previous choice
    Optimal, ///< dynamic programming: the non-decreasing path in the band of least total cost
    /// Thesis 3.3/3.5.1 before the time-evolution fix: each frame's cheapest sample frame in the
    /// band, independently - may run backwards. Only for reproducing the thesis's experiments.
    Independent,
};

enum class ChannelWeighting {
    None,        ///< raw coefficients (the thesis)
    Standardise, ///< each channel divided by its reference-take standard deviation (cm vs degrees)
};

enum class LevelAlignment {
    None,       ///< transform the values as they are
    /// Each channel minus its first frame before the transform: thesis 2.2 step 4 aligns start
    /// positions before normalising; this extends it to angles (e.g. a take turned by 180 deg in
    /// yaw) and makes the zero-padded CWT edges of takes at different levels comparable.
    FirstFrame,
};

/// How takes of different lengths are brought together before the local matching (which only
/// moves each frame within +-T_cmp of the diagonal).
enum class TimeScaling {
    /// Global when the lengths differ by more than kAutoScalingBand of the band T_cmp, else None.
    Auto,
    /// As they are (the thesis): a reference longer than the sample plus T_cmp has no path, and
    /// a sample longer than the reference plus T_cmp is cut.
    None,
    /// A global time scale first: the sample resampled (linearly) to the reference's length,
    /// t_smp = s t_ref with s = (N_smp - 1) / (N_ref - 1); the local matching then runs in that
    /// scaled time and its correspondence is mapped back (t_smp = s c(t_ref), rounded).
    Global,
};

/// The largest search band T_cmp the matcher takes, frames: the band's width 2 T_cmp + 1 sizes
/// every row of costs and back-pointers. The one limit of T_cmp: the pipeline's parameters, the
/// workbench's controls and the command line's options take it from here.
inline constexpr int kMaxSearchBand = 16000;

/// TimeScaling::Auto scales when |N_ref - N_smp| > kAutoScalingBand * T_cmp.
inline constexpr double kAutoScalingBand = 0.5;

struct MatchOptions {
    std::vector<double> scales = integerScales(16); ///< c_1..c_max (thesis: 1..16 or 1..21)
    int tau = 4;                     ///< half window, frames (thesis 3.5.2: tau = 4)
    int searchBand = 20;             ///< T_cmp, frames: t_smp in t_ref +- T_cmp (thesis: 20)
    double approximationWeight = 0;  ///< M of thesis eq. 5.17 (chapter 5 uses 8); 0 = eq. 3.28
    PathMethod path = PathMethod::Greedy;
    ChannelWeighting weighting = ChannelWeighting::None;
    LevelAlignment level = LevelAlignment::FirstFrame;
    CwtOptions cwt;                  ///< wavelet (sym3) and transform method
    TimeScaling timeScaling = TimeScaling::Auto; ///< takes of different lengths
};

struct MatchResult {
    /// t_ref -> t_smp, one sample frame per reference frame, non-decreasing.
    Eigen::VectorXi correspondence;
    /// Sub-frame monotone warp t_ref -> t_smp (frames, same length), for smooth display and
    /// resampling: the correspondence with its plateaus and jumps spread linearly.
    Eigen::VectorXd smoothWarp;
    /// Sum over t_ref of the chosen window cost (thesis eq. 3.28/5.17), summed over channels.
    double cost = 0;
};

/// Sample frames per reference frame of the global time scale the options apply before the
/// local matching: (N_smp - 1) / (N_ref - 1), or 1 when they apply none (TimeScaling).
double globalTimeScale(const MatchOptions& options, Eigen::Index referenceFrames, Eigen::Index sampleFrames);

/// The rows of `values` linearly interpolated at t * scale, t = 0..frames - 1 (clamped).
Eigen::MatrixXd scaledInTime(const Eigen::MatrixXd& values, double scale, Eigen::Index frames);

/// A match made in scaled sample time mapped back to the sample's frames: correspondence
/// round(scale c), smooth warp scale w (both clamped to the sample), cost unchanged.
MatchResult unscaledMatch(MatchResult match, double scale, Eigen::Index sampleFrames);

/// Matches sample to reference: reference and sample are frames x channels (the same channels
/// in the same order; the frame counts may differ by any amount: see TimeScaling), all
/// channels sharing one correspondence.
/// Window indices beyond either end replicate the edge frame. InvalidArgument for tau < 0,
/// searchBand outside 0..kMaxSearchBand, empty scales, a scale whose filter is longer than either signal
/// (largestScale), channel counts that differ, NaN; Cancelled via control.
Result<MatchResult> matchChannels(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& sample,
                                  const MatchOptions& options = {}, const RunControl& control = {});

/// x_nor(t_ref) = x_smp(correspondence(t_ref)) for every column: the sample on the reference's
/// time axis (thesis 3.3). sample: frames x channels; result: reference frames x channels.
Eigen::MatrixXd applyCorrespondence(const Eigen::MatrixXd& sample, const Eigen::VectorXi& correspondence);

/// The sample linearly interpolated at the sub-frame warp (clamped to its frames).
Eigen::MatrixXd applyWarp(const Eigen::MatrixXd& sample, const Eigen::VectorXd& warp);

} // namespace bunraku::analysis
