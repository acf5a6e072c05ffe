#include "analysis/wavelet/cwt.h"

#include "analysis/wavelet/fftw_support.h"

#include <algorithm>
#include <cmath>
#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif
#include <string>
#include <vector>

namespace bunraku::analysis {

namespace {

// Offset of the kept central part: pywt/MATLAB drop floor(d) samples of the differenced full
// convolution (length N + M - 2) at the start, d = (M - 2) / 2, M = filter length.
Eigen::Index centralOffset(Eigen::Index filterLength) { return (filterLength - 2) / 2; }

void directScale(const Eigen::VectorXd& signal, const Eigen::VectorXd& kernel, double scale,
                 Eigen::Ref<Eigen::VectorXd> out)
{
    const Eigen::Index n = signal.size();
    const Eigen::Index m = kernel.size() - 1; // filter length M
    const Eigen::Index offset = centralOffset(m);
    const Eigen::VectorXd reversed = kernel.reverse();
    const double factor = -std::sqrt(scale);
    for (Eigen::Index t = 0; t < n; ++t) {
        // y[k] = sum_j reversed[j] * x[k - M + j], k = t + offset + 1; x is zero outside 0..N-1.
        const Eigen::Index start = t + offset + 1 - m;
        const Eigen::Index first = std::max<Eigen::Index>(0, -start);
        const Eigen::Index last = std::min<Eigen::Index>(m, n - 1 - start);
        double sum = 0.0;
        if (last >= first) sum = reversed.segment(first, last - first + 1).dot(signal.segment(start + first, last - first + 1));
        out[t] = factor * sum;
    }
}

// All channels at one scale: out(t, c * channelStride + column) = factor * sum_j reversed[j] x(k_t + j, c),
// x row-major frames x channels. Blocks of channels accumulate in registers; an AVX2/FMA version
// is chosen at run time when the CPU has it (the portable build targets baseline x86-64).
struct ScaleJob {
    const double* x;
    Eigen::Index frames;
    Eigen::Index channels;
    const double* reversed;
    Eigen::Index taps;
    Eigen::Index offset;
    double factor;
    double* out;
    Eigen::Index rowStride;
    Eigen::Index column;
    Eigen::Index channelStride;
    Eigen::Index begin = 0; ///< output frames begin..end-1 (the input is always all frames)
    Eigen::Index end = 0;
};

void directScaleChannelsPlain(const ScaleJob& job)
{
    const Eigen::Index m = job.taps - 1;
    const Eigen::Index channels = job.channels;
    for (Eigen::Index t = job.begin; t < job.end; ++t) {
        const Eigen::Index start = t + job.offset + 1 - m;
        const Eigen::Index first = std::max<Eigen::Index>(0, -start);
        const Eigen::Index last = std::min<Eigen::Index>(m, job.frames - 1 - start);
        double* target = job.out + t * job.rowStride + job.column;
        Eigen::Index c0 = 0;
        for (; c0 + 4 <= channels; c0 += 4) {
            double block[4] = {0, 0, 0, 0};
            for (Eigen::Index j = first; j <= last; ++j) {
                const double weight = job.reversed[j];
                const double* row = job.x + (start + j) * channels + c0;
                for (int k = 0; k < 4; ++k) block[k] += weight * row[k];
            }
            for (int k = 0; k < 4; ++k) target[(c0 + k) * job.channelStride] = job.factor * block[k];
        }
        for (Eigen::Index c = c0; c < channels; ++c) {
            double sum = 0.0;
            for (Eigen::Index j = first; j <= last; ++j) sum += job.reversed[j] * job.x[(start + j) * channels + c];
            target[c * job.channelStride] = job.factor * sum;
        }
    }
}

#if defined(__GNUC__) && defined(__x86_64__)
#define BUNRAKU_CWT_AVX2 1
// Four interior frames t..t+3 (all taps inside the signal) of every group of 8 channels at
// once: eight independent accumulator chains instead of two hide the FMA latency. Each output
// is summed in the same order as the one-frame loop below, so the results are identical.
__attribute__((target("avx2,fma"))) void fourFramesAvx2(const ScaleJob& job, Eigen::Index t, Eigen::Index start)
{
    const Eigen::Index m = job.taps - 1;
    const Eigen::Index channels = job.channels;
    alignas(32) double block[8];
    for (Eigen::Index c0 = 0; c0 + 8 <= channels; c0 += 8) {
        __m256d s[4][2];
        for (auto& frame : s) frame[0] = frame[1] = _mm256_setzero_pd();
        const double* row = job.x + start * channels + c0;
        for (Eigen::Index j = 0; j <= m; ++j, row += channels) {
            const __m256d weight = _mm256_broadcast_sd(job.reversed + j);
            for (int r = 0; r < 4; ++r) {
                s[r][0] = _mm256_fmadd_pd(weight, _mm256_loadu_pd(row + r * channels), s[r][0]);
                s[r][1] = _mm256_fmadd_pd(weight, _mm256_loadu_pd(row + r * channels + 4), s[r][1]);
            }
        }
        for (int r = 0; r < 4; ++r) {
            _mm256_store_pd(block, s[r][0]);
            _mm256_store_pd(block + 4, s[r][1]);
            double* target = job.out + (t + r) * job.rowStride + job.column;
            for (int k = 0; k < 8; ++k) target[(c0 + k) * job.channelStride] = job.factor * block[k];
        }
    }
}

__attribute__((target("avx2,fma"))) void directScaleChannelsAvx2(const ScaleJob& job)
{
    const Eigen::Index m = job.taps - 1;
    const Eigen::Index channels = job.channels;
    Eigen::Index blockedUntil = job.begin; // frames below it have their groups of 8 channels done
    for (Eigen::Index t = job.begin; t < job.end; ++t) {
        const Eigen::Index start = t + job.offset + 1 - m;
        const Eigen::Index first = std::max<Eigen::Index>(0, -start);
        const Eigen::Index last = std::min<Eigen::Index>(m, job.frames - 1 - start);
        double* target = job.out + t * job.rowStride + job.column;
        if (t >= blockedUntil && channels >= 8 && start >= 0 && t + 3 < job.end && start + 3 + m <= job.frames - 1) {
            fourFramesAvx2(job, t, start);
            blockedUntil = t + 4;
        }
        Eigen::Index c0 = t < blockedUntil ? channels / 8 * 8 : 0;
        alignas(32) double block[8];
        for (; c0 + 8 <= channels; c0 += 8) {
            __m256d s0 = _mm256_setzero_pd();
            __m256d s1 = _mm256_setzero_pd();
            const double* row = job.x + (start + first) * channels + c0;
            for (Eigen::Index j = first; j <= last; ++j, row += channels) {
                const __m256d weight = _mm256_broadcast_sd(job.reversed + j);
                s0 = _mm256_fmadd_pd(weight, _mm256_loadu_pd(row), s0);
                s1 = _mm256_fmadd_pd(weight, _mm256_loadu_pd(row + 4), s1);
            }
            _mm256_store_pd(block, s0);
            _mm256_store_pd(block + 4, s1);
            for (int k = 0; k < 8; ++k) target[(c0 + k) * job.channelStride] = job.factor * block[k];
        }
        for (; c0 + 4 <= channels; c0 += 4) {
            __m256d s0 = _mm256_setzero_pd();
            const double* row = job.x + (start + first) * channels + c0;
            for (Eigen::Index j = first; j <= last; ++j, row += channels)
                s0 = _mm256_fmadd_pd(_mm256_broadcast_sd(job.reversed + j), _mm256_loadu_pd(row), s0);
            _mm256_store_pd(block, s0);
            for (int k = 0; k < 4; ++k) target[(c0 + k) * job.channelStride] = job.factor * block[k];
        }
        for (Eigen::Index c = c0; c < channels; ++c) {
            double sum = 0.0;
            for (Eigen::Index j = first; j <= last; ++j) sum += job.reversed[j] * job.x[(start + j) * channels + c];
            target[c * job.channelStride] = job.factor * sum;
        }
    }
}
#endif

// One channel at one scale, column-major: out[t] = factor * sum_j reversed[j] x[t + offset + 1 - M + j]
// for begin <= t < end (x zero outside 0 .. frames - 1). Interior frames are vectorised
// across frames: each tap's weight multiplies 32 consecutive frames at once.
struct SeriesJob {
    const double* x;
    Eigen::Index frames;
    const double* reversed;
    Eigen::Index taps;
    Eigen::Index offset;
    double factor;
    double* out;
    Eigen::Index begin;
    Eigen::Index end;
};

void seriesFrame(const SeriesJob& job, Eigen::Index t)
{
    const Eigen::Index m = job.taps - 1;
    const Eigen::Index start = t + job.offset + 1 - m;
    const Eigen::Index first = std::max<Eigen::Index>(0, -start);
    const Eigen::Index last = std::min<Eigen::Index>(m, job.frames - 1 - start);
    double sum = 0.0;
    for (Eigen::Index j = first; j <= last; ++j) sum += job.reversed[j] * job.x[start + j];
    job.out[t] = job.factor * sum;
}

void directScaleSeriesPlain(const SeriesJob& job)
{
    for (Eigen::Index t = job.begin; t < job.end; ++t) seriesFrame(job, t);
}

#ifdef BUNRAKU_CWT_AVX2
__attribute__((target("avx2,fma"))) void directScaleSeriesAvx2(const SeriesJob& job)
{
    const Eigen::Index m = job.taps - 1;
    // Frame t reads x[t + shift .. t + shift + M]: inside the signal for firstInterior <= t <= lastInterior.
    const Eigen::Index shift = job.offset + 1 - m;
    const Eigen::Index firstInterior = std::max(job.begin, -shift);
    const Eigen::Index lastInterior = std::min(job.end - 1, job.frames - 1 - m - shift);
    Eigen::Index t = job.begin;
    for (; t < std::min(job.end, firstInterior); ++t) seriesFrame(job, t);
    const __m256d factor = _mm256_set1_pd(job.factor);
    constexpr int kVectors = 8;
    for (; t + 4 * kVectors - 1 <= lastInterior; t += 4 * kVectors) {
        __m256d sum[kVectors];
        for (auto& one : sum) one = _mm256_setzero_pd();
        const double* x = job.x + t + shift;
        for (Eigen::Index j = 0; j <= m; ++j, ++x) {
            const __m256d weight = _mm256_broadcast_sd(job.reversed + j);
            for (int v = 0; v < kVectors; ++v) sum[v] = _mm256_fmadd_pd(weight, _mm256_loadu_pd(x + 4 * v), sum[v]);
        }
        for (int v = 0; v < kVectors; ++v) _mm256_storeu_pd(job.out + t + 4 * v, _mm256_mul_pd(factor, sum[v]));
    }
    for (; t + 3 <= lastInterior; t += 4) {
        __m256d sum = _mm256_setzero_pd();
        const double* x = job.x + t + shift;
        for (Eigen::Index j = 0; j <= m; ++j, ++x) sum = _mm256_fmadd_pd(_mm256_broadcast_sd(job.reversed + j), _mm256_loadu_pd(x), sum);
        _mm256_storeu_pd(job.out + t, _mm256_mul_pd(factor, sum));
    }
    for (; t < job.end; ++t) seriesFrame(job, t);
}
#endif

void directScaleSeries(const SeriesJob& job)
{
#ifdef BUNRAKU_CWT_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) {
        directScaleSeriesAvx2(job);
        return;
    }
#endif
    directScaleSeriesPlain(job);
}

void directScaleChannels(const ScaleJob& job)
{
#ifdef BUNRAKU_CWT_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) {
        directScaleChannelsAvx2(job);
        return;
    }
#endif
    directScaleChannelsPlain(job);
}

} // namespace

