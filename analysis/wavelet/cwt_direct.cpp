#include "analysis/wavelet/cwt_direct.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) // GCC target pragmas (clang: plain kernels)
#define BUNRAKU_CWT_SIMD 1
#include <immintrin.h>
#endif

namespace bunraku::analysis::detail {

namespace {

void convolveLanesPlain(const LaneConvolution& job)
{
    for (std::size_t t = 0; t < job.count; ++t) {
        double sum[kLanes] = {};
        const double* row = job.x + t * kLanes;
        for (std::size_t j = 0; j < job.taps; ++j, row += kLanes) {
            const double weight = job.weights[j];
            for (std::size_t l = 0; l < kLanes; ++l) sum[l] += weight * row[l];
        }
        for (std::size_t l = 0; l < kLanes; ++l) job.out[t * kLanes + l] = job.factor * sum[l];
    }
}

void storeLanesPlain(const double* rows, std::size_t count, double* const* targets, const std::size_t* valid)
{
    for (std::size_t l = 0; l < kLanes; ++l) {
        if (!targets[l]) continue;
        for (std::size_t r = 0; r < std::min(count, valid[l]); ++r) targets[l][r] = rows[r * kLanes + l];
    }
}

} // namespace

#ifdef BUNRAKU_CWT_SIMD
#pragma GCC push_options
#pragma GCC target("avx2,fma")
namespace avx2 {
using Vector = __m256d;
constexpr int kWidth = 4;
constexpr int kRows = 6; // 12 accumulators of AVX2's 16 registers
inline Vector zero() { return _mm256_setzero_pd(); }
inline Vector broadcast(const double* p) { return _mm256_broadcast_sd(p); }
inline Vector load(const double* p) { return _mm256_load_pd(p); }
inline void store(double* p, Vector v) { _mm256_store_pd(p, v); }
inline Vector multiplyAdd(Vector a, Vector b, Vector c) { return _mm256_fmadd_pd(a, b, c); }
inline Vector scale(double factor, Vector v) { return _mm256_mul_pd(_mm256_set1_pd(factor), v); }
#include "analysis/wavelet/cwt_direct_simd.inc"
} // namespace avx2
#pragma GCC pop_options

#ifndef BUNRAKU_NO_AVX512
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq,avx512bw,avx2,fma")
namespace avx512 {
using Vector = __m512d;
constexpr int kWidth = 8;
constexpr int kRows = 12; // 12 of AVX-512's 32 registers: enough chains to hide the latency
inline Vector zero() { return _mm512_setzero_pd(); }
inline Vector broadcast(const double* p) { return _mm512_set1_pd(*p); }
inline Vector load(const double* p) { return _mm512_load_pd(p); }
inline void store(double* p, Vector v) { _mm512_store_pd(p, v); }
inline Vector multiplyAdd(Vector a, Vector b, Vector c) { return _mm512_fmadd_pd(a, b, c); }
inline Vector scale(double factor, Vector v) { return _mm512_mul_pd(_mm512_set1_pd(factor), v); }
#include "analysis/wavelet/cwt_direct_simd.inc"
} // namespace avx512
#pragma GCC pop_options
#endif
#endif

void convolveLanes(const LaneConvolution& job, SimdLevel level)
{
#ifdef BUNRAKU_CWT_SIMD
#ifndef BUNRAKU_NO_AVX512
    if (level >= SimdLevel::Avx512) {
        avx512::convolveLanes(job);
        return;
    }
#endif
    if (level >= SimdLevel::Avx2) {
        avx2::convolveLanes(job);
        return;
    }
#endif
    (void)level;
    convolveLanesPlain(job);
}

void storeLanes(const double* rows, std::size_t count, double* const* targets, const std::size_t* valid, SimdLevel level)
{
#ifdef BUNRAKU_CWT_SIMD
    if (level >= SimdLevel::Avx2) {
        avx2::storeLanes(rows, count, targets, valid);
        return;
    }
#endif
    (void)level;
    storeLanesPlain(rows, count, targets, valid);
}

const char* directKernelName(SimdLevel level)
{
#ifdef BUNRAKU_CWT_SIMD
#ifndef BUNRAKU_NO_AVX512
    if (level >= SimdLevel::Avx512) return "avx512";
#endif
    if (level >= SimdLevel::Avx2) return "avx2";
#endif
    (void)level;
    return "plain";
}

namespace {

// 64-byte aligned doubles (whole cache lines: no vector load of the kernels straddles two).
class AlignedBuffer {
public:
    explicit AlignedBuffer(std::size_t count)
        : m_data(static_cast<double*>(std::aligned_alloc(64, (count * sizeof(double) + 63) / 64 * 64 + 64)))
    {
    }
    double* data() const { return m_data.get(); }

private:
    struct Free {
        void operator()(double* p) const { std::free(p); }
    };
    std::unique_ptr<double, Free> m_data;
};

// Output rows per kernel call: a multiple of every kernel's row block (6 and 12). The chunk's
// interleaved input (its rows plus the filters' reach) stays in the first-level cache.
constexpr std::size_t kChunk = 240;

struct ScaleSetup {
    const double* weights;
    std::size_t taps;
    Eigen::Index delay; // output row t reads interleaved rows t + delay ..
    double factor;
};

// Segments per channel: a long channel is cut into K segments that run side by side in the
// lanes (each reading its neighbours' frames as halo); K minimises the lane-rows computed plus
// the rows interleaved.
Eigen::Index segmentsPerChannel(Eigen::Index frames, Eigen::Index channels, Eigen::Index span, double tapsPerRow)
{
    Eigen::Index best = 1;
    double bestCost = 0.0;
    for (Eigen::Index k = 1; k <= Eigen::Index(kLanes); ++k) {
        const Eigen::Index length = (frames + k - 1) / k;
        const Eigen::Index groups = (channels * k + Eigen::Index(kLanes) - 1) / Eigen::Index(kLanes);
        const double cost = double(groups) * (double(length) * tapsPerRow + 4.0 * double(length + span));
        if (k == 1 || cost < bestCost) {
            best = k;
            bestCost = cost;
        }
    }
    return best;
}

} // namespace

Status directTransform(const double* input, Eigen::Index frames, Eigen::Index channels, const CwtFilterBank& bank,
                       const CoefficientLayout& layout, const RunControl& control, SimdLevel level)
{
    const auto scales = Eigen::Index(bank.kernels.size());
    std::vector<Eigen::VectorXd> reversed;
    std::vector<ScaleSetup> setup;
    // Frame t at scale s reads x[t - left_s .. t - left_s + M_s], left_s = M_s - offset_s - 1;
    // the interleaved rows start `pad` frames before frame 0.
    Eigen::Index pad = 0;
    for (const auto& kernel : bank.kernels) {
        const Eigen::Index m = kernel.size() - 1;
        pad = std::max(pad, m - centralOffset(m) - 1);
    }
    Eigen::Index span = 0;
    double tapsPerRow = 0.0;
    for (Eigen::Index s = 0; s < scales; ++s) {
        const Eigen::VectorXd& kernel = bank.kernels[std::size_t(s)];
        reversed.emplace_back(kernel.reverse());
        const Eigen::Index m = kernel.size() - 1;
        const Eigen::Index delay = pad - (m - centralOffset(m) - 1);
        setup.push_back({reversed.back().data(), std::size_t(kernel.size()), delay, -std::sqrt(bank.scales[std::size_t(s)])});
        span = std::max(span, delay + kernel.size());
        tapsPerRow += double(kernel.size());
    }
    const Eigen::Index segments = segmentsPerChannel(frames, channels, span, tapsPerRow);
    const Eigen::Index length = (frames + segments - 1) / segments; // output frames per lane
    const Eigen::Index lanes = channels * segments;
    const Eigen::Index groups = (lanes + Eigen::Index(kLanes) - 1) / Eigen::Index(kLanes);
    AlignedBuffer x((kChunk + std::size_t(span)) * kLanes);
    AlignedBuffer scratch(kChunk * kLanes);
    const Eigen::Index reportEvery = std::max<Eigen::Index>(Eigen::Index(kChunk), groups * length / 64);
    Eigen::Index done = 0;
    Eigen::Index reported = 0;
    for (Eigen::Index g = 0; g < groups; ++g) {
        for (Eigen::Index t0 = 0; t0 < length; t0 += Eigen::Index(kChunk)) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt cancelled");
            const Eigen::Index count = std::min<Eigen::Index>(Eigen::Index(kChunk), length - t0);
            // Row r of the chunk, lane l: channel c's frame k * length + t0 - pad + r (zero
            // outside the take).
            const Eigen::Index rows = count + span - 1;
            std::fill(x.data(), x.data() + rows * Eigen::Index(kLanes), 0.0);
            for (Eigen::Index l = 0; l < Eigen::Index(kLanes); ++l) {
                const Eigen::Index lane = g * Eigen::Index(kLanes) + l;
                if (lane >= lanes) break;
                const double* series = input + (lane / segments) * frames;
                const Eigen::Index first = (lane % segments) * length + t0 - pad; // frame of row 0
                const Eigen::Index from = std::clamp<Eigen::Index>(-first, 0, rows);
                const Eigen::Index to = std::clamp<Eigen::Index>(frames - first, from, rows);
                double* target = x.data() + l;
                for (Eigen::Index r = from; r < to; ++r) target[r * Eigen::Index(kLanes)] = series[first + r];
            }
            for (Eigen::Index s = 0; s < scales; ++s) {
                const ScaleSetup& one = setup[std::size_t(s)];
                convolveLanes({x.data() + one.delay * Eigen::Index(kLanes), one.weights, one.taps, one.factor,
                               std::size_t(count), scratch.data()},
                              level);
                double* targets[kLanes] = {};
                std::size_t valid[kLanes] = {};
                for (Eigen::Index l = 0; l < Eigen::Index(kLanes); ++l) {
                    const Eigen::Index lane = g * Eigen::Index(kLanes) + l;
                    const Eigen::Index frame = (lane % segments) * length + t0;
                    if (lane >= lanes || frame >= frames) continue;
                    targets[l] = layout.out + frame * layout.rowStride + (lane / segments) * layout.channelStride + s * layout.scaleStride;
                    valid[l] = std::size_t(std::min(count, frames - frame));
                }
                if (layout.rowStride == 1) {
                    storeLanes(scratch.data(), std::size_t(count), targets, valid, level);
                    continue;
                }
                for (std::size_t l = 0; l < kLanes; ++l)
                    for (std::size_t r = 0; targets[l] && r < valid[l]; ++r)
                        targets[l][Eigen::Index(r) * layout.rowStride] = scratch.data()[r * kLanes + l];
            }
            done += count;
            if (done - reported >= reportEvery) {
                reported = done;
                control.report(double(done) / double(groups * length));
            }
        }
    }
    control.report(1.0);
    return okStatus();
}

} // namespace bunraku::analysis::detail
