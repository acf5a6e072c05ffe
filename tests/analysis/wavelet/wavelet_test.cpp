#include "tests/support/peer.h"
#include "analysis/wavelet/wavelet.h"

#include "tests/analysis/wavelet/pywt_peer.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace bunraku::analysis;

namespace {

double maxAbsDifference(const Eigen::VectorXd& ours, const std::vector<double>& theirs, std::size_t offset = 0)
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < ours.size(); ++i) worst = std::max(worst, std::abs(ours[i] - theirs[offset + std::size_t(i)]));
    return worst;
}

} // namespace

TEST_CASE("wavelets are found by name and unknown names are a clear error", "[wavelet]")
{
    auto sym3 = waveletByName("sym3");
    REQUIRE(sym3.ok());
    CHECK(sym3->reconstructionLowPass.size() == 6);
    CHECK(sym3->reconstructionLowPass[0] == Approx(0.33267055295095688).epsilon(1e-14));
    CHECK(sym3->upperBound == 5.0);
    CHECK(waveletByName("db8")->reconstructionLowPass.size() == 16);
    CHECK(waveletByName("mexh")->kind == WaveletKind::Continuous);
    auto unknown = waveletByName("haar2");
    REQUIRE_FALSE(unknown.ok());
    CHECK(unknown.error().code == ErrorCode::NotFound);
    CHECK(unknown.error().message.find("haar2") != std::string::npos);
}

TEST_CASE("orthogonal filters have unit energy and sum to sqrt 2", "[wavelet]")
{
    for (const auto& name : waveletNames()) {
        const Wavelet wavelet = *waveletByName(name);
        if (wavelet.kind != WaveletKind::Orthogonal) continue;
        double sum = 0.0;
        double energy = 0.0;
        for (double c : wavelet.reconstructionLowPass) {
            sum += c;
            energy += c * c;
        }
        INFO(name);
        CHECK(sum == Approx(std::sqrt(2.0)).epsilon(1e-9));
        CHECK(energy == Approx(1.0).epsilon(1e-9));
    }
}

TEST_CASE("sampled and integrated wavelets match pywt's wavefun and integrate_wavelet", "[wavelet][peer]")
{
    const std::string name = GENERATE(as<std::string>{}, "sym3", "db1", "db4", "sym8", "mexh", "morl");
    const Wavelet wavelet = *waveletByName(name);
    const SampledWavelet ours = waveletFunction(wavelet, 10);
    const SampledWavelet integrated = integratedWavelet(wavelet, 10);
    const auto theirs = bunraku::test::runPywt(
        "wavefun-" + name,
        "w = pywt.DiscreteContinuousWavelet('" + name + "')\n"
        "f = w.wavefun(10)\n"
        "psi, x = f[-2], f[-1]\n"
        "ip, ix = pywt.integrate_wavelet('" + name + "', precision=10)\n"
        "print(len(psi)); print(' '.join(repr(float(v)) for v in np.concatenate([x, psi, ip])))");
    if (!bunraku::test::requirePeer(theirs.has_value(), "python3-pywt (/usr/bin/python3 with pywt) for the peer comparison",
                                    "apt-get install python3-pywt"))
        return;
    INFO(name);
    const auto count = std::size_t((*theirs)[0]);
    REQUIRE(Eigen::Index(count) == ours.psi.size());
    CHECK(maxAbsDifference(ours.x, *theirs, 1) == 0.0);
    CHECK(maxAbsDifference(ours.psi, *theirs, 1 + count) < 1e-12);
    CHECK(maxAbsDifference(integrated.psi, *theirs, 1 + 2 * count) < 1e-12);
}

TEST_CASE("centre frequencies match pywt and sym3's is 0.8", "[wavelet][peer]")
{
    CHECK(centreFrequency(sym3Wavelet()) == Approx(0.8));
    CHECK(scaleToFrequency(sym3Wavelet(), 8.0, 0.2) == Approx(0.8 / 8.0 / 0.2));
    const auto theirs = bunraku::test::runPywt(
        "centfrq", "print(' '.join(repr(pywt.central_frequency(n)) for n in ['sym3','db2','sym6','mexh','morl']))");
    if (!bunraku::test::requirePeer(theirs.has_value(), "python3-pywt (/usr/bin/python3 with pywt) for the peer comparison",
                                    "apt-get install python3-pywt"))
        return;
    const std::vector<std::string> names{"sym3", "db2", "sym6", "mexh", "morl"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        INFO(names[i]);
        CHECK(centreFrequency(*waveletByName(names[i])) == Approx((*theirs)[i]).epsilon(1e-12));
    }
}