CwtMethod resolvedCwtMethod(Eigen::Index samples, const CwtFilterBank& bank)
{
    if (bank.method != CwtMethod::Automatic) return bank.method;
    if (samples < 4096) return CwtMethod::Direct;
    Eigen::Index longest = 0;
    double directWork = 0.0;
    for (const auto& kernel : bank.kernels) {
        longest = std::max(longest, kernel.size());
        directWork += double(samples) * double(kernel.size());
    }
    const auto fftLength = double(detail::fastFftLength(std::size_t(samples + longest - 1)));
    const double fftWork = 2.0 * double(2 * bank.kernels.size() + 1) * fftLength * std::log2(fftLength);
    return directWork > fftWork ? CwtMethod::Fft : CwtMethod::Direct;
}

std::vector<double> integerScales(int maxScale)
{
    std::vector<double> scales;
    for (int s = 1; s <= maxScale; ++s) scales.push_back(double(s));
    return scales;
}

Result<CwtFilterBank> makeCwtFilterBank(const std::vector<double>& scales, const CwtOptions& options)
{
    if (scales.empty()) return makeError(ErrorCode::InvalidArgument, "cwt: no scales given");
    if (options.precision < 1 || options.precision > 20)
        return makeError(ErrorCode::InvalidArgument, "cwt: precision must be in 1..20, got " + std::to_string(options.precision));
    const SampledWavelet integrated = integratedWavelet(options.wavelet, options.precision);
    const Eigen::Index size = integrated.psi.size();
    const double step = integrated.x[1] - integrated.x[0];
    const double span = integrated.x[size - 1] - integrated.x[0];

    CwtFilterBank bank;
    bank.scales = scales;
    bank.method = options.method;
    for (double scale : scales) {
        if (!std::isfinite(scale) || scale <= 0.0)
            return makeError(ErrorCode::InvalidArgument, "cwt: scales must be finite and > 0, got " + std::to_string(scale));
        // k = 0 .. ceil(scale * span + 1) - 1 (numpy.arange), j = trunc(k / (scale * step)),
        // indices past the sampled wavelet dropped: the filter samples Psi at 1 / scale steps.
        const double stop = scale * span + 1.0;
        const auto count = Eigen::Index(std::ceil(stop));
        const double divisor = scale * step;
        std::vector<Eigen::Index> indices;
        indices.reserve(std::size_t(count));
        for (Eigen::Index k = 0; k < count; ++k) {
            const auto j = Eigen::Index(double(k) / divisor);
            if (j < size) indices.push_back(j);
        }
        const auto length = Eigen::Index(indices.size());
        if (length < 2)
            return makeError(ErrorCode::InvalidArgument,
                             "cwt: scale " + std::to_string(scale) + " is too small for wavelet " + options.wavelet.name
                                 + " (its filter has fewer than 2 samples)");
        Eigen::VectorXd filter(length);
        for (Eigen::Index i = 0; i < length; ++i) filter[i] = integrated.psi[indices[std::size_t(length - 1 - i)]];
        Eigen::VectorXd kernel(length + 1);
        kernel[0] = filter[0];
        for (Eigen::Index i = 1; i < length; ++i) kernel[i] = filter[i] - filter[i - 1];
        kernel[length] = -filter[length - 1];
        bank.filters.push_back(std::move(filter));
        bank.kernels.push_back(std::move(kernel));
    }
    return bank;
}

