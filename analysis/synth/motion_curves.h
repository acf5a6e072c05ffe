#pragma once
/// Smooth curves the demo generator is built from: the minimum-jerk transition of a phrase, a
/// monotone cubic (Fritsch-Carlson) map for phase warps, and a seeded random source with its own
/// uniform and Gaussian draws (so the corpus depends only on std::mt19937_64, which the standard
/// fixes bit for bit).

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace bunraku::analysis::synth {

/// Minimum-jerk step 10 x^3 - 15 x^4 + 6 x^5 for x in [0, 1], 0 below and 1 above:
/// zero velocity and acceleration at both ends (Flash & Hogan 1985).
double minimumJerk(double x);

/// A strictly increasing C1 map through knots (x_k, y_k) with strictly increasing x and y:
/// piecewise cubic Hermite with Fritsch-Carlson slopes, so it never overshoots; linear
/// extrapolation with the end slopes outside the knots.
class MonotoneCubic {
public:
    MonotoneCubic(std::vector<double> x, std::vector<double> y);
    double operator()(double x) const;
    /// The x with (*this)(x) = y, by bisection to 1e-12 frames.
    double inverse(double y) const;

private:
    std::vector<double> m_x;
    std::vector<double> m_y;
    std::vector<double> m_slope;
};

/// Angle in degrees wrapped into (-180, 180], as a FASTRAK reports it.
double wrapDegrees(double degrees);

/// The generator's random source: std::mt19937_64 plus hand-written distributions, so the same
/// seed gives the same corpus with any standard library.
class DemoRandom {
public:
    explicit DemoRandom(std::uint64_t seed) : m_engine(seed) {}
    /// Uniform in [0, 1) from the top 53 bits of one draw.
    double uniform();
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    /// Uniform integer in [low, high].
    int uniformInt(int low, int high);
    /// Standard Gaussian (Box-Muller, one value per two uniforms).
    double gaussian();

private:
    std::mt19937_64 m_engine;
};

} // namespace bunraku::analysis::synth
