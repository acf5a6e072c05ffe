#include "analysis/normalise/distance_kernel.h"

#include "analysis/wavelet/simd_level.h"

#include <algorithm>
#include <limits>

#if defined(__GNUC__) && defined(__x86_64__)
#define BUNRAKU_AVX2_KERNEL 1
#include <immintrin.h>
#endif

namespace bunraku::analysis::detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void squaredDistancesPlain(const double* a, const double* const* rows, std::size_t count, std::size_t features, double* out)
{
    for (std::size_t j = 0; j < count; ++j) {
        const double* b = rows[j];
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
        std::size_t f = 0;
        for (; f + 4 <= features; f += 4) {
            const double d0 = a[f] - b[f], d1 = a[f + 1] - b[f + 1], d2 = a[f + 2] - b[f + 2], d3 = a[f + 3] - b[f + 3];
            s0 += d0 * d0;
            s1 += d1 * d1;
            s2 += d2 * d2;
            s3 += d3 * d3;
        }
        for (; f < features; ++f) {
            const double d = a[f] - b[f];
            s0 += d * d;
        }
        out[j] = (s0 + s1) + (s2 + s3);
    }
}

inline void windowStartBody(const double* __restrict e, std::size_t length, std::size_t columns, std::size_t stride,
                            double* __restrict running)
{
    for (std::size_t o = 0; o < columns; ++o) running[o] = e[o];
    for (std::size_t s = 1; s < length; ++s)
        for (std::size_t o = 0; o < columns; ++o) running[o] += e[s * stride + o];
}

inline void windowSlideBody(double* __restrict running, const double* __restrict entering, const double* __restrict leaving,
                            std::size_t columns)
{
    for (std::size_t o = 0; o < columns; ++o) running[o] = (running[o] + entering[o]) - leaving[o];
}

// The scan of the prefix minimum with its "drops here" bits, one column at a time.
void prefixScalar(const double* values, std::size_t from, std::size_t width, double run, double* prefix, std::uint64_t* bits)
{
    for (std::size_t k = from; k < width; ++k) {
        const bool drop = values[k] < run;
        run = drop ? values[k] : run;
        prefix[k] = run;
        bits[k >> 6] |= std::uint64_t(drop) << (k & 63);
    }
}

void prefixPlain(const double* values, std::size_t width, double* prefix, std::uint64_t* bits)
{
    prefixScalar(values, 0, width, kInfinity, prefix, bits);
}

#ifdef BUNRAKU_AVX2_KERNEL
__attribute__((target("avx2,fma"))) void squaredDistancesAvx2(const double* a, const double* const* rows,
                                                                std::size_t count, std::size_t features, double* out)
{
    for (std::size_t j = 0; j < count; ++j) {
        const double* b = rows[j];
        __m256d s0 = _mm256_setzero_pd();
        __m256d s1 = _mm256_setzero_pd();
        std::size_t f = 0;
        for (; f + 8 <= features; f += 8) {
            const __m256d d0 = _mm256_sub_pd(_mm256_loadu_pd(a + f), _mm256_loadu_pd(b + f));
            const __m256d d1 = _mm256_sub_pd(_mm256_loadu_pd(a + f + 4), _mm256_loadu_pd(b + f + 4));
            s0 = _mm256_fmadd_pd(d0, d0, s0);
            s1 = _mm256_fmadd_pd(d1, d1, s1);
        }
        for (; f + 4 <= features; f += 4) {
            const __m256d d0 = _mm256_sub_pd(_mm256_loadu_pd(a + f), _mm256_loadu_pd(b + f));
            s0 = _mm256_fmadd_pd(d0, d0, s0);
        }
        const __m256d s = _mm256_add_pd(s0, s1);
        const __m128d half = _mm_add_pd(_mm256_castpd256_pd128(s), _mm256_extractf128_pd(s, 1));
        double sum = _mm_cvtsd_f64(_mm_add_sd(half, _mm_unpackhi_pd(half, half)));
        for (; f < features; ++f) {
            const double d = a[f] - b[f];
            sum += d * d;
        }
        out[j] = sum;
    }
}

__attribute__((target("avx2,fma"))) double horizontalSum(__m256d s)
{
    const __m128d half = _mm_add_pd(_mm256_castpd256_pd128(s), _mm256_extractf128_pd(s, 1));
    return _mm_cvtsd_f64(_mm_add_sd(half, _mm_unpackhi_pd(half, half)));
}

