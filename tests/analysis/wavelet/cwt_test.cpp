#include "tests/support/peer.h"
#include "analysis/wavelet/cwt.h"

#include "tests/analysis/wavelet/pywt_peer.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <stop_token>

using namespace bunraku::analysis;

namespace {

Eigen::VectorXd impulse(Eigen::Index n, Eigen::Index at)
{
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    x[at] = 1.0;
    return x;
}

std::vector<double> testSignal(int kind, int n)
{
    std::mt19937 random(1234 + kind);
    std::normal_distribution<double> normal;
    std::vector<double> x(std::size_t(n), 0.0);
    for (int i = 0; i < n; ++i) {
        const double t = i;
        switch (kind) {
        case 0: x[std::size_t(i)] = normal(random); break;
        case 1: x[std::size_t(i)] = std::sin(2 * std::numbers::pi * 0.11 * t) + 0.3 * std::cos(0.05 * t); break;
        default: x[std::size_t(i)] = std::sin(2 * std::numbers::pi * (0.01 + 0.0008 * t) * t) + 0.01 * t; break;
        }
    }
    return x;
}

Eigen::VectorXd toEigen(const std::vector<double>& values)
{
    return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
}

} // namespace

TEST_CASE("sym3 cwt of an impulse reproduces the digest's reference values", "[cwt]")
{
    // THESIS-DIGEST section 3: unit impulse at n = 32, N = 64.
    const auto result = cwt(impulse(64, 32), {1.0, 2.0});
    REQUIRE(result.ok());
    const std::vector<double> scale1{-0.003207, -0.150300, 0.369351, -0.279498, 0.063654};
    const std::vector<double> scale2{-0.000113, -0.004423, 0.048136, -0.260692, 0.248379,
                                     0.273962,  -0.352436, -0.042834, 0.068831, 0.021190};
    for (std::size_t i = 0; i < scale1.size(); ++i)
        CHECK(result->coefficients(30 + Eigen::Index(i), 0) == Approx(scale1[i]).margin(6e-7));
    for (std::size_t i = 0; i < scale2.size(); ++i)
        CHECK(result->coefficients(28 + Eigen::Index(i), 1) == Approx(scale2[i]).margin(6e-7));
    // Outside the support the coefficients vanish.
    CHECK(result->coefficients(20, 0) == 0.0);
    CHECK(result->coefficients(45, 1) == 0.0);
}

TEST_CASE("the FFT transform agrees with the direct one to 1e-9 relative", "[cwt]")
{
    const int kind = GENERATE(0, 1, 2);
    const Eigen::VectorXd x = toEigen(testSignal(kind, 1500));
    std::vector<double> scales = integerScales(32);
    scales.push_back(2.5);
    scales.push_back(7.3);
    const std::string name = GENERATE(as<std::string>{}, "sym3", "db6", "mexh");
    CwtOptions options;
    options.wavelet = *waveletByName(name);
    options.method = CwtMethod::Direct;
    const auto direct = cwt(x, scales, options);
    options.method = CwtMethod::Fft;
    const auto fft = cwt(x, scales, options);
    REQUIRE(direct.ok());
    REQUIRE(fft.ok());
    const double scale = direct->coefficients.cwiseAbs().maxCoeff();
    INFO(name << " signal " << kind);
    CHECK((direct->coefficients - fft->coefficients).cwiseAbs().maxCoeff() <= 1e-9 * scale);
}

