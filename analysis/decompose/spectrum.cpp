#include "analysis/decompose/spectrum.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bunraku::analysis {
namespace {

Status checkSeries(const Eigen::VectorXd& series, double rateHz)
{
    if (series.size() < 2) return makeError(ErrorCode::InvalidArgument, "spectrum: need at least 2 samples");
    if (!(rateHz > 0.0) || !std::isfinite(rateHz))
        return makeError(ErrorCode::InvalidArgument, "spectrum: the sampling rate must be positive");
    if (!series.allFinite()) return makeError(ErrorCode::Numerical, "spectrum: the series has non-finite values");
    return okStatus();
}

/// One-sided density of one windowed segment, added into `power` (direct DFT: the series are
/// short, ~100 frames, and any length is allowed).
void addSegment(const Eigen::VectorXd& segment, const Eigen::VectorXd& window, double rateHz, Eigen::VectorXd& power)
{
    const Eigen::Index n = segment.size();
    const Eigen::VectorXd x = segment.cwiseProduct(window);
    const double scale = 1.0 / (rateHz * window.squaredNorm());
    // twiddle table: exp(-2 pi i m / n), indexed by (k t) mod n
    Eigen::VectorXd cosTable(n);
    Eigen::VectorXd sinTable(n);
    for (Eigen::Index m = 0; m < n; ++m) {
        cosTable(m) = std::cos(2.0 * std::numbers::pi * double(m) / double(n));
        sinTable(m) = -std::sin(2.0 * std::numbers::pi * double(m) / double(n));
    }
    for (Eigen::Index k = 0; k < power.size(); ++k) {
        double re = 0.0;
        double im = 0.0;
        Eigen::Index phase = 0;
        for (Eigen::Index t = 0; t < n; ++t) {
            re += x(t) * cosTable(phase);
            im += x(t) * sinTable(phase);
            phase += k;
            if (phase >= n) phase -= n;
        }
        double p = (re * re + im * im) * scale;
        const bool nyquist = n % 2 == 0 && k == n / 2;
        if (k != 0 && !nyquist) p *= 2.0;
        power(k) += p;
    }
}

Eigen::VectorXd frequencies(Eigen::Index n, double rateHz)
{
    Eigen::VectorXd f(n / 2 + 1);
    for (Eigen::Index k = 0; k < f.size(); ++k) f(k) = double(k) * rateHz / double(n);
    return f;
}

Eigen::VectorXd detrended(const Eigen::VectorXd& x, Detrend detrend)
{
    if (detrend == Detrend::None) return x;
    return x.array() - x.mean();
}

} // namespace

Result<Spectrum> periodogram(const Eigen::VectorXd& series, double rateHz, const PeriodogramOptions& options)
{
    if (auto status = checkSeries(series, rateHz); !status) return status.error();
    Spectrum s;
    s.frequencyHz = frequencies(series.size(), rateHz);
    s.power = Eigen::VectorXd::Zero(s.frequencyHz.size());
    addSegment(detrended(series, options.detrend), Eigen::VectorXd::Ones(series.size()), rateHz, s.power);
    return s;
}

Result<Spectrum> welch(const Eigen::VectorXd& series, double rateHz, const WelchOptions& options)
{
    if (auto status = checkSeries(series, rateHz); !status) return status.error();
    if (options.segmentLength < 2) return makeError(ErrorCode::InvalidArgument, "welch: segment length must be >= 2");
    if (!(options.overlap >= 0.0 && options.overlap < 1.0))
        return makeError(ErrorCode::InvalidArgument, "welch: overlap must be in [0, 1)");
    const Eigen::Index n = std::min<Eigen::Index>(options.segmentLength, series.size());
    const Eigen::Index step = std::max<Eigen::Index>(1, n - Eigen::Index(std::floor(options.overlap * double(n))));
    Eigen::VectorXd window(n);
    for (Eigen::Index t = 0; t < n; ++t) window(t) = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(t) / double(n));
    Spectrum s;
    s.frequencyHz = frequencies(n, rateHz);
    s.power = Eigen::VectorXd::Zero(s.frequencyHz.size());
    int segments = 0;
    for (Eigen::Index start = 0; start + n <= series.size(); start += step, ++segments)
        addSegment(detrended(series.segment(start, n), options.detrend), window, rateHz, s.power);
    s.power /= double(segments);
    return s;
}

} // namespace bunraku::analysis
