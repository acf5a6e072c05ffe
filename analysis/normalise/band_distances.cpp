#include "analysis/normalise/band_distances.h"

#include "analysis/wavelet/simd_level.h"

#include <algorithm>
#include <cstddef>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) // GCC target pragmas (clang: plain kernels)
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
            if (p + o < tile.from) {
                row[o] = 0.0;
                continue;
            }
            double dot = 0.0;
            for (std::size_t f = 0; f < tile.features; ++f) dot += tile.a[f * tile.aStride + p] * tile.b[f * tile.bStride + p + o];
            row[o] = std::max(0.0, (tile.aNorms[p] + tile.bNorms[p + o]) - 2.0 * dot);
        }
    }
}

} // namespace

#ifdef BUNRAKU_BAND_SIMD
// The same kernel text compiled twice: 6 reference frames by 2 x 4 sample frames fill AVX2's
// 16 registers; 12 by 2 x 8 use 24 of AVX-512's 32 (512-bit vectors).
#pragma GCC push_options
#pragma GCC target("avx2,fma")
namespace avx2 {
using Vector = __m256d;
constexpr int kWidth = 4;
constexpr int kRows = 6;
constexpr int kVectors = 2;
inline Vector zero() { return _mm256_setzero_pd(); }
inline Vector broadcast(const double* p) { return _mm256_broadcast_sd(p); }
inline Vector load(const double* p) { return _mm256_loadu_pd(p); }
inline Vector multiplyAdd(Vector a, Vector b, Vector c) { return _mm256_fmadd_pd(a, b, c); }

// Distances of reference frame p to sample frames q .. q + 3 (from their dot products),
// written to their diagonals o = q - p; lanes whose diagonal falls outside 0 .. width - 1 are
// dropped.
inline void storeDistances(const BandTile& tile, std::size_t p, std::size_t q, Vector dots)
{
    const __m256d sum = _mm256_add_pd(_mm256_set1_pd(tile.aNorms[p]), _mm256_loadu_pd(tile.bNorms + q));
    const __m256d value = _mm256_max_pd(_mm256_fnmadd_pd(_mm256_set1_pd(2.0), dots, sum), _mm256_setzero_pd());
    const auto o = std::ptrdiff_t(q) - std::ptrdiff_t(p);
    double* row = tile.e + p * tile.eStride;
    if (o >= 0 && o + 4 <= std::ptrdiff_t(tile.width)) {
        _mm256_storeu_pd(row + o, value);
        return;
    }
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, value);
    for (std::ptrdiff_t k = 0; k < 4; ++k)
        if (o + k >= 0 && o + k < std::ptrdiff_t(tile.width)) row[o + k] = lanes[k];
}
#include "analysis/normalise/band_distances_simd.inc"
} // namespace avx2
#pragma GCC pop_options

#ifndef BUNRAKU_NO_AVX512
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq,avx512bw,avx2,fma")
namespace avx512 {
using Vector = __m512d;
constexpr int kWidth = 8;
constexpr int kRows = 12;
constexpr int kVectors = 2;
inline Vector zero() { return _mm512_setzero_pd(); }
inline Vector broadcast(const double* p) { return _mm512_set1_pd(*p); }
inline Vector load(const double* p) { return _mm512_loadu_pd(p); }
inline Vector multiplyAdd(Vector a, Vector b, Vector c) { return _mm512_fmadd_pd(a, b, c); }

inline void storeDistances(const BandTile& tile, std::size_t p, std::size_t q, Vector dots)
{
    const __m512d sum = _mm512_add_pd(_mm512_set1_pd(tile.aNorms[p]), _mm512_loadu_pd(tile.bNorms + q));
    // (maskz forms: GCC 12 warns about the undefined source operand of the unmasked ones)
    const __m512d value = _mm512_maskz_max_pd(0xff, _mm512_fnmadd_pd(_mm512_set1_pd(2.0), dots, sum), _mm512_setzero_pd());
    const auto o = std::ptrdiff_t(q) - std::ptrdiff_t(p);
    double* row = tile.e + p * tile.eStride;
    if (o >= 0 && o + 8 <= std::ptrdiff_t(tile.width)) {
        _mm512_storeu_pd(row + o, value);
        return;
    }
    alignas(64) double lanes[8];
    _mm512_store_pd(lanes, value);
    for (std::ptrdiff_t k = 0; k < 8; ++k)
        if (o + k >= 0 && o + k < std::ptrdiff_t(tile.width)) row[o + k] = lanes[k];
}
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

BandKernel currentBandKernel()
{
#ifdef BUNRAKU_BAND_SIMD
#ifndef BUNRAKU_NO_AVX512
    if (simdLevel() >= SimdLevel::Avx512) return BandKernel::Avx512;
#endif
    if (simdLevel() >= SimdLevel::Avx2) return BandKernel::Avx2;
#endif
    return BandKernel::Plain;
}

void bandDistances(const BandTile& tile) { bandDistancesWith(currentBandKernel(), tile); }

const char* bandKernelName(BandKernel kernel)
{
    switch (kernel) {
    case BandKernel::Avx512: return "avx512";
    case BandKernel::Avx2: return "avx2";
    default: return "plain";
    }
}

} // namespace bunraku::analysis::detail