TEST_CASE("the automatic method picks the FFT for long signals with long filters only", "[cwt]")
{
    const CwtFilterBank small = *makeCwtFilterBank(integerScales(16));
    CHECK(resolvedCwtMethod(106, small) == CwtMethod::Direct);
    CHECK(resolvedCwtMethod(100000, small) == CwtMethod::Direct);
    const CwtFilterBank large = *makeCwtFilterBank(integerScales(128));
    CHECK(resolvedCwtMethod(3000, large) == CwtMethod::Direct);
    CHECK(resolvedCwtMethod(100000, large) == CwtMethod::Fft);
    CwtOptions forced;
    forced.method = CwtMethod::Fft;
    CHECK(resolvedCwtMethod(106, *makeCwtFilterBank(integerScales(4), forced)) == CwtMethod::Fft);

    // Automatic gives the same coefficients as direct, whichever it picks.
    const Eigen::VectorXd x = toEigen(testSignal(0, 5000));
    const auto automatic = cwt(x, large);
    CwtOptions direct;
    direct.method = CwtMethod::Direct;
    const auto reference = cwt(x, integerScales(128), direct);
    REQUIRE(automatic.ok());
    REQUIRE(reference.ok());
    CHECK((automatic->coefficients - reference->coefficients).cwiseAbs().maxCoeff()
          <= 1e-9 * reference->coefficients.cwiseAbs().maxCoeff());
}

TEST_CASE("cwt coefficients match pywt on several signals and wavelets", "[cwt][peer]")
{
    const int kind = GENERATE(0, 1, 2);
    const std::string name = GENERATE(as<std::string>{}, "sym3", "db4", "sym5", "mexh", "morl");
    const std::vector<double> signal = testSignal(kind, 300);
    const std::vector<double> scales{1.0, 2.0, 3.0, 4.5, 8.0, 13.7, 20.0};
    // Discrete wavelets: the legacy algorithm step by step (pywt 1.1.1's cwt refuses them);
    // continuous ones: pywt.cwt itself.
    const std::string script =
        "x = " + bunraku::test::pythonArray(signal) + "\n"
        "scales = " + bunraku::test::pythonArray(scales) + "\n"
        "name = '" + name + "'\n"
        "if name in ('mexh', 'morl'):\n"
        "    c, f = pywt.cwt(x, scales, name)\n"
        "else:\n"
        "    ip, ix = pywt.integrate_wavelet(name, precision=10)\n"
        "    step = ix[1] - ix[0]\n"
        "    rows = []\n"
        "    for a in scales:\n"
        "        j = (np.arange(a * (ix[-1] - ix[0]) + 1) / (a * step)).astype(int)\n"
        "        j = j[j < ip.size]\n"
        "        coef = -np.sqrt(a) * np.diff(np.convolve(x, ip[j][::-1]))\n"
        "        d = (coef.size - x.size) / 2.\n"
        "        if d > 0: coef = coef[int(np.floor(d)):int(-np.ceil(d))]\n"
        "        rows.append(coef)\n"
        "    c = np.array(rows)\n"
        "print(' '.join(repr(float(v)) for v in c.ravel()))";
    const auto theirs = bunraku::test::runPywt("cwt-" + name + std::to_string(kind), script);
    if (!bunraku::test::requirePeer(theirs.has_value(), "python3-pywt (/usr/bin/python3 with pywt) for the peer comparison",
                                    "apt-get install python3-pywt"))
        return;
    CwtOptions options;
    options.wavelet = *waveletByName(name);
    const auto ours = cwt(toEigen(signal), scales, options);
    REQUIRE(ours.ok());
    REQUIRE(theirs->size() == scales.size() * signal.size());
    double worst = 0.0;
    double largest = 0.0;
    for (std::size_t s = 0; s < scales.size(); ++s) {
        for (std::size_t t = 0; t < signal.size(); ++t) {
            const double their = (*theirs)[s * signal.size() + t];
            worst = std::max(worst, std::abs(ours->coefficients(Eigen::Index(t), Eigen::Index(s)) - their));
            largest = std::max(largest, std::abs(their));
        }
    }
    INFO(name << " signal " << kind);
    CHECK(worst <= 1e-10 * largest);
}

TEST_CASE("sym3's largest scale for 106 frames is 21 as in thesis 5.3.2", "[cwt]")
{
    CHECK(largestScale(sym3Wavelet(), 106) == 21);
    CHECK(largestScale(sym3Wavelet(), 105) == 20);
}

