#include "analysis/normalise/noise_experiment.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

TEST_CASE("the noise experiment ranks wavelet matching below the noise first (thesis 3.4)", "[experiment]")
{
    auto result = runNoiseExperiment();
    REQUIRE(result.ok());
    REQUIRE(result->methods.size() == 3);
    CHECK(result->methods[0].name == "amplitude-dp");
    CHECK(result->methods[1].name == "wavelet-below-noise");
    CHECK(result->methods[2].name == "wavelet-with-noise-band");
    const double amplitude = result->methods[0].meanAbsErrorFrames;
    const double below = result->methods[1].meanAbsErrorFrames;
    const double withNoise = result->methods[2].meanAbsErrorFrames;
    INFO("amplitude " << amplitude << ", below noise " << below << ", with noise band " << withNoise);
    CHECK(below < 0.6 * withNoise);
    CHECK(below < 0.6 * amplitude);
    CHECK(below < 2.0);
}

TEST_CASE("without noise every method follows the 1.1x sample", "[experiment]")
{
    NoiseExperimentOptions options;
    options.noiseAmplitude = 0.0;
    options.path = PathMethod::Optimal;
    options.tau = 4;
    auto result = runNoiseExperiment(options);
    REQUIRE(result.ok());
    for (const auto& method : result->methods) {
        INFO(method.name);
        CHECK(method.meanAbsErrorFrames < 1.0);
    }
    // The true warp: the sample at 1.1 x the frequency reaches the reference's phase earlier.
    CHECK(result->trueWarp[100] == Approx((2 * 3.14159265358979 * 0.025 * 100 + 0.4) / (2 * 3.14159265358979 * 0.0275)));
}
