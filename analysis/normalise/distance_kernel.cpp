#include "analysis/normalise/distance_kernel.h"

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

void diagonalDistancesPlain(const double* a, std::size_t aStride, const double* b, std::size_t bStride,
                            std::size_t features, std::size_t count, double* e, std::size_t eStride)
{
    for (std::size_t p = 0; p < count; ++p) {
        double sum[kDiagonalBlock] = {};
        for (std::size_t f = 0; f < features; ++f) {
            const double x = a[f * aStride + p];
            const double* y = b + f * bStride + p;
            for (std::size_t k = 0; k < kDiagonalBlock; ++k) {
                const double d = x - y[k];
                sum[k] += d * d;
            }
        }
        for (std::size_t k = 0; k < kDiagonalBlock; ++k) e[p * eStride + k] = sum[k];
    }
}

inline void windowRowsBody(const double* __restrict e, std::size_t count, std::size_t length, std::size_t columns,
                           std::size_t stride, double* __restrict rows)
{
    for (std::size_t o = 0; o < columns; ++o) rows[o] = e[o];
    for (std::size_t s = 1; s < length; ++s)
        for (std::size_t o = 0; o < columns; ++o) rows[o] += e[s * stride + o];
    for (std::size_t p = 1; p < count; ++p) {
        const double* __restrict entering = e + (p + length - 1) * stride;
        const double* __restrict leaving = e + (p - 1) * stride;
        const double* __restrict before = rows + (p - 1) * stride;
        double* __restrict out = rows + p * stride;
        for (std::size_t o = 0; o < columns; ++o) out[o] = (before[o] + entering[o]) - leaving[o];
    }
}

void windowRowsPlain(const double* e, std::size_t count, std::size_t length, std::size_t columns, std::size_t stride,
                     double* rows)
{
    windowRowsBody(e, count, length, columns, stride, rows);
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

// r_q holds four frames of column q; stores them as four rows of the four columns.
__attribute__((target("avx2,fma"))) inline void storeTransposed(__m256d r0, __m256d r1, __m256d r2, __m256d r3,
                                                                  double* out, std::size_t stride)
{
    const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
    const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
    _mm256_storeu_pd(out, _mm256_permute2f128_pd(t0, t2, 0x20));
    _mm256_storeu_pd(out + stride, _mm256_permute2f128_pd(t1, t3, 0x20));
    _mm256_storeu_pd(out + 2 * stride, _mm256_permute2f128_pd(t0, t2, 0x31));
    _mm256_storeu_pd(out + 3 * stride, _mm256_permute2f128_pd(t1, t3, 0x31));
}

// Four reference frames (one register) against 8 diagonals: each load of `a` serves 8 cells,
// and no horizontal sums are needed (the cells are the lanes).
__attribute__((target("avx2,fma"))) void diagonalDistancesAvx2(const double* a, std::size_t aStride, const double* b,
                                                                 std::size_t bStride, std::size_t features,
                                                                 std::size_t count, double* e, std::size_t eStride)
{
    for (std::size_t p = 0; p < count; p += 4) {
        __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd(), s2 = _mm256_setzero_pd(), s3 = _mm256_setzero_pd();
        __m256d s4 = _mm256_setzero_pd(), s5 = _mm256_setzero_pd(), s6 = _mm256_setzero_pd(), s7 = _mm256_setzero_pd();
        const double* af = a + p;
        const double* bf = b + p;
        for (std::size_t f = 0; f < features; ++f, af += aStride, bf += bStride) {
            const __m256d x = _mm256_loadu_pd(af);
            __m256d d;
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 0)); s0 = _mm256_fmadd_pd(d, d, s0);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 1)); s1 = _mm256_fmadd_pd(d, d, s1);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 2)); s2 = _mm256_fmadd_pd(d, d, s2);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 3)); s3 = _mm256_fmadd_pd(d, d, s3);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 4)); s4 = _mm256_fmadd_pd(d, d, s4);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 5)); s5 = _mm256_fmadd_pd(d, d, s5);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 6)); s6 = _mm256_fmadd_pd(d, d, s6);
            d = _mm256_sub_pd(x, _mm256_loadu_pd(bf + 7)); s7 = _mm256_fmadd_pd(d, d, s7);
        }
        storeTransposed(s0, s1, s2, s3, e + p * eStride, eStride);
        storeTransposed(s4, s5, s6, s7, e + p * eStride + 4, eStride);
    }
}

