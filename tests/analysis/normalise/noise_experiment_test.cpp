#include "analysis/normalise/noise_experiment.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

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

TEST_CASE("the thesis's bands of 3.4 are 0.894-1.151 x the signal's frequency and up to 2 x the noise's", "[experiment]")
{
    // sym3's centre frequency 0.8: scale c sees 0.8 / c cycles per frame
    const auto below = scalesInBand(0.894 * 0.025, 1.151 * 0.025);
    REQUIRE_FALSE(below.empty());
    CHECK(below.front() == 28.0);
    CHECK(below.back() == 35.0);
    const NoiseExperimentOptions thesis = thesisBandOptions();
    CHECK(thesis.scalesBelowNoise == below);
    // sym3's centre frequency is 0.8005 (Table 3.1), so scale 4 (0.2001) is just above 2 x the noise
    const double centre = centreFrequency(sym3Wavelet());
    CHECK(centre == Approx(0.8005).margin(0.003));
    const ThesisNoiseBands bands;
    CHECK(bands.highestOfNoise == Approx(1.9975).margin(1e-4));
    CHECK(thesis.scalesWithNoise.front() == std::ceil(centre / (bands.highestOfNoise * 0.1) - 1e-9));
    CHECK(thesis.scalesWithNoise.back() == 35.0);
    // in the thesis's own units (cycles per sample): 0.0178-0.0229 -> scales 35..44, up to 0.160 -> from scale 6
    NoiseExperimentOptions own;
    own.referenceFrequency = 0.0199;
    own.noiseFrequency = 0.0801;
    const NoiseExperimentOptions literal = thesisBandOptions(own);
    CHECK(literal.scalesBelowNoise.front() == 35.0);
    CHECK(literal.scalesBelowNoise.back() == 44.0);
    CHECK(literal.scalesWithNoise.front() == std::ceil(centre / 0.160 - 1e-9));
    CHECK(scalesInBand(0.5, 0.1).empty());
}

TEST_CASE("with the thesis's bands, the noise band does not spoil wavelet matching (docs/NORMALISATION.md says why)",
          "[experiment]")
{
    auto result = runNoiseExperiment(thesisBandOptions());
    REQUIRE(result.ok());
    REQUIRE(result->methods.size() == 3);
    const MethodError& amplitude = result->methods[0];
    const MethodError& below = result->methods[1];
    const MethodError& withNoise = result->methods[2];
    INFO("mean error: amplitude " << amplitude.meanAbsErrorFrames << ", below " << below.meanAbsErrorFrames << ", with "
                                  << withNoise.meanAbsErrorFrames << "; shape RMS " << amplitude.shapeRms << " "
                                  << below.shapeRms << " " << withNoise.shapeRms);
    // as in the thesis: wavelet matching beats amplitude matching on the noisy sample
    CHECK(below.meanAbsErrorFrames < 0.5 * amplitude.meanAbsErrorFrames);
    CHECK(below.shapeRms < 0.7 * amplitude.shapeRms);
    CHECK(withNoise.shapeRms < 0.7 * amplitude.shapeRms);
    // unlike the thesis's Fig. 3.9: a band from 0.894 x the signal's frequency up to 2 x the
    // noise's keeps the signal's own scales, whose coefficients (growing as sqrt(scale)) outweigh
    // the noise's; it matches at least as well as the band below the noise
    CHECK(withNoise.shapeRms <= below.shapeRms);
    CHECK(withNoise.meanAbsErrorFrames <= below.meanAbsErrorFrames);
    // the thesis's ranking returns when the noise band stops short of the signal's scales (5..15)
    NoiseExperimentOptions narrow = thesisBandOptions();
    narrow.scalesWithNoise = integerScales(15);
    narrow.scalesWithNoise.erase(narrow.scalesWithNoise.begin(), narrow.scalesWithNoise.begin() + 4);
    REQUIRE(narrow.scalesWithNoise.front() == 5.0);
    auto narrowResult = runNoiseExperiment(narrow);
    REQUIRE(narrowResult.ok());
    CHECK(narrowResult->methods[1].shapeRms < 0.6 * narrowResult->methods[2].shapeRms);
    CHECK(narrowResult->methods[1].meanAbsErrorFrames < 0.6 * narrowResult->methods[2].meanAbsErrorFrames);
}

TEST_CASE("the shape error of the noise-free sample is small for every method", "[experiment]")
{
    NoiseExperimentOptions options;
    options.noiseAmplitude = 0.0;
    options.path = PathMethod::Optimal;
    options.tau = 4;
    auto result = runNoiseExperiment(options);
    REQUIRE(result.ok());
    CHECK(result->cleanSample == result->sample);
    // whole-frame matches of a sine with 40-frame period: about 0.05 RMS, more at the edges
    for (const auto& method : result->methods) CHECK(method.shapeRms < 0.15);
}

TEST_CASE("noise experiment: the with-noise band's lower edge", "[.][table]")
{
    for (int last : {10, 15, 20, 25, 30, 35}) {
        NoiseExperimentOptions options = thesisBandOptions();
        options.scalesWithNoise.clear();
        for (int c = 5; c <= last; ++c) options.scalesWithNoise.push_back(c);
        for (PathMethod path : {PathMethod::Independent, PathMethod::Optimal}) {
            options.path = path;
            options.tau = path == PathMethod::Optimal ? 4 : 0;
            auto result = runNoiseExperiment(options);
            REQUIRE(result.ok());
            std::printf("5..%d %s: below %.3f / %.3f, with %.3f / %.3f (mean frames / shape RMS)\n", last,
                        path == PathMethod::Optimal ? "optimal tau 4" : "single frames", result->methods[1].meanAbsErrorFrames,
                        result->methods[1].shapeRms, result->methods[2].meanAbsErrorFrames, result->methods[2].shapeRms);
        }
    }
}
