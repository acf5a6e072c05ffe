#pragma once
/// Internal: the per-frame squared distances of a matching band, the bulk of the optimal
/// path's work. Computed as |a|^2 + |b|^2 - 2 a.b with register-blocked dot products (one
/// multiply-add per feature and cell, each load of a feature serving several cells), in an
/// AVX-512VL or AVX2 version chosen at run time and a plain fallback that gives the same
/// values up to rounding.

#include <cstddef>
#include <vector>

namespace bunraku::analysis::detail {

/// One tile of band distances on feature series (a[f] and b[f] point at feature f's values,
/// one per frame):
/// e[p * eStride + o] = max(0, aNorms[p] + bNorms[p + o] - 2 sum_f a[f][p] b[f][p + o])
/// for p < count and o < width. aNorms[p] and bNorms[q] are the squared
/// norms of frame p of `a` and frame q of `b`. Every b[f] and `bNorms` must be readable for
/// count + width + kBandReadAhead entries.
struct BandTile {
    const double* const* a = nullptr;
    const double* aNorms = nullptr;
    const double* const* b = nullptr;
    const double* bNorms = nullptr;
    std::size_t features = 0;
    std::size_t count = 0;
    std::size_t width = 0;
    double* e = nullptr;
    std::size_t eStride = 0;
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

/// The kernel's name: "plain", "avx2" or "avx512vl".
const char* bandKernelName(BandKernel kernel);

} // namespace bunraku::analysis::detail