Result<CwtResult> cwt(const Eigen::VectorXd& signal, const CwtFilterBank& bank, const RunControl& control)
{
    const Eigen::Index n = signal.size();
    if (n == 0) return makeError(ErrorCode::InvalidArgument, "cwt: the signal is empty");
    if (!signal.allFinite()) return makeError(ErrorCode::InvalidArgument, "cwt: the signal contains NaN or infinity");

    CwtResult result;
    result.scales = bank.scales;
    result.coefficients.resize(n, Eigen::Index(bank.scales.size()));

    const bool useFft = resolvedCwtMethod(n, bank) == CwtMethod::Fft;
    if (useFft) {
        Eigen::Index longest = 0;
        for (const auto& kernel : bank.kernels) longest = std::max(longest, kernel.size());
        const std::size_t fftLength = detail::fastFftLength(std::size_t(n + longest - 1));
        detail::FftConvolver convolver(signal, fftLength);
        for (std::size_t s = 0; s < bank.scales.size(); ++s) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt cancelled");
            const Eigen::VectorXd& kernel = bank.kernels[s];
            const Eigen::Index offset = centralOffset(kernel.size() - 1) + 1;
            result.coefficients.col(Eigen::Index(s)) =
                -std::sqrt(bank.scales[s]) * convolver.convolve(kernel, std::size_t(offset), std::size_t(n));
            control.report(double(s + 1) / double(bank.scales.size()));
        }
        return result;
    }
    for (std::size_t s = 0; s < bank.scales.size(); ++s) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt cancelled");
        directScale(signal, bank.kernels[s], bank.scales[s], result.coefficients.col(Eigen::Index(s)));
        control.report(double(s + 1) / double(bank.scales.size()));
    }
    return result;
}

