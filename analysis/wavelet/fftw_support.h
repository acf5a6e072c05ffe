#pragma once
/// Internal: thin RAII over FFTW3 (double precision) for the wavelet module. FFTW's planner is
/// not thread-safe, so plans are made and destroyed under one mutex; executing a plan on its
/// own buffers is safe from any thread.

#include <Eigen/Core>

#include <complex>
#include <cstddef>
#include <stop_token>
#include <vector>

namespace bunraku::analysis::detail {

/// The smallest n' >= n whose prime factors are 2, 3, 5 and 7 (fast FFTW sizes).
std::size_t fastFftLength(std::size_t n);

/// The first n / 2 + 1 bins of the DFT of `values` zero-padded (or cut) to n samples.
std::vector<std::complex<double>> realSpectrum(const Eigen::VectorXd& values, std::size_t n);

/// Linear convolutions of signals with a fixed set of kernels by overlap-save: the signal in
/// blocks of one power-of-two length, each block's spectrum computed once for every kernel,
/// the kernels' spectra once for all signals.
class BlockConvolver {
public:
    explicit BlockConvolver(const std::vector<Eigen::VectorXd>& kernels);
    ~BlockConvolver();
    BlockConvolver(const BlockConvolver&) = delete;
    BlockConvolver& operator=(const BlockConvolver&) = delete;

    /// out(t, k) = factors[k] * (signal * kernels[k])(offsets[k] + t) for t < out.rows(), the
    /// full convolution's samples outside 0 .. signal + kernel - 2 being 0. False when `stop`
    /// was requested (checked between blocks).
    bool convolve(const Eigen::VectorXd& signal, const std::vector<std::size_t>& offsets, const std::vector<double>& factors,
                  Eigen::Ref<Eigen::MatrixXd> out, const std::stop_token& stop);

private:
    std::size_t m_length = 0; // block length (a power of two)
    std::size_t m_reach = 0;  // longest kernel - 1: samples each block repeats from the one before
    std::vector<std::vector<std::complex<double>>> m_spectra;
    void* m_forward = nullptr;  // fftw_plan
    void* m_backward = nullptr; // fftw_plan
    double* m_real = nullptr;
    std::complex<double>* m_spectrum = nullptr;
    std::complex<double>* m_product = nullptr;
    double* m_block = nullptr;
};

} // namespace bunraku::analysis::detail
