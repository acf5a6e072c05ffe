#pragma once
/// Mother wavelets for the continuous wavelet transform (thesis 3.2, 5.3.1): the orthogonal
/// Daubechies (db1..db8) and symlets (sym2..sym8) from their published reconstruction filters,
/// sampled by the cascade algorithm, and the continuous Mexican hat and Morlet wavelets, as
/// MATLAB's wavelet toolbox and PyWavelets define them. sym3 (= db3) is the thesis's wavelet.

#include "analysis/core/result.h"

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

enum class WaveletKind {
    Orthogonal, ///< compactly supported on [0, filterLength - 1], sampled by the cascade algorithm
    Continuous, ///< given by a formula on [lowerBound, upperBound] (mexh, morl)
};

struct Wavelet {
    std::string name = "sym3";
    WaveletKind kind = WaveletKind::Orthogonal;
    /// Reconstruction low-pass filter rec_lo (orthogonal wavelets only; empty otherwise).
    std::vector<double> reconstructionLowPass;
    /// Support of psi in wavelet units: [0, 2N-1] for dbN/symN, [-8, 8] for mexh and morl.
    double lowerBound = 0.0;
    double upperBound = 5.0;
};

/// "sym3", "db1".."db8", "sym2".."sym8", "mexh", "morl"; NotFound for any other name.
Result<Wavelet> waveletByName(std::string_view name);
/// The thesis's analysing wavelet.
Wavelet sym3Wavelet();
/// Every name waveletByName accepts.
std::vector<std::string> waveletNames();

/// psi sampled on a grid: x (wavelet units, increasing) and psi(x), same length.
struct SampledWavelet {
    Eigen::VectorXd x;
    Eigen::VectorXd psi;
};

/// psi as pywt's Wavelet.wavefun(precision) returns it: orthogonal wavelets by the cascade
/// algorithm on x_i = i / 2^precision (a leading 0 sample, as pywt), continuous wavelets on
/// 2^precision points spanning [lowerBound, upperBound]. precision in 1..20.
SampledWavelet waveletFunction(const Wavelet& wavelet, int precision = 10);

/// Psi(x) = cumsum(psi) * step, the rectangle-rule integral of psi from the left end (pywt
/// integrate_wavelet; legacy MATLAB intwave). The CWT filters are samples of it.
SampledWavelet integratedWavelet(const Wavelet& wavelet, int precision = 10);

/// Centre frequency in cycles per wavelet unit (MATLAB centfrq, pywt central_frequency): the
/// dominant Fourier bin of psi. About 0.8 for sym3.
double centreFrequency(const Wavelet& wavelet, int precision = 8);

/// Pseudo-frequency of a scale: centreFrequency / (scale * samplingPeriod), in cycles per unit
/// of samplingPeriod (Hz when the period is in seconds).
double scaleToFrequency(const Wavelet& wavelet, double scale, double samplingPeriod = 1.0, int precision = 8);

} // namespace bunraku::analysis
