#pragma once
/// Internal: thin RAII over FFTW3 (double precision) for the wavelet module. FFTW's planner is
/// not thread-safe, so plans are made and destroyed under one mutex; executing a plan on its
/// own buffers is safe from any thread.

#include <Eigen/Core>

#include <complex>
#include <cstddef>
#include <vector>

namespace bunraku::analysis::detail {

/// The smallest n' >= n whose prime factors are 2, 3, 5 and 7 (fast FFTW sizes).
std::size_t fastFftLength(std::size_t n);

/// The first n / 2 + 1 bins of the DFT of `values` zero-padded (or cut) to n samples.
std::vector<std::complex<double>> realSpectrum(const Eigen::VectorXd& values, std::size_t n);

/// Full linear convolutions of one signal with several kernels through one padded length.
class FftConvolver {
public:
    /// length >= signal.size() + longest kernel - 1; the signal's spectrum is computed once.
    FftConvolver(const Eigen::VectorXd& signal, std::size_t length);
    ~FftConvolver();
    FftConvolver(const FftConvolver&) = delete;
    FftConvolver& operator=(const FftConvolver&) = delete;

    /// signal * kernel (full convolution), the first `count` samples of it from `offset`.
    Eigen::VectorXd convolve(const Eigen::VectorXd& kernel, std::size_t offset, std::size_t count);

private:
    std::size_t m_length;
    void* m_forward = nullptr;  // fftw_plan
    void* m_backward = nullptr; // fftw_plan
    double* m_real = nullptr;
    std::complex<double>* m_spectrum = nullptr;
    std::vector<std::complex<double>> m_signalSpectrum;
};

} // namespace bunraku::analysis::detail