// Dot products of `a` with four rows at a time, so each load of `a` serves four rows.
__attribute__((target("avx2,fma"))) void dotDistancesAvx2(const double* a, double aNorm, const double* first,
                                                            const double* norms, std::size_t count,
                                                            std::size_t features, double* out)
{
    const std::size_t vectorised = features - features % 4;
    std::size_t j = 0;
    for (; j + 4 <= count; j += 4) {
        const double* b0 = first + j * features;
        const double* b1 = b0 + features;
        const double* b2 = b1 + features;
        const double* b3 = b2 + features;
        __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd(), s2 = _mm256_setzero_pd(), s3 = _mm256_setzero_pd();
        for (std::size_t f = 0; f < vectorised; f += 4) {
            const __m256d va = _mm256_loadu_pd(a + f);
            s0 = _mm256_fmadd_pd(va, _mm256_loadu_pd(b0 + f), s0);
            s1 = _mm256_fmadd_pd(va, _mm256_loadu_pd(b1 + f), s1);
            s2 = _mm256_fmadd_pd(va, _mm256_loadu_pd(b2 + f), s2);
            s3 = _mm256_fmadd_pd(va, _mm256_loadu_pd(b3 + f), s3);
        }
        double dot[4] = {horizontalSum(s0), horizontalSum(s1), horizontalSum(s2), horizontalSum(s3)};
        for (std::size_t f = vectorised; f < features; ++f) {
            dot[0] += a[f] * b0[f];
            dot[1] += a[f] * b1[f];
            dot[2] += a[f] * b2[f];
            dot[3] += a[f] * b3[f];
        }
        for (std::size_t k = 0; k < 4; ++k) out[j + k] = std::max(0.0, aNorm + norms[j + k] - 2.0 * dot[k]);
    }
    for (; j < count; ++j) {
        const double* b = first + j * features;
        double dot = 0.0;
        for (std::size_t f = 0; f < features; ++f) dot += a[f] * b[f];
        out[j] = std::max(0.0, aNorm + norms[j] - 2.0 * dot);
    }
}

__attribute__((target("avx2,fma"))) void windowStartAvx2(const double* e, std::size_t length, std::size_t columns,
                                                           std::size_t stride, double* running)
{
    windowStartBody(e, length, columns, stride, running);
}

__attribute__((target("avx2,fma"))) void windowSlideAvx2(double* running, const double* entering, const double* leaving,
                                                           std::size_t columns)
{
    windowSlideBody(running, entering, leaving, columns);
}

// Prefix minimum four columns at a time: an in-register scan (an in-lane and a cross-lane
// shifted minimum) and a carried minimum. A drop at column c is prefix[c] < prefix[c - 1]: the
// prefix shifted by one column (prefix[k - 3 .. k], built one block behind the scan) gives the
// drop bits of columns k - 3 .. k and, with `cost`, current[j] = cost[j] + prefix[j + 1] for
// j = k - 4 .. k - 1. Lane-crossing shuffles are the bottleneck here: three per block.
// Returns how many leading entries of `current` are set (0 without `cost`).
__attribute__((target("avx2,fma"))) std::size_t prefixAvx2(const double* values, std::size_t width, double* prefix,
                                                              std::uint64_t* bits, const double* cost, double* current)
{
    if (width < 4) {
        prefixScalar(values, 0, width, kInfinity, prefix, bits);
        return 0;
    }
    const __m256d infinity = _mm256_set1_pd(kInfinity);
    __m256d carry = infinity;
    __m256d previousBlock = infinity;
    // The word of drop bits stays in a register until its 64 columns are done (or-ing into
    // memory each block would chain every block through a store and a load).
    std::uint64_t word = 0;
    std::size_t k = 0;
    for (; k + 4 <= width; k += 4) {
        const __m256d x = _mm256_loadu_pd(values + k);
        const __m256d y = _mm256_min_pd(x, _mm256_blend_pd(_mm256_permute_pd(x, 0x0), infinity, 0x5));
        const __m256d z = _mm256_min_pd(y, _mm256_blend_pd(_mm256_permute4x64_pd(y, 0x55), infinity, 0x3));
        const __m256d p = _mm256_min_pd(z, carry);
        _mm256_storeu_pd(prefix + k, p);
        if (k > 0) {
            const __m256d next = _mm256_shuffle_pd(previousBlock, _mm256_permute2f128_pd(previousBlock, p, 0x21), 0x5);
            const auto drops = std::uint64_t(_mm256_movemask_pd(_mm256_cmp_pd(next, previousBlock, _CMP_LT_OQ)));
            if ((k & 63) == 0) { // columns k - 3 .. k - 1 end the previous word, k starts this one
                bits[(k >> 6) - 1] = word | ((drops & 0x7) << 61);
                word = drops >> 3;
            } else {
                word |= drops << ((k - 3) & 63);
            }
            if (cost) _mm256_storeu_pd(current + k - 4, _mm256_add_pd(_mm256_loadu_pd(cost + k - 4), next));
        }
        previousBlock = p;
        // The carried minimum depends on the previous carry through one min only (the block's
        // own minimum, z's last lane, is broadcast off the chain).
        carry = _mm256_min_pd(carry, _mm256_permute4x64_pd(z, 0xff));
    }
    // Bits so far: columns 1 .. k - 4 (the last block's first column); then that block's other
    // three columns, column 0 and the columns after the last block.
    const std::size_t last = k - 4;
    bits[last >> 6] = word;
    for (std::size_t c = last + 1; c < k; ++c) bits[c >> 6] |= std::uint64_t(prefix[c] < prefix[c - 1]) << (c & 63);
    bits[0] |= std::uint64_t(prefix[0] < kInfinity);
    prefixScalar(values, k, width, prefix[k - 1], prefix, bits);
    return cost ? last : 0;
}

