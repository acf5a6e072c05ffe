#include "analysis/wavelet/cwt.h"
#include "analysis/wavelet/simd_level.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace bunraku::analysis;

namespace {

Eigen::MatrixXd randomSignals(Eigen::Index frames, Eigen::Index channels, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd x(frames, channels);
    for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = normal(random) + 3.0 * std::sin(0.01 * double(i));
    return x;
}

// The defining sum (cwt.h): -sqrt(scale) * (x conv kernel)(t + floor((M - 2) / 2) + 1) with x zero
// outside the signal, M the filter length; returns the coefficient and the sum of the terms'
// magnitudes (the scale of its rounding error).
std::pair<double, double> definingSum(const Eigen::VectorXd& x, const Eigen::VectorXd& kernel, double scale, Eigen::Index t)
{
    const Eigen::Index m = kernel.size() - 1;
    const Eigen::Index k = t + (m - 2) / 2 + 1;
    long double sum = 0.0L;
    double magnitude = 0.0;
    for (Eigen::Index i = std::max<Eigen::Index>(0, k - m); i <= std::min<Eigen::Index>(x.size() - 1, k); ++i) {
        sum += static_cast<long double>(x[i]) * static_cast<long double>(kernel[k - i]);
        magnitude += std::abs(x[i] * kernel[k - i]);
    }
    return {-std::sqrt(scale) * double(sum), std::sqrt(scale) * magnitude};
}

struct Shape {
    Eigen::Index frames;
    Eigen::Index channels;
};

} // namespace

TEST_CASE("every direct CWT kernel the CPU runs gives the defining sum and the plain kernel's coefficients", "[cwt][simd]")
{
    // Lengths from 1 frame (every tap outside the signal) to long series cut into segments that
    // run side by side; channel counts that fill the eight lanes, leave some empty or need
    // several groups; integer and fractional scales of a short and a long wavelet.
    const std::string wavelet = GENERATE("sym3", "mexh");
    const std::vector<Shape> shapes{{1, 1}, {2, 3}, {7, 1}, {106, 24}, {300, 5}, {5000, 1}, {5001, 2}, {20011, 3}};
    CwtOptions options;
    options.wavelet = *waveletByName(wavelet);
    options.method = CwtMethod::Direct;
    const CwtFilterBank bank = *makeCwtFilterBank({1.0, 2.0, 3.5, 9.0, 16.0}, options);
    const auto scales = Eigen::Index(bank.scales.size());
    for (const Shape& shape : shapes) {
        const Eigen::MatrixXd x = randomSignals(shape.frames, shape.channels, unsigned(shape.frames + shape.channels));
        Eigen::MatrixXd plain;
        {
            ScopedSimdLevel scope(SimdLevel::Plain);
            plain = *cwtChannelSeries(x, bank);
        }
        for (SimdLevel level : runnableSimdLevels()) {
            ScopedSimdLevel scope(level);
            auto series = cwtChannelSeries(x, bank);
            REQUIRE(series.ok());
            INFO(simdLevelName(level) << ", " << wavelet << ", " << shape.frames << " frames x " << shape.channels << " channels");
            double worstDefinition = 0.0;
            double worstPlain = 0.0;
            // Every frame of short signals; for long ones both ends, segment borders and a stride.
            for (Eigen::Index c = 0; c < shape.channels; ++c)
                for (Eigen::Index s = 0; s < scales; ++s)
                    for (Eigen::Index t = 0; t < shape.frames; t += (shape.frames < 400 || t < 200 || t > shape.frames - 200) ? 1 : 7) {
                        const double ours = (*series)(t, c * scales + s);
                        const auto [truth, magnitude] = definingSum(x.col(c), bank.kernels[std::size_t(s)], bank.scales[std::size_t(s)], t);
                        worstDefinition = std::max(worstDefinition, std::abs(ours - truth) / (magnitude + 1e-300));
                        worstPlain = std::max(worstPlain, std::abs(ours - plain(t, c * scales + s)) / (magnitude + 1e-300));
                    }
            CHECK(worstDefinition < 1e-13);
            CHECK(worstPlain < 1e-13);
        }
    }
}

TEST_CASE("the SIMD CWT kernels sum in one order: identical bits for every layout and level", "[cwt][simd]")
{
    // One channel alone (its frames cut into segments side by side), the same channel among
    // others (a lane each) and the row-major layout run the same multiply-add chains: the
    // coefficients agree bit for bit, and so do the AVX2 and AVX-512 kernels.
    const Eigen::MatrixXd x = randomSignals(9000, 3, 7);
    CwtOptions options;
    options.method = CwtMethod::Direct;
    const CwtFilterBank bank = *makeCwtFilterBank(integerScales(16), options);
    std::vector<Eigen::MatrixXd> perLevel;
    for (SimdLevel level : runnableSimdLevels()) {
        if (level == SimdLevel::Plain) continue;
        ScopedSimdLevel scope(level);
        const Eigen::MatrixXd series = *cwtChannelSeries(x, bank);
        const Eigen::MatrixXd rows = *cwtChannels(x, bank);
        INFO(simdLevelName(level));
        CHECK(series == rows);
        for (Eigen::Index c = 0; c < 3; ++c) {
            const auto alone = cwt(Eigen::VectorXd(x.col(c)), bank);
            REQUIRE(alone.ok());
            CHECK(alone->coefficients == series.middleCols(c * 16, 16));
        }
        perLevel.push_back(series);
    }
    for (std::size_t k = 1; k < perLevel.size(); ++k) CHECK(perLevel[k] == perLevel[0]);
}
