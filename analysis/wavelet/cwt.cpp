#include "analysis/wavelet/cwt.h"

#include "analysis/wavelet/cwt_direct.h"
#include "analysis/wavelet/fftw_support.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bunraku::analysis {

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

namespace {

// The FFT method: coefficient(t) = -sqrt(scale) (signal conv kernel)(t + offset + 1), overlap-save.
Status fftTransform(detail::BlockConvolver& convolver, const Eigen::VectorXd& signal, const CwtFilterBank& bank,
                    Eigen::Ref<Eigen::MatrixXd> out, const RunControl& control)
{
    std::vector<std::size_t> offsets;
    std::vector<double> factors;
    for (std::size_t s = 0; s < bank.scales.size(); ++s) {
        offsets.push_back(std::size_t(detail::centralOffset(bank.kernels[s].size() - 1) + 1));
        factors.push_back(-std::sqrt(bank.scales[s]));
    }
    if (!convolver.convolve(signal, offsets, factors, out, control.stop)) return makeError(ErrorCode::Cancelled, "cwt cancelled");
    control.report(1.0);
    return okStatus();
}

} // namespace

Result<CwtResult> cwt(const Eigen::VectorXd& signal, const CwtFilterBank& bank, const RunControl& control)
{
    const Eigen::Index n = signal.size();
    if (n == 0) return makeError(ErrorCode::InvalidArgument, "cwt: the signal is empty");
    if (!signal.allFinite()) return makeError(ErrorCode::InvalidArgument, "cwt: the signal contains NaN or infinity");

    CwtResult result;
    result.scales = bank.scales;
    result.coefficients.resize(n, Eigen::Index(bank.scales.size()));

    if (resolvedCwtMethod(n, bank) == CwtMethod::Fft) {
        detail::BlockConvolver convolver(bank.kernels);
        if (auto status = fftTransform(convolver, signal, bank, result.coefficients, control); !status) return status.error();
        return result;
    }
    const detail::CoefficientLayout layout{result.coefficients.data(), 1, 0, n};
    if (auto status = detail::directTransform(signal.data(), n, 1, bank, layout, control); !status) return status.error();
    return result;
}

namespace {

// cwtChannels into either layout: the FFT method a channel at a time, the direct one all
// channels together (cwt_direct.h).
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
        detail::BlockConvolver convolver(bank.kernels);
        Eigen::MatrixXd one(frames, scales);
        for (Eigen::Index c = 0; c < channels; ++c) {
            if (auto status = fftTransform(convolver, input.col(c), bank, one, RunControl{control.stop, {}}); !status) return status;
            out.middleCols(c * scales, scales) = one;
            control.report(double(c + 1) / double(channels));
        }
        return okStatus();
    }
    // Element (t, c * scales + s) lives at t * rowStride + c * channelStride + s * scaleStride.
    const Eigen::Index rowStride = Output::IsRowMajor ? channels * scales : 1;
    const Eigen::Index channelStride = Output::IsRowMajor ? scales : scales * frames;
    const Eigen::Index scaleStride = Output::IsRowMajor ? 1 : frames;
    return detail::directTransform(input.data(), frames, channels, bank, {out.data(), rowStride, channelStride, scaleStride},
                                   control);
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