bool cpuHasAvx2() { return simdLevel() >= SimdLevel::Avx2; }
#endif

} // namespace

void squaredDistancesContiguous(const double* a, double aNorm, const double* first, const double* norms,
                                std::size_t count, std::size_t features, double* out)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        dotDistancesAvx2(a, aNorm, first, norms, count, features, out);
        return;
    }
#endif
    for (std::size_t j = 0; j < count; ++j) {
        const double* b = first + j * features;
        double d0 = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0;
        std::size_t f = 0;
        for (; f + 4 <= features; f += 4) {
            d0 += a[f] * b[f];
            d1 += a[f + 1] * b[f + 1];
            d2 += a[f + 2] * b[f + 2];
            d3 += a[f + 3] * b[f + 3];
        }
        for (; f < features; ++f) d0 += a[f] * b[f];
        out[j] = std::max(0.0, aNorm + norms[j] - 2.0 * ((d0 + d1) + (d2 + d3)));
    }
}

void squaredDistances(const double* a, const double* const* rows, std::size_t count, std::size_t features, double* out)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        squaredDistancesAvx2(a, rows, count, features, out);
        return;
    }
#endif
    squaredDistancesPlain(a, rows, count, features, out);
}

void windowStart(const double* e, std::size_t length, std::size_t columns, std::size_t stride, double* running)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        windowStartAvx2(e, length, columns, stride, running);
        return;
    }
#endif
    windowStartBody(e, length, columns, stride, running);
}

void windowSlide(double* running, const double* entering, const double* leaving, std::size_t columns)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        windowSlideAvx2(running, entering, leaving, columns);
        return;
    }
#endif
    windowSlideBody(running, entering, leaving, columns);
}

void prefixMinimumBits(const double* values, std::size_t width, double* prefix, std::uint64_t* bits)
{
    std::fill(bits, bits + (width + 63) / 64, std::uint64_t(0));
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        prefixAvx2(values, width, prefix, bits, nullptr, nullptr);
        return;
    }
#endif
    prefixPlain(values, width, prefix, bits);
}

void dynamicProgrammeRow(const double* previous, const double* cost, std::size_t width, std::size_t low,
                         std::size_t high, double* prefix, std::uint64_t* bits, double* current)
{
    std::fill(bits, bits + (width + 63) / 64, std::uint64_t(0));
    std::size_t done = 0;
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2())
        done = prefixAvx2(previous, width, prefix, bits, cost, current);
    else
#endif
        prefixPlain(previous, width, prefix, bits);
    prefix[width] = prefix[width - 1]; // column width - 1 reads the whole previous row
    for (std::size_t j = done; j < width; ++j) current[j] = cost[j] + prefix[j + 1];
    std::fill(current, current + low, kInfinity);
    std::fill(current + high + 1, current + width, kInfinity);
}

} // namespace bunraku::analysis::detail
