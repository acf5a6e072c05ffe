#pragma once
/// Thesis 3.4 (figures 3.5-3.9): why wavelet matching restricts its smallest scale. A reference
/// sine, a sample at 1.1 x its frequency with a phase shift plus a 0.4-amplitude sine at 4 x the
/// frequency as noise; each method's correspondence is compared with the true one.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/normalise/wavelet_matching.h"

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

struct MethodError {
    std::string name;
    double meanAbsErrorFrames = 0;
    double maxAbsErrorFrames = 0;
    std::vector<double> scales; ///< the scales used (empty for amplitude matching)
};

struct NoiseExperimentResult {
    /// "amplitude-dp", "wavelet-below-noise", "wavelet-with-noise-band", in that order.
    std::vector<MethodError> methods;
    Eigen::VectorXd reference;     ///< frames
    Eigen::VectorXd sample;        ///< frames, with the noise
    Eigen::VectorXd trueWarp;      ///< t_ref -> true t_smp (frames, sub-frame)
};

/// Runs the three methods, all with the same path method, tau and band.
Result<NoiseExperimentResult> runNoiseExperiment(const NoiseExperimentOptions& options = {}, const RunControl& control = {});

/// Mean and max of |correspondence(t) - trueWarp(t)| over t.
MethodError correspondenceError(std::string name, const Eigen::VectorXi& correspondence, const Eigen::VectorXd& trueWarp);

} // namespace bunraku::analysis
