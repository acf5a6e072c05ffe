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

inline void windowStartBody(const double* const* rows, std::size_t length, std::size_t columns, double* __restrict running)
{
    const double* __restrict first = rows[0];
    for (std::size_t o = 0; o < columns; ++o) running[o] = first[o];
    for (std::size_t s = 1; s < length; ++s) {
        const double* __restrict row = rows[s];
        for (std::size_t o = 0; o < columns; ++o) running[o] += row[o];
    }
}

inline void windowSlideBody(double* __restrict running, const double* __restrict entering, const double* __restrict leaving,
                            std::size_t columns)
{
    for (std::size_t o = 0; o < columns; ++o) running[o] = (running[o] + entering[o]) - leaving[o];
}

// The costs of a row in column order (slid first when asked), 4 S entries.
void slideIfAsked(const DpCost& cost, std::size_t segment)
{
    if (cost.entering) windowSlideBody(cost.running, cost.entering, cost.leaving, 4 * segment);
}

// Quarter prefix minima of an interleaved row and the drops of its prefix minimum, plain.
void dropBitsPlain(const double* segmentPrefix, std::size_t segment, std::uint64_t* bits)
{
    std::fill(bits, bits + dpWords(segment), std::uint64_t(0));
    double before = kInfinity; // P(c - 1)
    for (std::size_t c = 0; c < 4 * segment; ++c) {
        const double prefix = std::min(before, segmentPrefix[dpEntry(c, segment)]);
        const std::size_t entry = dpEntry(c, segment);
        bits[entry >> 6] |= std::uint64_t(prefix < before) << (entry & 63);
        before = prefix;
    }
}

void dpRowPlain(const double* segmentPrefix, const DpCost& cost, std::size_t width, std::size_t low, std::size_t high,
                std::uint64_t* bits, double* d, double* nextSegmentPrefix)
{
    const std::size_t segment = dpSegment(width);
    slideIfAsked(cost, segment);
    dropBitsPlain(segmentPrefix, segment, bits);
    // P(c + 1) for c = 0 .. 4 S - 1 (the last padding column reads itself).
    double prefix = kInfinity;
    double next = std::min(prefix, segmentPrefix[dpEntry(0, segment)]);
    double run = kInfinity;
    for (std::size_t c = 0; c < 4 * segment; ++c) {
        prefix = next;
        if (c + 1 < 4 * segment) next = std::min(prefix, segmentPrefix[dpEntry(c + 1, segment)]);
        const double value = c < low || c > high ? kInfinity : cost.running[c] + next;
        if (c % segment == 0) run = kInfinity;
        run = std::min(run, value);
        if (d) d[dpEntry(c, segment)] = value;
        nextSegmentPrefix[dpEntry(c, segment)] = run;
    }
}

#ifdef BUNRAKU_AVX2_KERNEL
__attribute__((target("avx2,fma"))) void windowStartAvx2(const double* const* rows, std::size_t length, std::size_t columns,
                                                           double* running)
{
    windowStartBody(rows, length, columns, running);
}

__attribute__((target("avx2,fma"))) void windowSlideAvx2(double* running, const double* entering, const double* leaving,
                                                           std::size_t columns)
{
    windowSlideBody(running, entering, leaving, columns);
}

// The minimum of the quarters before each lane's: (inf, m0, min(m0, m1), min(m0, m1, m2)) for
// quarter minima m - the prefix minimum just before each quarter's first column.
__attribute__((target("avx2,fma"))) __m256d quarterCarry(__m256d minima)
{
    const __m256d infinity = _mm256_set1_pd(kInfinity);
    // Lanes moved up one (inf, m0, m1, m2), then min with itself moved up one and two lanes
    // (lane 0 is infinity, so moving it in needs no blend).
    const __m256d shifted = _mm256_blend_pd(_mm256_permute4x64_pd(minima, 0x90), infinity, 0x1);
    const __m256d pairs = _mm256_min_pd(shifted, _mm256_permute4x64_pd(shifted, 0x90));
    return _mm256_min_pd(pairs, _mm256_permute4x64_pd(pairs, 0x40));
}

// Columns L S + k0 .. + 3 of the four quarters (natural order) as four interleaved vectors:
// out[i] holds column L S + k0 + i in lane L. Slid first when the costs are window sums.
template <bool kSlide>
__attribute__((target("avx2,fma"))) inline void loadCosts(double* __restrict running, const double* __restrict entering,
                                                            const double* __restrict leaving, std::size_t segment, std::size_t k0,
                                                            __m256d* out)
{
    __m256d quarter[4];
    for (std::size_t l = 0; l < 4; ++l) {
        const std::size_t c = l * segment + k0;
        quarter[l] = _mm256_loadu_pd(running + c);
        if constexpr (kSlide) {
            quarter[l] = _mm256_sub_pd(_mm256_add_pd(quarter[l], _mm256_loadu_pd(entering + c)), _mm256_loadu_pd(leaving + c));
            _mm256_storeu_pd(running + c, quarter[l]);
        }
    }
    const __m256d low01 = _mm256_unpacklo_pd(quarter[0], quarter[1]);
    const __m256d high01 = _mm256_unpackhi_pd(quarter[0], quarter[1]);
    const __m256d low23 = _mm256_unpacklo_pd(quarter[2], quarter[3]);
    const __m256d high23 = _mm256_unpackhi_pd(quarter[2], quarter[3]);
    out[0] = _mm256_permute2f128_pd(low01, low23, 0x20);
    out[1] = _mm256_permute2f128_pd(high01, high23, 0x20);
    out[2] = _mm256_permute2f128_pd(low01, low23, 0x31);
    out[3] = _mm256_permute2f128_pd(high01, high23, 0x31);
}