namespace {

// cwtChannels into either layout: vectorised across channels (a frame's coefficients together),
// or, for long takes into column-major output, across frames a channel's series at a time.
template <class Output>
Status transformChannels(const Eigen::MatrixXd& input, const CwtFilterBank& bank, Output& out, const RunControl& control)
{
    const Eigen::Index frames = input.rows();
    const Eigen::Index channels = input.cols();
    const auto scales = Eigen::Index(bank.scales.size());
    if (frames == 0 || channels == 0) return makeError(ErrorCode::InvalidArgument, "cwt: no samples or no channels");
    if (!input.allFinite()) return makeError(ErrorCode::InvalidArgument, "cwt: the signal contains NaN or infinity");
    out.resize(frames, channels * scales);
    if (resolvedCwtMethod(frames, bank) == CwtMethod::Fft) {
        for (Eigen::Index c = 0; c < channels; ++c) {
            auto one = cwt(input.col(c), bank, RunControl{control.stop, {}});
            if (!one) return one.error();
            out.middleCols(c * scales, scales) = one->coefficients;
            control.report(double(c + 1) / double(channels));
        }
        return okStatus();
    }
    std::vector<Eigen::VectorXd> reversed;
    for (const auto& kernel : bank.kernels) reversed.emplace_back(kernel.reverse());
    Eigen::Index longest = 0;
    for (const auto& kernel : reversed) longest = std::max(longest, kernel.size());
    if (!Output::IsRowMajor && frames >= 8 * longest) {
        // Long takes, column-major: each channel's series at each scale, vectorised across
        // frames (most frames have all their taps inside the signal).
        for (Eigen::Index c = 0; c < channels; ++c) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt cancelled");
            for (Eigen::Index s = 0; s < scales; ++s) {
                const Eigen::Index taps = reversed[std::size_t(s)].size();
                directScaleSeries({input.col(c).data(), frames, reversed[std::size_t(s)].data(), taps, centralOffset(taps - 1),
                                   -std::sqrt(bank.scales[std::size_t(s)]), out.data() + (c * scales + s) * frames, 0, frames});
            }
            control.report(double(c + 1) / double(channels));
        }
        return okStatus();
    }
    // Otherwise vectorised across channels. Element (t, c * scales + s) lives at
    // t * rowStride + c * channelStride + s * scaleStride.
    const Eigen::Index rowStride = Output::IsRowMajor ? channels * scales : 1;
    const Eigen::Index channelStride = Output::IsRowMajor ? scales : scales * frames;
    const Eigen::Index scaleStride = Output::IsRowMajor ? 1 : frames;
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = input;
    // Blocks of frames, every scale per block: the block's outputs stay in cache while the
    // scales fill them in, instead of the whole output streaming through memory once per
    // scale. Each coefficient is computed as before.
    constexpr Eigen::Index kBlock = 256;
    for (Eigen::Index begin = 0; begin < frames; begin += kBlock) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt cancelled");
        for (Eigen::Index s = 0; s < scales; ++s) {
            const Eigen::Index taps = reversed[std::size_t(s)].size();
            ScaleJob job{rows.data(), frames, channels, reversed[std::size_t(s)].data(), taps, centralOffset(taps - 1),
                         -std::sqrt(bank.scales[std::size_t(s)]), out.data(), rowStride, s * scaleStride, channelStride};
            job.begin = begin;
            job.end = std::min(frames, begin + kBlock);
            directScaleChannels(job);
        }
        control.report(double(std::min(frames, begin + kBlock)) / double(frames));
    }
    return okStatus();
}

} // namespace

