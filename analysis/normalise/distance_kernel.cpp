#include "analysis/normalise/distance_kernel.h"

#include <algorithm>

#if defined(__GNUC__) && defined(__x86_64__)
#define BUNRAKU_AVX2_KERNEL 1
#include <immintrin.h>
#endif

namespace bunraku::analysis::detail {

namespace {

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

} // namespace bunraku::analysis::detail
