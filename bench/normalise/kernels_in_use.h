#pragma once
/// Which kernels the normalisation benchmarks run: the SIMD level (analysis/wavelet/simd_level.h;
/// BUNRAKU_SIMD=avx2 or =plain lowers it) and each kernel family's version at that level.

#include "analysis/normalise/band_distances.h"
#include "analysis/normalise/distance_kernel.h"
#include "analysis/wavelet/cwt_direct.h"
#include "analysis/wavelet/simd_level.h"

#include <string>

namespace bunraku::bench {

inline std::string kernelsInUse()
{
    using namespace analysis;
    const SimdLevel level = simdLevel();
    return std::string(simdLevelName(level)) + " (this CPU runs up to " + simdLevelName(cpuSimdLevel()) + "): CWT "
           + detail::directKernelName(level) + ", band distances " + detail::bandKernelName(detail::currentBandKernel())
           + ", window sums and dynamic programme " + detail::scanKernelName(level);
}

} // namespace bunraku::bench
