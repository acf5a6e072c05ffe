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

FftConvolver::FftConvolver(const Eigen::VectorXd& signal, std::size_t length)
    : m_length(length)
{
    m_real = fftw_alloc_real(length);
    m_spectrum = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(length / 2 + 1));
    auto* spectrum = reinterpret_cast<fftw_complex*>(m_spectrum);
    {
        std::lock_guard lock(plannerMutex());
        m_forward = fftw_plan_dft_r2c_1d(int(length), m_real, spectrum, FFTW_ESTIMATE);
        m_backward = fftw_plan_dft_c2r_1d(int(length), spectrum, m_real, FFTW_ESTIMATE);
    }
    std::fill(m_real, m_real + length, 0.0);
    std::copy(signal.data(), signal.data() + signal.size(), m_real);
    fftw_execute(static_cast<fftw_plan>(m_forward));
    m_signalSpectrum.assign(m_spectrum, m_spectrum + length / 2 + 1);
}

FftConvolver::~FftConvolver()
{
    {
        std::lock_guard lock(plannerMutex());
        fftw_destroy_plan(static_cast<fftw_plan>(m_forward));
        fftw_destroy_plan(static_cast<fftw_plan>(m_backward));
    }
    fftw_free(m_real);
    fftw_free(m_spectrum);
}

Eigen::VectorXd FftConvolver::convolve(const Eigen::VectorXd& kernel, std::size_t offset, std::size_t count)
{
    std::fill(m_real, m_real + m_length, 0.0);
    std::copy(kernel.data(), kernel.data() + kernel.size(), m_real);
    fftw_execute(static_cast<fftw_plan>(m_forward));
    const std::size_t bins = m_length / 2 + 1;
    for (std::size_t k = 0; k < bins; ++k) m_spectrum[k] *= m_signalSpectrum[k];
    // c2r destroys its input; the spectrum buffer is rebuilt on every call anyway.
    fftw_execute(static_cast<fftw_plan>(m_backward));
    Eigen::VectorXd out(static_cast<Eigen::Index>(count));
    const double norm = 1.0 / double(m_length);
    for (std::size_t i = 0; i < count; ++i) out[Eigen::Index(i)] = m_real[offset + i] * norm;
    return out;
}

} // namespace bunraku::analysis::detail