// The drops of four steps' prefix minima (each against the step before), four bits a step.
__attribute__((target("avx2,fma"))) inline std::uint64_t drops(__m256d now, __m256d then)
{
    return std::uint64_t(unsigned(_mm256_movemask_pd(_mm256_cmp_pd(now, then, _CMP_LT_OQ))));
}

__attribute__((target("avx2,fma"))) inline std::uint64_t dropNibbles(__m256d before, const __m256d* prefix)
{
    return drops(prefix[0], before) | drops(prefix[1], prefix[0]) << 4 | drops(prefix[2], prefix[1]) << 8
           | drops(prefix[3], prefix[2]) << 12;
}

// D at step k (cost plus P one column on; infinity outside low .. high when masked) and the
// quarter prefix minima of D, stored at step k.
template <bool kMasked>
struct RowOutput {
    __m256d infinity, low, high;
    __m256d column; // of the next step stored
    __m256d run;
    double* d;
    double* segmentPrefix;
    __attribute__((target("avx2,fma"))) void store(std::size_t k, __m256d costs, __m256d next)
    {
        __m256d value = _mm256_add_pd(costs, next);
        if constexpr (kMasked) {
            const __m256d outside = _mm256_or_pd(_mm256_cmp_pd(column, low, _CMP_LT_OQ), _mm256_cmp_pd(column, high, _CMP_GT_OQ));
            value = _mm256_blendv_pd(value, infinity, outside);
            column = _mm256_add_pd(column, _mm256_set1_pd(1.0));
        }
        run = _mm256_min_pd(run, value);
        if (d) _mm256_storeu_pd(d + 4 * k, value);
        _mm256_storeu_pd(segmentPrefix + 4 * k, run);
    }
};

// One row, four quarters side by side: at step k, P at columns L S + k is the quarter prefix
// minimum with the carry of the quarters before; its drops against step k - 1 (or, at k = 0,
// against the carry, which is P just before the quarter) are four bits; D at step k - 1 is the
// cost plus P at step k (one column on), and the row's own quarter prefix minima follow D.
template <bool kSlide, bool kMasked>
__attribute__((target("avx2,fma"))) void dpRowAvx2(const double* segmentPrefix, const DpCost& cost, std::size_t width,
                                                     std::size_t low, std::size_t high, std::uint64_t* bits, double* d,
                                                     double* nextSegmentPrefix)
{
    const std::size_t segment = dpSegment(width);
    const __m256d infinity = _mm256_set1_pd(kInfinity);
    const __m256d carry = quarterCarry(_mm256_loadu_pd(segmentPrefix + 4 * (segment - 1)));
    RowOutput<kMasked> output{infinity, _mm256_set1_pd(double(low)), _mm256_set1_pd(double(high)),
                              _mm256_set_pd(double(3 * segment), double(2 * segment), double(segment), 0.0), infinity, d,
                              nextSegmentPrefix};
    __m256d before = carry;     // P at step k0 - 1
    __m256d pending = infinity; // the costs of step k0 - 1
    __m256d first = infinity;   // P at step 0
    std::uint64_t word = 0;
    double* running = cost.running;
    const double* entering = cost.entering;
    const double* leaving = cost.leaving;
    // Four steps at a time (S is a multiple of 4): 16 drop bits, 16 aligned in their word.
    for (std::size_t k0 = 0; k0 < segment; k0 += 4) {
        __m256d costs[4];
        loadCosts<kSlide>(running, entering, leaving, segment, k0, costs);
        __m256d prefix[4];
        for (std::size_t i = 0; i < 4; ++i) prefix[i] = _mm256_min_pd(_mm256_loadu_pd(segmentPrefix + 4 * (k0 + i)), carry);
        word |= dropNibbles(before, prefix) << ((4 * k0) & 63);
        if (((4 * k0) & 63) == 48) {
            bits[(4 * k0) >> 6] = word;
            word = 0;
        }
        if (k0 == 0)
            first = prefix[0];
        else
            output.store(k0 - 1, pending, prefix[0]);
        output.store(k0, costs[0], prefix[1]);
        output.store(k0 + 1, costs[1], prefix[2]);
        output.store(k0 + 2, costs[2], prefix[3]);
        pending = costs[3];
        before = prefix[3];
    }
    if (((4 * segment) & 63) != 0) bits[(4 * segment) >> 6] = word;
    // The last step reads P one column on: the next quarter's first column (lanes moved down
    // one); the last lane is padding and reads itself.
    output.store(segment - 1, pending, _mm256_blend_pd(_mm256_permute4x64_pd(first, 0xf9), before, 0x8));
}

