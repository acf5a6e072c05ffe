#pragma once
/// Internal: the per-frame squared distances of a matching band, the bulk of the optimal
/// path's work. Computed as |a|^2 + |b|^2 - 2 a.b with register-blocked dot products (one
/// multiply-add per feature and cell, each load of a feature serving several cells), in an
/// AVX-512 or AVX2 version chosen at run time (simdLevel(), analysis/wavelet/simd_level.h) and a
/// plain fallback that gives the same values up to rounding (the SIMD versions fuse the
/// multiply-adds and agree with each other bit for bit).

#include <cstddef>
#include <vector>

namespace bunraku::analysis::detail {

/// One tile of band distances on feature series (feature f's values, one per frame, at
/// a + f * aStride and b + f * bStride; written a[f][p] and b[f][q] below):
/// e[p * eStride + o] = max(0, aNorms[p] + bNorms[p + o] - 2 sum_f a[f][p] b[f][p + o])
/// for p < count and o < width, except that entries whose sample frame p + o is below `from`
/// are set to 0 (the greedy scan never reads them). aNorms[p] and bNorms[q] are the squared
/// norms of frame p of `a` and frame q of `b`. Every b[f] and `bNorms` must be readable for
/// count + width + kBandReadAhead entries. Each entry is the same whatever the tile's shape:
/// its dot product runs over the features in order, one multiply-add each.
struct BandTile {
    const double* a = nullptr;
    std::size_t aStride = 0;
    const double* aNorms = nullptr;
    const double* b = nullptr;
    std::size_t bStride = 0;
    const double* bNorms = nullptr;
    std::size_t features = 0;
    std::size_t count = 0;
    std::size_t width = 0;
    double* e = nullptr;
    std::size_t eStride = 0;
    std::size_t from = 0;
};

/// How far past count + width the kernels may read `b` and `bNorms`.
inline constexpr std::size_t kBandReadAhead = 16;

void bandDistances(const BandTile& tile);

/// The kernels: bandDistances uses the best one the CPU runs.
enum class BandKernel { Plain, Avx2, Avx512 };

/// The kernels this CPU can run, best last (Plain always).
std::vector<BandKernel> availableBandKernels();

/// bandDistances with a given kernel (one of availableBandKernels()), for tests.
void bandDistancesWith(BandKernel kernel, const BandTile& tile);

/// The kernel's name: "plain", "avx2" or "avx512".
const char* bandKernelName(BandKernel kernel);

/// The kernel bandDistances runs at the current level (simdLevel()).
BandKernel currentBandKernel();

} // namespace bunraku::analysis::detail
