#include "analysis/synth/motion_curves.h"

#include "analysis/synth/demo_corpus.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace bunraku::analysis::synth {

double minimumJerk(double x)
{
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 1.0;
    return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y) : m_x(std::move(x)), m_y(std::move(y))
{
    assert(m_x.size() == m_y.size() && m_x.size() >= 2);
    const std::size_t n = m_x.size();
    std::vector<double> secant(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        assert(m_x[k + 1] > m_x[k] && m_y[k + 1] > m_y[k]);
        secant[k] = (m_y[k + 1] - m_y[k]) / (m_x[k + 1] - m_x[k]);
    }
    // Fritsch-Carlson: interior slopes are weighted harmonic means of the adjacent secants
    // (always positive here, and small enough that the cubic stays monotone).
    m_slope.resize(n);
    m_slope.front() = secant.front();
    m_slope.back() = secant.back();
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const double h0 = m_x[k] - m_x[k - 1];
        const double h1 = m_x[k + 1] - m_x[k];
        const double w0 = 2.0 * h1 + h0;
        const double w1 = h1 + 2.0 * h0;
        m_slope[k] = (w0 + w1) / (w0 / secant[k - 1] + w1 / secant[k]);
    }
}

double MonotoneCubic::operator()(double x) const
{
    if (x <= m_x.front()) return m_y.front() + m_slope.front() * (x - m_x.front());
    if (x >= m_x.back()) return m_y.back() + m_slope.back() * (x - m_x.back());
    const auto it = std::upper_bound(m_x.begin(), m_x.end(), x);
    const std::size_t k = std::size_t(it - m_x.begin()) - 1;
    const double h = m_x[k + 1] - m_x[k];
    const double s = (x - m_x[k]) / h;
    const double s2 = s * s;
    const double s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * m_y[k] + (s3 - 2 * s2 + s) * h * m_slope[k] + (-2 * s3 + 3 * s2) * m_y[k + 1] +
           (s3 - s2) * h * m_slope[k + 1];
}

double MonotoneCubic::inverse(double y) const
{
    double low = m_x.front();
    double high = m_x.back();
    if (y <= m_y.front()) return low + (y - m_y.front()) / m_slope.front();
    if (y >= m_y.back()) return high + (y - m_y.back()) / m_slope.back();
    for (int i = 0; i < 200 && high - low > 1e-12; ++i) {
        const double mid = 0.5 * (low + high);
        if ((*this)(mid) < y)
            low = mid;
        else
            high = mid;
    }
    return 0.5 * (low + high);
}

double wrapDegrees(double degrees)
{
    double r = std::fmod(degrees + 180.0, 360.0);
    if (r <= 0.0) r += 360.0;
    return r - 180.0;
}

double DemoRandom::uniform() { return double(m_engine() >> 11) * 0x1.0p-53; }

int DemoRandom::uniformInt(int low, int high)
{
    const auto span = std::uint64_t(high - low) + 1;
    return low + int(m_engine() % span); // the modulo bias is below 1e-17 for our spans
}

double DemoRandom::gaussian()
{
    const double u1 = 1.0 - uniform(); // in (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Eigen::RowVectorXd interpolateMotion(const Eigen::MatrixXd& motion, double frame)
{
    assert(motion.rows() >= 1);
    const Eigen::Index last = motion.rows() - 1;
    if (last == 0 || frame <= 0.0) return motion.row(0);
    if (frame >= double(last)) return motion.row(last);
    const Eigen::Index k = std::min<Eigen::Index>(Eigen::Index(std::floor(frame)), last - 1);
    const double s = frame - double(k);
    auto tangent = [&](Eigen::Index i) -> Eigen::RowVectorXd {
        if (i == 0) return motion.row(1) - motion.row(0);
        if (i == last) return motion.row(last) - motion.row(last - 1);
        return 0.5 * (motion.row(i + 1) - motion.row(i - 1));
    };
    const double s2 = s * s;
    const double s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * motion.row(k) + (s3 - 2 * s2 + s) * tangent(k) +
           (-2 * s3 + 3 * s2) * motion.row(k + 1) + (s3 - s2) * tangent(k + 1);
}

Eigen::MatrixXd resampleMotion(const Eigen::MatrixXd& motion, const Eigen::VectorXd& frames)
{
    Eigen::MatrixXd result(frames.size(), motion.cols());
    for (Eigen::Index i = 0; i < frames.size(); ++i) result.row(i) = interpolateMotion(motion, frames(i));
    return result;
}

} // namespace bunraku::analysis::synth
