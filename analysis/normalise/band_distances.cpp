#include "analysis/normalise/band_distances.h"

#include "analysis/wavelet/simd_level.h"

#include <algorithm>
#include <cstddef>

#if defined(__GNUC__) && defined(__x86_64__)
#define BUNRAKU_BAND_SIMD 1
#include <immintrin.h>
#endif

namespace bunraku::analysis::detail {

namespace {

void bandDistancesPlain(const BandTile& tile)
{
    for (std::size_t p = 0; p < tile.count; ++p) {
        double* row = tile.e + p * tile.eStride;
        for (std::size_t o = 0; o < tile.width; ++o) {
            double dot = 0.0;
            for (std::size_t f = 0; f < tile.features; ++f) dot += tile.a[f][p] * tile.b[f][p + o];
            row[o] = std::max(0.0, (tile.aNorms[p] + tile.bNorms[p + o]) - 2.0 * dot);
        }
    }
}

} // namespace

#ifdef BUNRAKU_BAND_SIMD
// The same kernel text compiled twice: 6 reference frames by 2 x 4 sample frames fill AVX2's
// 16 registers, 6 by 4 x 4 use AVX-512VL's 32 (still 256-bit vectors).
#pragma GCC push_options
#pragma GCC target("avx2,fma")
namespace avx2 {
constexpr int kRows = 6;
constexpr int kVectors = 2;
#include "analysis/normalise/band_distances_simd.inc"
} // namespace avx2
#pragma GCC pop_options

#ifndef BUNRAKU_NO_AVX512
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx2,fma")
namespace avx512 {
constexpr int kRows = 6;
constexpr int kVectors = 4;
#include "analysis/normalise/band_distances_simd.inc"
} // namespace avx512
#pragma GCC pop_options
#endif
#endif

std::vector<BandKernel> availableBandKernels()
{
    std::vector<BandKernel> kernels{BandKernel::Plain};
#ifdef BUNRAKU_BAND_SIMD
    if (simdLevel() >= SimdLevel::Avx2) kernels.push_back(BandKernel::Avx2);
#ifndef BUNRAKU_NO_AVX512
    if (simdLevel() >= SimdLevel::Avx512) kernels.push_back(BandKernel::Avx512);
#endif
#endif
    return kernels;
}

void bandDistancesWith(BandKernel kernel, const BandTile& tile)
{
    switch (kernel) {
#if defined(BUNRAKU_BAND_SIMD) && !defined(BUNRAKU_NO_AVX512)
    case BandKernel::Avx512: avx512::bandDistances(tile); return;
#endif
#ifdef BUNRAKU_BAND_SIMD
    case BandKernel::Avx2: avx2::bandDistances(tile); return;
#endif
    default: bandDistancesPlain(tile); return;
    }
}

void bandDistances(const BandTile& tile)
{
    const SimdLevel level = simdLevel();
    bandDistancesWith(level == SimdLevel::Avx512 ? BandKernel::Avx512 : level == SimdLevel::Avx2 ? BandKernel::Avx2 : BandKernel::Plain, tile);
}

const char* bandKernelName(BandKernel kernel)
{
    switch (kernel) {
    case BandKernel::Avx512: return "avx512vl";
    case BandKernel::Avx2: return "avx2";
    default: return "plain";
    }
}

} // namespace bunraku::analysis::detail
