#include "analysis/wavelet/fftw_support.h"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <mutex>

namespace bunraku::analysis::detail {

namespace {

std::mutex& plannerMutex()
{
    static std::mutex mutex;
    return mutex;
}

} // namespace

std::size_t fastFftLength(std::size_t n)
{
    for (std::size_t candidate = std::max<std::size_t>(n, 1);; ++candidate) {
        std::size_t rest = candidate;
        for (std::size_t prime : {2u, 3u, 5u, 7u}) {
            while (rest % prime == 0) rest /= prime;
        }
        if (rest == 1) return candidate;
    }
}

std::vector<std::complex<double>> realSpectrum(const Eigen::VectorXd& values, std::size_t n)
{
    double* in = fftw_alloc_real(n);
    fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
    fftw_plan plan;
    {
        std::lock_guard lock(plannerMutex());
        plan = fftw_plan_dft_r2c_1d(int(n), in, out, FFTW_ESTIMATE);
    }
    std::fill(in, in + n, 0.0);
    const std::size_t copied = std::min<std::size_t>(n, std::size_t(values.size()));
    std::copy(values.data(), values.data() + copied, in);
    fftw_execute(plan);
    std::vector<std::complex<double>> spectrum(n / 2 + 1);
    for (std::size_t k = 0; k < spectrum.size(); ++k) spectrum[k] = {out[k][0], out[k][1]};
    {
        std::lock_guard lock(plannerMutex());
        fftw_destroy_plan(plan);
    }
    fftw_free(in);
    fftw_free(out);
    return spectrum;
}

BlockConvolver::BlockConvolver(const std::vector<Eigen::VectorXd>& kernels)
{
    std::size_t longest = 1;
    for (const auto& kernel : kernels) longest = std::max(longest, std::size_t(kernel.size()));
    m_reach = longest - 1;
    // Blocks of at least 8 kernel lengths (so at most an eighth of each block is repeated) and
    // at least 2048 samples (so FFTW's per-transform overhead stays small).
    m_length = 2048;
    while (m_length < 8 * longest) m_length *= 2;
    const std::size_t bins = m_length / 2 + 1;
    m_real = fftw_alloc_real(m_length);
    m_block = fftw_alloc_real(m_length);
    m_spectrum = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(bins));
    m_product = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(bins));
    {
        std::lock_guard lock(plannerMutex());
        m_forward = fftw_plan_dft_r2c_1d(int(m_length), m_real, reinterpret_cast<fftw_complex*>(m_spectrum), FFTW_ESTIMATE);
        m_backward = fftw_plan_dft_c2r_1d(int(m_length), reinterpret_cast<fftw_complex*>(m_product), m_block, FFTW_ESTIMATE);
    }
    for (const auto& kernel : kernels) {
        std::fill(m_real, m_real + m_length, 0.0);
        std::copy(kernel.data(), kernel.data() + kernel.size(), m_real);
        fftw_execute(static_cast<fftw_plan>(m_forward));
        m_spectra.emplace_back(m_spectrum, m_spectrum + bins);
    }
}

BlockConvolver::~BlockConvolver()
{
    {
        std::lock_guard lock(plannerMutex());
        fftw_destroy_plan(static_cast<fftw_plan>(m_forward));
        fftw_destroy_plan(static_cast<fftw_plan>(m_backward));
    }
    fftw_free(m_real);
    fftw_free(m_block);
    fftw_free(m_spectrum);
    fftw_free(m_product);
}

bool BlockConvolver::convolve(const Eigen::VectorXd& signal, const std::vector<std::size_t>& offsets,
                              const std::vector<double>& factors, Eigen::Ref<Eigen::MatrixXd> out, const std::stop_token& stop)
{
    const auto n = std::ptrdiff_t(signal.size());
    const auto count = std::ptrdiff_t(out.rows());
    const std::size_t bins = m_length / 2 + 1;
    const auto useful = std::ptrdiff_t(m_length - m_reach); // full-convolution samples a block yields
    std::ptrdiff_t first = 0;
    std::ptrdiff_t last = 0; // full-convolution samples needed: first .. last - 1
    for (std::size_t k = 0; k < offsets.size(); ++k) {
        first = k == 0 ? std::ptrdiff_t(offsets[k]) : std::min(first, std::ptrdiff_t(offsets[k]));
        last = std::max(last, std::ptrdiff_t(offsets[k]) + count);
    }
    const double norm = 1.0 / double(m_length);
    for (std::ptrdiff_t begin = first / useful * useful; begin < last; begin += useful) {
        if (stop.stop_requested()) return false;
        // Block sample i is signal sample begin - reach + i; circular outputs reach .. length - 1
        // are the full convolution's samples begin .. begin + useful - 1.
        const std::ptrdiff_t start = begin - std::ptrdiff_t(m_reach);
        for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(m_length); ++i) {
            const std::ptrdiff_t at = start + i;
            m_real[i] = at >= 0 && at < n ? signal[at] : 0.0;
        }
        fftw_execute(static_cast<fftw_plan>(m_forward));
        for (std::size_t k = 0; k < m_spectra.size(); ++k) {
            const std::ptrdiff_t from = std::max(begin, std::ptrdiff_t(offsets[k]));
            const std::ptrdiff_t to = std::min(begin + useful, std::ptrdiff_t(offsets[k]) + count);
            if (from >= to) continue;
            const std::complex<double>* kernel = m_spectra[k].data();
            for (std::size_t b = 0; b < bins; ++b) m_product[b] = m_spectrum[b] * kernel[b];
            fftw_execute(static_cast<fftw_plan>(m_backward)); // c2r overwrites m_product
            const double scale = factors[k] * norm;
            for (std::ptrdiff_t j = from; j < to; ++j)
                out(j - std::ptrdiff_t(offsets[k]), std::ptrdiff_t(k)) = scale * m_block[j - start];
        }
    }
    return true;
}

} // namespace bunraku::analysis::detail