TEST_CASE("bad cwt parameters are clear errors", "[cwt]")
{
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(50, 0.0, 1.0);
    CHECK(cwt(x, std::vector<double>{}).error().message.find("no scales") != std::string::npos);
    auto negative = cwt(x, {1.0, -2.0});
    REQUIRE_FALSE(negative.ok());
    CHECK(negative.error().code == ErrorCode::InvalidArgument);
    CHECK(negative.error().message.find("-2") != std::string::npos);
    CHECK_FALSE(cwt(x, {0.1}).ok()); // filter of a single sample
    CHECK_FALSE(cwt(Eigen::VectorXd(), {1.0}).ok());
    Eigen::VectorXd withNan = x;
    withNan[3] = std::nan("");
    CHECK(cwt(withNan, {1.0}).error().message.find("NaN") != std::string::npos);
}

TEST_CASE("a stopped cwt returns Cancelled and progress reaches 1", "[cwt]")
{
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(200, 0.0, 1.0);
    std::stop_source source;
    source.request_stop();
    RunControl stopped{source.get_token(), {}};
    auto result = cwt(x, integerScales(4), CwtOptions{}, stopped);
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().code == ErrorCode::Cancelled);
    double last = 0.0;
    RunControl watched{{}, [&](double fraction) { last = fraction; }};
    REQUIRE(cwt(x, integerScales(4), CwtOptions{}, watched).ok());
    CHECK(last == 1.0);
}

TEST_CASE("transforming many channels at once equals transforming each alone", "[cwt]")
{
    const int method = GENERATE(1, 2); // Direct, Fft
    Eigen::MatrixXd signals(700, 5);
    for (int c = 0; c < 5; ++c) signals.col(c) = toEigen(testSignal(c % 3, 700)) * (c + 1.0);
    CwtOptions options;
    options.method = CwtMethod(method);
    const std::vector<double> scales{1.0, 2.0, 3.5, 9.0, 21.0};
    const CwtFilterBank bank = *makeCwtFilterBank(scales, options);
    auto together = cwtChannels(signals, bank);
    REQUIRE(together.ok());
    REQUIRE(together->cols() == 25);
    for (int c = 0; c < 5; ++c) {
        const auto alone = cwt(Eigen::VectorXd(signals.col(c)), bank);
        REQUIRE(alone.ok());
        const Eigen::MatrixXd block = together->middleCols(c * 5, 5);
        CHECK((block - alone->coefficients).cwiseAbs().maxCoeff() <= 1e-12 * alone->coefficients.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("the column-major channel transform equals the row-major one", "[cwt]")
{
    // 11 channels: two groups of the vectorised 8-channel path and a remainder; 300 frames (the
    // column-major transform then also runs across channels) and 5000 (across frames, a
    // channel at a time); interior and edge frames; both methods.
    const int method = GENERATE(1, 2); // Direct, Fft
    for (const Eigen::Index frames : {Eigen::Index(300), Eigen::Index(5000)}) {
        Eigen::MatrixXd signals(frames, 11);
        for (int c = 0; c < 11; ++c)
            signals.col(c) = toEigen(testSignal(c % 3, int(frames))) * (c + 1.0) + Eigen::VectorXd::Constant(frames, 0.5 * c);
        CwtOptions options;
        options.method = CwtMethod(method);
        const CwtFilterBank bank = *makeCwtFilterBank({1.0, 2.0, 5.0, 16.0}, options);
        auto rows = cwtChannels(signals, bank);
        auto series = cwtChannelSeries(signals, bank);
        REQUIRE(rows.ok());
        REQUIRE(series.ok());
        REQUIRE(series->rows() == frames);
        REQUIRE(series->cols() == 44);
        // The same sums in the same order; only whether a multiply-add is fused may differ.
        INFO(frames << " frames");
        CHECK((Eigen::MatrixXd(*rows) - *series).cwiseAbs().maxCoeff() <= 1e-13 * series->cwiseAbs().maxCoeff());
    }
}
