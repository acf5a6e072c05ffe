#include "analysis/wavelet/cwt_reconstruction.h"

#include "analysis/wavelet/fftw_support.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

namespace bunraku::analysis {

namespace {

// C_psi = integral_0^inf |psi_hat(w)|^2 / w dw (thesis eq. 5.14, with the square the
// reconstruction needs), from the sampled wavelet's zero-padded spectrum. ln 2 for every
// orthogonal wavelet; cached per wavelet and precision.
double admissibilityConstant(const Wavelet& wavelet, int precision)
{
    static std::mutex mutex;
    static std::map<std::pair<std::string, int>, double> cache;
    const auto key = std::make_pair(wavelet.name, precision);
    {
        std::lock_guard lock(mutex);
        if (auto it = cache.find(key); it != cache.end()) return it->second;
    }
    const SampledWavelet sampled = waveletFunction(wavelet, precision);
    const double dx = sampled.x[1] - sampled.x[0];
    const std::size_t length = detail::fastFftLength(std::max<std::size_t>(std::size_t(1) << 17, 64 * std::size_t(sampled.psi.size())));
    const auto spectrum = detail::realSpectrum(sampled.psi, length);
    const double dw = 2.0 * std::numbers::pi / (double(length) * dx);
    double sum = 0.0;
    for (std::size_t k = 1; k < spectrum.size(); ++k) sum += std::norm(spectrum[k] * dx) / (double(k) * dw) * dw;
    std::lock_guard lock(mutex);
    cache[key] = sum;
    return sum;
}

// Each scale's share of the scale axis: cells between midpoints of the sorted scales, the end
// cells mirrored (1 for the integer scales 1..c).
std::vector<double> scaleWeights(const std::vector<double>& scales)
{
    const std::size_t count = scales.size();
    std::vector<double> weights(count, 1.0);
    if (count < 2) return weights;
    for (std::size_t i = 0; i < count; ++i) {
        const double left = i == 0 ? scales[1] - scales[0] : scales[i] - scales[i - 1];
        const double right = i + 1 == count ? scales[i] - scales[i - 1] : scales[i + 1] - scales[i];
        weights[i] = 0.5 * (left + right);
    }
    return weights;
}

/// Adds scale s's term of eq. 5.13 (before the division by C_psi) to `out`.
void addScaleTerm(const CwtFilterBank& bank, const CwtResult& coefficients, const std::vector<double>& scales,
                  const std::vector<double>& weights, std::size_t s, Eigen::Ref<Eigen::VectorXd> out)
{
    const Eigen::Index n = out.size();
    const Eigen::VectorXd& kernel = bank.kernels[s];
    const Eigen::Index m = kernel.size() - 1;
    const Eigen::Index offset = (m - 2) / 2;
    const Eigen::VectorXd reversed = kernel.reverse();
    const double factor = -std::sqrt(scales[s]) * weights[s] / (scales[s] * scales[s]);
    for (Eigen::Index t = 0; t < n; ++t) {
        const Eigen::Index start = t + offset + 1 - m;
        const Eigen::Index first = std::max<Eigen::Index>(0, -start);
        const Eigen::Index last = std::min<Eigen::Index>(m, n - 1 - start);
        if (last < first) continue;
        out.segment(start + first, last - first + 1) +=
            (factor * coefficients.coefficients(t, Eigen::Index(s))) * reversed.segment(first, last - first + 1);
    }
}

} // namespace

Result<Eigen::MatrixXd> cwtScaleContributions(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                                              const CwtOptions& options, const RunControl& control)
{
    if (!std::is_sorted(scales.begin(), scales.end()) || std::adjacent_find(scales.begin(), scales.end()) != scales.end())
        return makeError(ErrorCode::InvalidArgument, "cwt reconstruction: scales must be strictly increasing");
    auto bank = makeCwtFilterBank(scales, options);
    if (!bank) return bank.error();
    auto coefficients = cwt(signal, *bank, control);
    if (!coefficients) return coefficients.error();
    const std::vector<double> weights = scaleWeights(scales);
    Eigen::MatrixXd contributions = Eigen::MatrixXd::Zero(signal.size(), Eigen::Index(scales.size()));
    for (std::size_t s = 0; s < scales.size(); ++s) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt reconstruction cancelled");
        addScaleTerm(*bank, *coefficients, scales, weights, s, contributions.col(Eigen::Index(s)));
    }
    contributions /= admissibilityConstant(options.wavelet, options.precision);
    return contributions;
}

Result<Eigen::VectorXd> cwtReconstruction(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                                          const CwtOptions& options, const RunControl& control)
{
    if (!std::is_sorted(scales.begin(), scales.end()) || std::adjacent_find(scales.begin(), scales.end()) != scales.end())
        return makeError(ErrorCode::InvalidArgument, "cwt reconstruction: scales must be strictly increasing");
    auto bank = makeCwtFilterBank(scales, options);
    if (!bank) return bank.error();
    auto coefficients = cwt(signal, *bank, control);
    if (!coefficients) return coefficients.error();

    // x_rec = (1 / C) sum_c w_c / c^2 H_c^T H_c x: eq. 5.13 with the synthesis kernel
    // c^(-1/2) psi((t - s) / c), the transpose of the analysis filter.
    const Eigen::Index n = signal.size();
    const std::vector<double> weights = scaleWeights(scales);
    Eigen::VectorXd reconstruction = Eigen::VectorXd::Zero(n);
    for (std::size_t s = 0; s < scales.size(); ++s) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "cwt reconstruction cancelled");
        addScaleTerm(*bank, *coefficients, scales, weights, s, reconstruction);
    }
    reconstruction /= admissibilityConstant(options.wavelet, options.precision);
    return reconstruction;
}

Result<Eigen::VectorXd> cwtApproximation(const Eigen::VectorXd& signal, const std::vector<double>& scales,
                                         const CwtOptions& options, const RunControl& control)
{
    auto reconstruction = cwtReconstruction(signal, scales, options, control);
    if (!reconstruction) return reconstruction.error();
    return Eigen::VectorXd(signal - *reconstruction);
}

} // namespace bunraku::analysis