Result<CoefficientRows> cwtChannels(const Eigen::MatrixXd& input, const CwtFilterBank& bank, const RunControl& control)
{
    CoefficientRows out;
    if (auto status = transformChannels(input, bank, out, control); !status) return status.error();
    return out;
}

Result<Eigen::MatrixXd> cwtChannelSeries(const Eigen::MatrixXd& input, const CwtFilterBank& bank, const RunControl& control)
{
    Eigen::MatrixXd out;
    if (auto status = cwtChannelSeriesInto(input, bank, out, control); !status) return status.error();
    return out;
}

Status cwtChannelSeriesInto(const Eigen::MatrixXd& input, const CwtFilterBank& bank, Eigen::MatrixXd& out, const RunControl& control)
{
    return transformChannels(input, bank, out, control);
}

Result<CwtResult> cwt(const Eigen::VectorXd& signal, const std::vector<double>& scales, const CwtOptions& options,
                      const RunControl& control)
{
    auto bank = makeCwtFilterBank(scales, options);
    if (!bank) return bank.error();
    return cwt(signal, *bank, control);
}

int largestScale(const Wavelet& wavelet, Eigen::Index samples)
{
    const double span = wavelet.upperBound - wavelet.lowerBound;
    if (samples < 2 || span <= 0) return 0;
    return int(std::floor(double(samples - 1) / span + 1e-12));
}

} // namespace bunraku::analysis