__attribute__((target("avx2,fma"))) void dropBitsAvx2(const double* segmentPrefix, std::size_t segment, std::uint64_t* bits)
{
    const __m256d carry = quarterCarry(_mm256_loadu_pd(segmentPrefix + 4 * (segment - 1)));
    __m256d before = carry;
    std::uint64_t word = 0;
    for (std::size_t k0 = 0; k0 < segment; k0 += 4) {
        __m256d prefix[4];
        for (std::size_t i = 0; i < 4; ++i) prefix[i] = _mm256_min_pd(_mm256_loadu_pd(segmentPrefix + 4 * (k0 + i)), carry);
        word |= dropNibbles(before, prefix) << ((4 * k0) & 63);
        if (((4 * k0) & 63) == 48) {
            bits[(4 * k0) >> 6] = word;
            word = 0;
        }
        before = prefix[3];
    }
    if (((4 * segment) & 63) != 0) bits[(4 * segment) >> 6] = word;
}
#endif

bool avx2() { return simdLevel() >= SimdLevel::Avx2; }

} // namespace

const char* scanKernelName(SimdLevel level)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (level >= SimdLevel::Avx2) return "avx2";
#endif
    (void)level;
    return "plain";
}

void windowStart(const double* const* rows, std::size_t length, std::size_t columns, double* running)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (avx2()) {
        windowStartAvx2(rows, length, columns, running);
        return;
    }
#endif
    windowStartBody(rows, length, columns, running);
}

void windowSlide(double* running, const double* entering, const double* leaving, std::size_t columns)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (avx2()) {
        windowSlideAvx2(running, entering, leaving, columns);
        return;
    }
#endif
    windowSlideBody(running, entering, leaving, columns);
}

std::size_t dpSegment(std::size_t width) { return (width / 4 + 1 + 3) / 4 * 4; }

void dpFirstRow(const DpCost& cost, std::size_t width, std::size_t low, std::size_t high, double* d, double* segmentPrefix)
{
    const std::size_t segment = dpSegment(width);
    slideIfAsked(cost, segment);
    double run = kInfinity;
    for (std::size_t c = 0; c < 4 * segment; ++c) {
        const double value = c < low || c > high ? kInfinity : cost.running[c];
        if (c % segment == 0) run = kInfinity;
        run = std::min(run, value);
        d[dpEntry(c, segment)] = value;
        segmentPrefix[dpEntry(c, segment)] = run;
    }
}

void dpRow(const double* segmentPrefix, const DpCost& cost, std::size_t width, std::size_t low, std::size_t high,
           std::uint64_t* bits, double* d, double* nextSegmentPrefix)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (avx2()) {
        const bool masked = low > 0 || high + 1 < width;
        if (cost.entering)
            masked ? dpRowAvx2<true, true>(segmentPrefix, cost, width, low, high, bits, d, nextSegmentPrefix)
                   : dpRowAvx2<true, false>(segmentPrefix, cost, width, low, high, bits, d, nextSegmentPrefix);
        else
            masked ? dpRowAvx2<false, true>(segmentPrefix, cost, width, low, high, bits, d, nextSegmentPrefix)
                   : dpRowAvx2<false, false>(segmentPrefix, cost, width, low, high, bits, d, nextSegmentPrefix);
        return;
    }
#endif
    dpRowPlain(segmentPrefix, cost, width, low, high, bits, d, nextSegmentPrefix);
}

void dpDropBits(const double* segmentPrefix, std::size_t width, std::uint64_t* bits)
{
#ifdef BUNRAKU_AVX2_KERNEL
    if (avx2()) {
        dropBitsAvx2(segmentPrefix, dpSegment(width), bits);
        return;
    }
#endif
    dropBitsPlain(segmentPrefix, dpSegment(width), bits);
}

std::ptrdiff_t lastDropAtOrBelow(const std::uint64_t* bits, std::size_t column, std::size_t segment)
{
    // Lane l's bits sit at entries 4 k + l: search the column's quarter up to its step, then the
    // quarters before it whole.
    constexpr std::uint64_t kLaneBits = 0x1111111111111111ull;
    for (std::ptrdiff_t lane = std::ptrdiff_t(column / segment); lane >= 0; --lane) {
        const std::size_t step = std::size_t(lane) == column / segment ? column % segment : segment - 1;
        const std::size_t top = 4 * step + std::size_t(lane); // highest entry to look at
        for (std::ptrdiff_t word = std::ptrdiff_t(top >> 6); word >= 0; --word) {
            std::uint64_t mask = bits[word] & (kLaneBits << lane);
            if (std::size_t(word) == top >> 6 && (top & 63) != 63) mask &= (std::uint64_t(1) << ((top & 63) + 1)) - 1;
            if (mask != 0) {
                const std::size_t entry = std::size_t(word) * 64 + 63 - std::size_t(__builtin_clzll(mask));
                return std::ptrdiff_t(std::size_t(lane) * segment + entry / 4);
            }
        }
    }
    return -1;
}

} // namespace bunraku::analysis::detail
