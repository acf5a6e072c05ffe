#include "analysis/wavelet/wavelet.h"

#include "analysis/wavelet/fftw_support.h"
#include "analysis/wavelet/wavelet_filters.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace bunraku::analysis {

namespace {

constexpr double kContinuousBound = 8.0; // pywt: mexh and morl live on [-8, 8]

// One cascade step (pywt upcoef, one level): insert zeros between samples, then convolve fully.
std::vector<double> upsampleAndConvolve(const std::vector<double>& values, const std::vector<double>& filter)
{
    const std::size_t upsampled = 2 * values.size() - 1;
    std::vector<double> out(upsampled + filter.size() - 1, 0.0);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double v = values[i];
        for (std::size_t k = 0; k < filter.size(); ++k) out[2 * i + k] += v * filter[k];
    }
    return out;
}

// numpy.linspace(lower, upper, count): x_i = i * step + lower, the last forced to upper.
Eigen::VectorXd linspaceLikeNumpy(double lower, double upper, Eigen::Index count)
{
    Eigen::VectorXd x(count);
    const double step = (upper - lower) / double(count - 1);
    for (Eigen::Index i = 0; i < count; ++i) x[i] = double(i) * step + lower;
    x[count - 1] = upper;
    return x;
}

} // namespace

Wavelet sym3Wavelet()
{
    Wavelet wavelet;
    wavelet.name = "sym3";
    wavelet.kind = WaveletKind::Orthogonal;
    for (const auto& filter : detail::orthogonalFilters()) {
        if (filter.name == "sym3") wavelet.reconstructionLowPass = filter.reconstructionLowPass;
    }
    wavelet.lowerBound = 0.0;
    wavelet.upperBound = double(wavelet.reconstructionLowPass.size() - 1);
    return wavelet;
}

std::vector<std::string> waveletNames()
{
    std::vector<std::string> names;
    for (const auto& filter : detail::orthogonalFilters()) names.push_back(filter.name);
    names.emplace_back("mexh");
    names.emplace_back("morl");
    return names;
}

Result<Wavelet> waveletByName(std::string_view name)
{
    for (const auto& filter : detail::orthogonalFilters()) {
        if (filter.name == name) {
            Wavelet wavelet;
            wavelet.name = filter.name;
            wavelet.kind = WaveletKind::Orthogonal;
            wavelet.reconstructionLowPass = filter.reconstructionLowPass;
            wavelet.lowerBound = 0.0;
            wavelet.upperBound = double(filter.reconstructionLowPass.size() - 1);
            return wavelet;
        }
    }
    if (name == "mexh" || name == "morl") {
        Wavelet wavelet;
        wavelet.name = std::string(name);
        wavelet.kind = WaveletKind::Continuous;
        wavelet.lowerBound = -kContinuousBound;
        wavelet.upperBound = kContinuousBound;
        return wavelet;
    }
    std::string known;
    for (const auto& n : waveletNames()) known += (known.empty() ? "" : ", ") + n;
    return makeError(ErrorCode::NotFound, "unknown wavelet '" + std::string(name) + "' (expected one of " + known + ")");
}

SampledWavelet waveletFunction(const Wavelet& wavelet, int precision)
{
    assert(precision >= 1 && precision <= 20);
    SampledWavelet sampled;
    if (wavelet.kind == WaveletKind::Continuous) {
        const Eigen::Index count = Eigen::Index(1) << precision;
        sampled.x = linspaceLikeNumpy(wavelet.lowerBound, wavelet.upperBound, count);
        sampled.psi.resize(count);
        for (Eigen::Index i = 0; i < count; ++i) {
            const double x = sampled.x[i];
            if (wavelet.name == "mexh") {
                // Mexican hat: second derivative of a Gaussian, unit energy.
                sampled.psi[i] = (1.0 - x * x) * std::exp(-x * x / 2.0) * 2.0
                                 / (std::sqrt(3.0) * std::sqrt(std::sqrt(std::numbers::pi)));
            } else {
                // Morlet (real): cos(5x) exp(-x^2 / 2).
                sampled.psi[i] = std::cos(5.0 * x) * std::exp(-x * x / 2.0);
            }
        }
        return sampled;
    }

    // Cascade algorithm (pywt upcoef('d', [sqrt(2)^P], w, P)): one step with rec_hi, then P - 1
    // steps with rec_lo; rec_hi[i] = (-1)^i rec_lo[L - 1 - i].
    const std::vector<double>& lowPass = wavelet.reconstructionLowPass;
    const std::size_t length = lowPass.size();
    std::vector<double> highPass(length);
    for (std::size_t i = 0; i < length; ++i) highPass[i] = (i % 2 == 0 ? 1.0 : -1.0) * lowPass[length - 1 - i];
    std::vector<double> values{std::pow(std::numbers::sqrt2, precision)};
    values = upsampleAndConvolve(values, highPass);
    for (int level = 1; level < precision; ++level) values = upsampleAndConvolve(values, lowPass);

    // pywt's layout: a leading zero, the cascade, zeros up to (L - 1) * 2^P + 1 samples (at least
    // two more than the cascade), on x_i = i / 2^P.
    const Eigen::Index scale = Eigen::Index(1) << precision;
    Eigen::Index count = Eigen::Index(length - 1) * scale + 1;
    const auto kept = Eigen::Index(values.size());
    if (count - kept - 2 < 0) count = kept + 2;
    sampled.psi = Eigen::VectorXd::Zero(count);
    for (Eigen::Index i = 0; i < kept; ++i) sampled.psi[i + 1] = values[std::size_t(i)];
    sampled.x = linspaceLikeNumpy(0.0, double(count - 1) / double(scale), count);
    return sampled;
}

SampledWavelet integratedWavelet(const Wavelet& wavelet, int precision)
{
    SampledWavelet sampled = waveletFunction(wavelet, precision);
    const double step = sampled.x[1] - sampled.x[0];
    double sum = 0.0;
    for (Eigen::Index i = 0; i < sampled.psi.size(); ++i) {
        sum += sampled.psi[i];
        sampled.psi[i] = sum * step;
    }
    return sampled;
}

double centreFrequency(const Wavelet& wavelet, int precision)
{
    const SampledWavelet sampled = waveletFunction(wavelet, precision);
    const Eigen::Index count = sampled.psi.size();
    const double domain = sampled.x[count - 1] - sampled.x[0];
    const std::vector<std::complex<double>> spectrum = detail::realSpectrum(sampled.psi, count);
    // The dominant non-zero bin (first maximum, as numpy.argmax over the mirrored spectrum).
    Eigen::Index best = 1;
    double bestMagnitude = -1.0;
    for (Eigen::Index k = 1; k < Eigen::Index(spectrum.size()); ++k) {
        const double magnitude = std::abs(spectrum[std::size_t(k)]);
        if (magnitude > bestMagnitude) {
            bestMagnitude = magnitude;
            best = k;
        }
    }
    return double(best) / domain;
}

double scaleToFrequency(const Wavelet& wavelet, double scale, double samplingPeriod, int precision)
{
    return centreFrequency(wavelet, precision) / (scale * samplingPeriod);
}

} // namespace bunraku::analysis
