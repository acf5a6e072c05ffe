#pragma once
/// Internal: the direct (time-domain) CWT of several series at once - what cwt(), cwtChannels
/// and cwtChannelSeries run for CwtMethod::Direct. The series (channels, or segments of one long
/// channel) are interleaved eight to a row, so every vector load of the convolution is aligned
/// and one broadcast filter tap serves eight series; the input is padded with zeros, so frames
/// near the ends run the same kernel as the rest. Kernels: plain, AVX2/FMA and AVX-512 (chosen by
/// simdLevel()).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/wavelet/cwt.h"
#include "analysis/wavelet/simd_level.h"

#include <Eigen/Core>

#include <cstddef>

namespace bunraku::analysis::detail {

/// Pywt/MATLAB keep the differenced full convolution (length N + M - 2) from floor((M - 2) / 2),
/// M = filter length.
inline Eigen::Index centralOffset(Eigen::Index filterLength) { return (filterLength - 2) / 2; }

/// Coefficient (frame t, channel c, scale index s) goes to
/// out[t * rowStride + c * channelStride + s * scaleStride].
struct CoefficientLayout {
    double* out = nullptr;
    Eigen::Index rowStride = 1;
    Eigen::Index channelStride = 0;
    Eigen::Index scaleStride = 0;
};

/// The direct CWT of `channels` series of `frames` samples each (series c at input + c * frames)
/// at every scale of the bank: -sqrt(scale) * sum_{j = 0..M} kernel[M - j] x[t + offset + 1 - M + j],
/// M + 1 = kernel length, x = 0 outside the series. Every sum runs j upward from 0 (fused
/// multiply-adds in the SIMD kernels, multiply then add in the plain one), whatever the layout,
/// the channel count or the kernel's level: only fusing differs between levels.
/// Cancelled when the stop token fires (checked every few thousand frames); progress reported.
Status directTransform(const double* input, Eigen::Index frames, Eigen::Index channels, const CwtFilterBank& bank,
                       const CoefficientLayout& layout, const RunControl& control, SimdLevel level = simdLevel());

/// The kernel's name at a level: "plain", "avx2" or "avx512".
const char* directKernelName(SimdLevel level);

/// One run of the lane kernel: out[t * 8 + l] = factor * sum_{j < taps} weights[j] x[(t + j) * 8 + l]
/// for t < count and the eight lanes l; x and out 64-byte aligned, x readable for count + taps - 1
/// rows.
struct LaneConvolution {
    const double* x = nullptr;
    const double* weights = nullptr;
    std::size_t taps = 0;
    double factor = 1.0;
    std::size_t count = 0;
    double* out = nullptr;
};

inline constexpr std::size_t kLanes = 8;

void convolveLanes(const LaneConvolution& job, SimdLevel level);

/// The transpose of the kernel's output into series: targets[l][r] = rows[r * 8 + l] for
/// r < valid[l] <= count (a null target skips its lane); rows 64-byte aligned.
void storeLanes(const double* rows, std::size_t count, double* const* targets, const std::size_t* valid, SimdLevel level);

} // namespace bunraku::analysis::detail