__attribute__((target("avx2,fma"))) void windowRowsAvx2(const double* e, std::size_t count, std::size_t length,
                                                          std::size_t columns, std::size_t stride, double* rows)
{
    windowRowsBody(e, count, length, columns, stride, rows);
}

// Prefix minimum four columns at a time: an in-register scan (two shifted minima) and a
// carried minimum; the drop bits compare each prefix value with the one before it.
__attribute__((target("avx2,fma"))) void prefixAvx2(const double* values, std::size_t width, double* prefix,
                                                      std::uint64_t* bits)
{
    const __m256d infinity = _mm256_set1_pd(kInfinity);
    __m256d carry = infinity;
    std::size_t k = 0;
    for (; k + 4 <= width; k += 4) {
        const __m256d x = _mm256_loadu_pd(values + k);
        const __m256d y = _mm256_min_pd(x, _mm256_blend_pd(_mm256_permute4x64_pd(x, 0x90), infinity, 0x1));
        const __m256d z = _mm256_min_pd(y, _mm256_blend_pd(_mm256_permute4x64_pd(y, 0x40), infinity, 0x3));
        const __m256d p = _mm256_min_pd(z, carry);
        const __m256d before = _mm256_blend_pd(_mm256_permute4x64_pd(p, 0x90), carry, 0x1);
        const auto drops = std::uint64_t(_mm256_movemask_pd(_mm256_cmp_pd(p, before, _CMP_LT_OQ)));
        bits[k >> 6] |= drops << (k & 63);
        _mm256_storeu_pd(prefix + k, p);
        // The carried minimum depends on the previous carry through one min only (the block's
        // own minimum, z's last lane, is broadcast off the chain).
        carry = _mm256_min_pd(carry, _mm256_permute4x64_pd(z, 0xff));
    }
    prefixScalar(values, k, width, k > 0 ? prefix[k - 1] : kInfinity, prefix, bits);
}

// current[j] = cost[j] + prefix[j + 1] for j < width.
__attribute__((target("avx2,fma"))) void addShiftedAvx2(const double* cost, const double* prefix, std::size_t width,
                                                          double* current)
{
    std::size_t j = 0;
    for (; j + 4 <= width; j += 4)
        _mm256_storeu_pd(current + j, _mm256_add_pd(_mm256_loadu_pd(cost + j), _mm256_loadu_pd(prefix + j + 1)));
    for (; j < width; ++j) current[j] = cost[j] + prefix[j + 1];
}

bool cpuHasAvx2()
{
    static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return has;
}
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

void diagonalDistances(const double* a, std::size_t aStride, const double* b, std::size_t bStride,
                       std::size_t features, std::size_t count, double* e, std::size_t eStride)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        diagonalDistancesAvx2(a, aStride, b, bStride, features, count, e, eStride);
        return;
    }
#endif
    diagonalDistancesPlain(a, aStride, b, bStride, features, count, e, eStride);
}

void windowRows(const double* e, std::size_t count, std::size_t length, std::size_t columns, std::size_t stride,
                double* rows)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        windowRowsAvx2(e, count, length, columns, stride, rows);
        return;
    }
#endif
    windowRowsPlain(e, count, length, columns, stride, rows);
}

void prefixMinimumBits(const double* values, std::size_t width, double* prefix, std::uint64_t* bits)
{
    std::fill(bits, bits + (width + 63) / 64, std::uint64_t(0));
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        prefixAvx2(values, width, prefix, bits);
        return;
    }
#endif
    prefixPlain(values, width, prefix, bits);
}

void dynamicProgrammeRow(const double* previous, const double* cost, std::size_t width, std::size_t low,
                         std::size_t high, double* prefix, std::uint64_t* bits, double* current)
{
    prefixMinimumBits(previous, width, prefix, bits);
    prefix[width] = prefix[width - 1]; // column width - 1 reads the whole previous row
#ifdef BUNRAKU_AVX2_KERNEL
    if (cpuHasAvx2()) {
        addShiftedAvx2(cost, prefix, width, current);
    } else
#endif
    {
        for (std::size_t j = 0; j < width; ++j) current[j] = cost[j] + prefix[j + 1];
    }
    std::fill(current, current + low, kInfinity);
    std::fill(current + high + 1, current + width, kInfinity);
}

} // namespace bunraku::analysis::detail
