#pragma once
/// Continuous wavelet transform, exactly as MATLAB's legacy `cwt` (and pywt's `cwt`, which
/// mirrors it): thesis eq. 5.12, d(t, c) = integral x(s) c^(-1/2) psi((s - t) / c) ds, computed
/// by convolving x with the reversed integrated wavelet sampled at scale c, differencing and
/// keeping the central N samples. No signal extension: samples outside x count as zero, so
/// about half the wavelet's support at each end feels the edge (THESIS-DIGEST section 3).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/wavelet/wavelet.h"

#include <Eigen/Core>

#include <vector>

namespace bunraku::analysis {

enum class CwtMethod {
    Automatic, ///< Direct for short signals and filters, Fft otherwise
    Direct,    ///< time-domain convolution, O(N * filter length) per scale
    Fft,       ///< FFTW3 convolution by overlap-save, O(N log L) per scale; agrees with Direct to 1e-9 relative
};

struct CwtOptions {
    Wavelet wavelet = sym3Wavelet();
    int precision = 10; ///< cascade levels of the sampled wavelet (MATLAB and pywt use 10)
    CwtMethod method = CwtMethod::Automatic;
};

/// The scales 1, 2, ..., maxScale.
std::vector<double> integerScales(int maxScale);

/// The sampled filters of one wavelet at a list of scales, reusable across signals (building it
/// integrates the wavelet once; transforming many channels with one bank saves that work).
struct CwtFilterBank {
    std::vector<double> scales;
    /// One filter per scale: reverse(Psi[floor(k / (scale * step))]), k = 0 .. scale * span.
    std::vector<Eigen::VectorXd> filters;
    /// Per scale, the first difference of [0, filter, 0] (one sample longer than the filter):
    /// coefficient(t) = -sqrt(scale) * (signal conv kernel)(t + floor((length - 2) / 2) + 1).
    std::vector<Eigen::VectorXd> kernels;
    CwtMethod method = CwtMethod::Automatic;
};

/// Checks the scales (finite, > 0) and builds the filters; InvalidArgument names a bad scale.
Result<CwtFilterBank> makeCwtFilterBank(const std::vector<double>& scales, const CwtOptions& options = {});

struct CwtResult {
    /// samples x scales (rows = time, column i = scales[i]); pywt's layout is the transpose.
    Eigen::MatrixXd coefficients;
    std::vector<double> scales;
};

/// The method Automatic resolves to for a signal of `samples` samples: Fft when the signal is
/// long (>= 4096 samples: below, FFTW planning dominates) and the direct convolutions' work
/// (samples x summed filter lengths) exceeds 2 n log2 n for each of the 2 scales + 1 FFTs of the
/// padded length n (measured break-even on this machine); Direct otherwise.
CwtMethod resolvedCwtMethod(Eigen::Index samples, const CwtFilterBank& bank);

/// The CWT of one signal at every scale of the bank. Any positive scale is computed (as MATLAB and
/// pywt do; scales past largestScale are dominated by the zero edges - matching rejects them).
/// InvalidArgument when the signal is empty or not finite; Cancelled when the stop token fires
/// (checked between scales or every few thousand frames); progress is reported as the work
/// advances. The direct method sums each coefficient's terms in one order whatever the layout,
/// so its coefficients equal cwtChannels' bit for bit at a given SIMD level
/// (analysis/wavelet/simd_level.h; the SIMD levels fuse the multiply-adds, plain does not).
Result<CwtResult> cwt(const Eigen::VectorXd& signal, const CwtFilterBank& bank, const RunControl& control = {});

/// frames x (channels * scales), row-major: a frame's coefficients are contiguous.
using CoefficientRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The CWT of every column of `input` (frames x channels): column c * scales + s holds
/// channel c at scale s, equal to cwt(input.col(c)). The direct method runs all channels
/// together (eight series side by side in the vector lanes, long channels cut into segments);
/// the FFT method one channel at a time.
Result<CoefficientRows> cwtChannels(const Eigen::MatrixXd& input, const CwtFilterBank& bank,
                                    const RunControl& control = {});

/// The same coefficients column-major: each channel-and-scale series is contiguous (what
/// matching reads a coupling set at a time). Equal to cwtChannels element for element.
Result<Eigen::MatrixXd> cwtChannelSeries(const Eigen::MatrixXd& input, const CwtFilterBank& bank,
                                         const RunControl& control = {});

/// cwtChannelSeries into `out`, resized to frames x (channels * scales): its storage is reused
/// when it already has that size (for callers transforming many inputs of one size).
Status cwtChannelSeriesInto(const Eigen::MatrixXd& input, const CwtFilterBank& bank, Eigen::MatrixXd& out,
                            const RunControl& control = {});

/// Convenience: builds the bank and transforms.
Result<CwtResult> cwt(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                      const CwtOptions& options = {}, const RunControl& control = {});

/// The largest integer scale whose filter fits a signal of `samples` samples (thesis 5.3.2: 21
/// for 106 frames and sym3): floor((samples - 1) / span) with span the wavelet's support width,
/// rounded so that span * scale + 1 <= samples.
int largestScale(const Wavelet& wavelet, Eigen::Index samples);

} // namespace bunraku::analysis
