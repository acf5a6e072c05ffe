#pragma once
/// Thesis 3.4 (figures 3.5-3.9): why wavelet matching restricts its smallest scale. A reference
/// sine, a sample at 1.1 x its frequency with a phase shift plus a 0.4-amplitude sine at 4 x the
/// frequency as noise; each method's correspondence is compared with the true one.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/normalise/wavelet_matching.h"
#include "analysis/wavelet/wavelet.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bunraku::analysis {

/// Defaults: the thesis's ratios (eqs. 3.8-3.13: sample at 1.1 x the reference frequency,
/// phase -0.4 rad, noise 0.4 x sin at about 4 x) on a 200-frame signal whose reference sits near
/// scale 32 and noise near scale 8 (sym3: pseudo-frequency 0.8 / c). Below-noise scales start
/// at 14 (pseudo-frequency 0.057, well under the noise's 0.1) and stop at 20 = frames / 10 so
/// the zero-padded ends (2.5 c frames each) stay a small part of the signal; the noise-band
/// variant uses 1..20. Matching as in thesis 3.4: single frames (tau = 0, eq. 3.4), the band
/// T_cmp = 20 of 3.5.1, no time-evolution constraint (3.5.3 comes later); set path and tau to
/// see how windows and the monotone path change the picture.
struct NoiseExperimentOptions {
    int frames = 200;
    double referenceFrequency = 0.025;  ///< cycles per frame
    double sampleFrequency = 0.0275;    ///< cycles per frame (1.1 x the reference)
    double phaseShiftRadians = -0.4;    ///< x_smp(t) = sin(2 pi f_s t - 0.4) + noise
    double noiseAmplitude = 0.4;        ///< relative to the unit sines
    double noiseFrequency = 0.1;        ///< cycles per frame (4 x the reference)
    std::vector<double> scalesBelowNoise = {14, 15, 16, 17, 18, 19, 20};
    std::vector<double> scalesWithNoise = integerScales(20);
    int tau = 0;
    int searchBand = 20;
    PathMethod path = PathMethod::Independent;
};

/// The thesis's bands (3.4, Table 3.1, Figs. 3.7 and 3.9) as fractions of its signals'
/// frequencies: "wavelet below the noise" considered 0.0178-0.0229 Hz with the reference at
/// 0.0199 Hz (0.894-1.151 x the reference's frequency); "with the noise band" considered up to
/// 0.160 Hz with the noise at 0.0801 Hz (2.0 x the noise's frequency), from the same lowest
/// frequency. The thesis's "Hz" are cycles per sample of its 5119-sample signals: the analysing
/// wavelet's 0.8005 Hz is sym3's centre frequency at scale 1 (eq. 3.14, F_scale = F_psi / scale).
struct ThesisNoiseBands {
    double lowestOfReference = 0.0178 / 0.0199;  ///< 0.894
    double highestOfReference = 0.0229 / 0.0199; ///< 1.151
    double highestOfNoise = 0.160 / 0.0801;      ///< 2.0
};

/// The integer scales whose pseudo-frequency (centre frequency / scale, cycles per frame) lies in
/// [lowFrequency, highFrequency] for `wavelet`; empty when none does.
std::vector<double> scalesInBand(double lowFrequency, double highFrequency, const Wavelet& wavelet = sym3Wavelet());

/// The experiment with the thesis's bands: `base` (the signals, path, tau and band) with
/// scalesBelowNoise and scalesWithNoise taken from ThesisNoiseBands at base's frequencies
/// (for the defaults, 0.025 and 0.1 cycles per frame: scales 28..36 and 4..36).
NoiseExperimentOptions thesisBandOptions(const NoiseExperimentOptions& base = {}, const ThesisNoiseBands& bands = {});

struct MethodError {
    std::string name;
    double meanAbsErrorFrames = 0;
    double maxAbsErrorFrames = 0;
    /// RMS of (noiseless sample at the matched frame - reference) over the frames: how far the
    /// normalised signal is from the reference, what the thesis's Figs. 3.5-3.9 show (blind to
    /// a match one period off).
    double shapeRms = 0;
    std::vector<double> scales; ///< the scales used (empty for amplitude matching)
};

struct NoiseExperimentResult {
    /// "amplitude-dp", "wavelet-below-noise", "wavelet-with-noise-band", in that order.
    std::vector<MethodError> methods;
    Eigen::VectorXd reference;     ///< frames
    Eigen::VectorXd sample;        ///< frames, with the noise
    Eigen::VectorXd cleanSample;   ///< frames, the sample without the noise (signal 1 of eq. 3.12)
    Eigen::VectorXd trueWarp;      ///< t_ref -> true t_smp (frames, sub-frame)
};

/// Runs the three methods, all with the same path method, tau and band.
Result<NoiseExperimentResult> runNoiseExperiment(const NoiseExperimentOptions& options = {}, const RunControl& control = {});

/// Mean and max of |correspondence(t) - trueWarp(t)| over t.
MethodError correspondenceError(std::string name, const Eigen::VectorXi& correspondence, const Eigen::VectorXd& trueWarp);

} // namespace bunraku::analysis
