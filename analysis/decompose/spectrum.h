#pragma once
/// Power spectra of a sampled series (thesis 4.3.2, Figures 4.3-4.8: spectra of the fluctuation
/// eta per channel). One-sided power spectral density in units^2 / Hz on a frequency axis in Hz
/// from the sampling rate, scaled like scipy.signal.periodogram / welch (density scaling), so
/// sum(power) * df equals the variance of the (detrended) series for the periodogram.

#include "analysis/core/result.h"

#include <Eigen/Core>

namespace bunraku::analysis {

struct Spectrum {
    Eigen::VectorXd frequencyHz; ///< 0 .. rate/2, n/2 + 1 bins for segment length n
    Eigen::VectorXd power;       ///< one-sided PSD, units^2 / Hz
};

enum class Detrend { None, Mean };

struct PeriodogramOptions {
    Detrend detrend = Detrend::Mean;
};

/// Periodogram with a rectangular window. Errors: fewer than 2 samples, rate <= 0, non-finite.
Result<Spectrum> periodogram(const Eigen::VectorXd& series, double rateHz, const PeriodogramOptions& options = {});

struct WelchOptions {
    int segmentLength = 32;     ///< samples per segment (clamped to the series length)
    double overlap = 0.5;       ///< fraction of a segment shared with the next, in [0, 1)
    Detrend detrend = Detrend::Mean; ///< per segment
};

/// Welch's averaged periodogram with a periodic Hann window. Errors as periodogram, and
/// segmentLength < 2 or overlap outside [0, 1).
Result<Spectrum> welch(const Eigen::VectorXd& series, double rateHz, const WelchOptions& options = {});

} // namespace bunraku::analysis
