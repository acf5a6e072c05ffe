#include "analysis/normalise/amplitude_matching.h"
#include "analysis/normalise/wavelet_matching.h"

#include "tests/analysis/normalise/synthetic_takes.h"

#include <catch2/catch.hpp>

#include <stop_token>

using namespace bunraku::analysis;
using bunraku::test::sineWarp;
using bunraku::test::trueCorrespondence;
using bunraku::test::warpedTake;

namespace {

double meanAbsError(const Eigen::VectorXi& correspondence, const Eigen::VectorXd& truth)
{
    return (correspondence.cast<double>() - truth).cwiseAbs().mean();
}

// arm.x and hand.x of a take: the channels method 1 couples.
Eigen::MatrixXd armHandX(const Take& take)
{
    Eigen::MatrixXd values(take.frameCount(), 2);
    values.col(0) = take.values.col(puppetChannel(2, Dof::X));
    values.col(1) = take.values.col(puppetChannel(3, Dof::X));
    return values;
}

} // namespace

TEST_CASE("a take matched to itself maps every frame to itself at zero cost", "[matching]")
{
    const Take take = warpedTake([](double u) { return u; }, 106, 1);
    for (auto path : {PathMethod::Greedy, PathMethod::Optimal}) {
        MatchOptions options;
        options.path = path;
        auto match = matchChannels(armHandX(take), armHandX(take), options);
        REQUIRE(match.ok());
        CHECK(match->cost == Approx(0.0).margin(1e-6));
        for (Eigen::Index t = 0; t < 106; ++t) CHECK(match->correspondence[t] == t);
    }
}

TEST_CASE("wavelet matching recovers a smooth time warp within a frame", "[matching]")
{
    const auto phi = sineWarp(9.0, 106, 2.0);
    const Take reference = warpedTake([](double u) { return u; }, 106, 4);
    const Take sample = warpedTake(phi, 106, 2);
    const Eigen::VectorXd truth = trueCorrespondence(phi, 106, 106);
    MatchOptions options;
    options.path = PathMethod::Optimal;
    auto optimal = matchChannels(armHandX(reference), armHandX(sample), options);
    REQUIRE(optimal.ok());
    // Away from the ends, where up to 2.5 x 16 frames of each coefficient see the zero padding
    // and the template is flat, the warp is found within a frame on average.
    CHECK(meanAbsError(optimal->correspondence.segment(10, 86), truth.segment(10, 86)) < 1.0);
    CHECK(meanAbsError(optimal->correspondence, truth) < 1.5);
    for (Eigen::Index t = 1; t < 106; ++t) CHECK(optimal->correspondence[t] >= optimal->correspondence[t - 1]);
    // The smooth warp is monotone and close to the integer correspondence.
    for (Eigen::Index t = 1; t < 106; ++t) CHECK(optimal->smoothWarp[t] >= optimal->smoothWarp[t - 1]);
    CHECK((optimal->smoothWarp - optimal->correspondence.cast<double>()).cwiseAbs().maxCoeff() <= 3.0);

    options.path = PathMethod::Greedy;
    auto greedy = matchChannels(armHandX(reference), armHandX(sample), options);
    REQUIRE(greedy.ok());
    CHECK(optimal->cost <= greedy->cost + 1e-9);
}

TEST_CASE("the amplitude baseline uses the same band and monotone constraint", "[matching]")
{
    const auto phi = sineWarp(6.0, 106);
    const Take reference = warpedTake([](double u) { return u; }, 106, 4);
    const Take sample = warpedTake(phi, 106, 2);
    AmplitudeMatchOptions options;
    options.searchBand = 5;
    auto match = matchAmplitudes(armHandX(reference), armHandX(sample), options);
    REQUIRE(match.ok());
    for (Eigen::Index t = 0; t < 106; ++t) {
        CHECK(std::abs(match->correspondence[t] - t) <= 5);
        if (t > 0) CHECK(match->correspondence[t] >= match->correspondence[t - 1]);
    }
    // Noise-free, it finds the warp too (the thesis's point is about noise).
    CHECK(meanAbsError(match->correspondence, trueCorrespondence(phi, 106, 106)) < 1.0);
}

TEST_CASE("the approximation term of eq. 5.17 penalises a level offset the coefficients miss", "[matching]")
{
    const Take reference = warpedTake([](double u) { return u; }, 106, 1);
    Eigen::MatrixXd shifted = armHandX(reference);
    shifted.array() += 20.0; // same shape, another level: invisible to the mid-signal coefficients
    MatchOptions options;
    // The default level alignment removes the offset altogether.
    auto aligned = matchChannels(armHandX(reference), shifted, options);
    REQUIRE(aligned.ok());
    CHECK(aligned->cost == Approx(0.0).margin(1e-6));
    options.level = LevelAlignment::None;
    auto without = matchChannels(armHandX(reference), shifted, options);
    options.approximationWeight = 8.0;
    auto with = matchChannels(armHandX(reference), shifted, options);
    REQUIRE(without.ok());
    REQUIRE(with.ok());
    // Every window of 2 channels x 9 frames pays about M * 20^2 more.
    CHECK(with->cost - without->cost > 0.5 * 8.0 * 400.0 * 18.0 * 106.0);
}

TEST_CASE("matching parameter errors are clear", "[matching]")
{
    const Eigen::MatrixXd take = armHandX(warpedTake([](double u) { return u; }, 106, 1));
    MatchOptions options;
    options.tau = -1;
    auto negativeTau = matchChannels(take, take, options);
    REQUIRE_FALSE(negativeTau.ok());
    CHECK(negativeTau.error().message.find("tau") != std::string::npos);

    options = {};
    options.scales = integerScales(22); // sym3 fits up to 21 on 106 frames
    auto tooLong = matchChannels(take, take, options);
    REQUIRE_FALSE(tooLong.ok());
    CHECK(tooLong.error().message.find("scale 22") != std::string::npos);
    CHECK(tooLong.error().message.find("21") != std::string::npos);

    options = {};
    options.searchBand = -3;
    CHECK_FALSE(matchChannels(take, take, options).ok());
    CHECK_FALSE(matchChannels(take, take.leftCols(1), MatchOptions{}).ok());
    options = {};
    options.approximationWeight = -1;
    CHECK_FALSE(matchChannels(take, take, options).ok());

    Eigen::MatrixXd withNan = take;
    withNan(5, 1) = std::nan("");
    CHECK(matchChannels(take, withNan, MatchOptions{}).error().message.find("NaN") != std::string::npos);

    // Without a global time scale, a reference longer than the sample plus the band has frames
    // nothing can match.
    options = {};
    options.searchBand = 5;
    options.scales = integerScales(4);
    options.timeScaling = TimeScaling::None;
    auto unmatched = matchChannels(take, take.topRows(60), options);
    REQUIRE_FALSE(unmatched.ok());
    CHECK(unmatched.error().message.find("longer") != std::string::npos);
}

TEST_CASE("a stopped match returns Cancelled", "[matching]")
{
    const Eigen::MatrixXd take = armHandX(warpedTake([](double u) { return u; }, 106, 1));
    std::stop_source source;
    source.request_stop();
    auto result = matchChannels(take, take, MatchOptions{}, RunControl{source.get_token(), {}});
    REQUIRE_FALSE(result.ok());
    CHECK(result.error().code == ErrorCode::Cancelled);
}

TEST_CASE("correspondences resample the sample on the reference's time axis", "[matching]")
{
    Eigen::MatrixXd sample(4, 1);
    sample << 10, 20, 30, 40;
    Eigen::VectorXi correspondence(5);
    correspondence << 0, 0, 1, 3, 3;
    const Eigen::MatrixXd normalised = applyCorrespondence(sample, correspondence);
    CHECK(normalised(1, 0) == 10);
    CHECK(normalised(3, 0) == 40);
    Eigen::VectorXd warp(3);
    warp << 0.5, 1.25, 9.0;
    const Eigen::MatrixXd warped = applyWarp(sample, warp);
    CHECK(warped(0, 0) == Approx(15.0));
    CHECK(warped(1, 0) == Approx(22.5));
    CHECK(warped(2, 0) == Approx(40.0));
}

TEST_CASE("a search band wider than the takes finds the same correspondence and cost as the band that just spans them", "[matching]")
{
    // 106 and 90 frames: every pair of frames lies within 105 of each other.
    const auto phi = sineWarp(9.0, 90, 2.0);
    const Take reference = warpedTake([](double u) { return u; }, 106, 4);
    const Take sample = warpedTake(phi, 90, 2);
    for (auto path : {PathMethod::Greedy, PathMethod::Optimal}) {
        MatchOptions spanning;
        spanning.path = path;
        spanning.searchBand = 105;
        auto expected = matchChannels(armHandX(reference), armHandX(sample), spanning);
        REQUIRE(expected.ok());
        for (int band : {106, 300, 16000}) {
            INFO("path " << int(path) << ", T_cmp " << band);
            MatchOptions wide = spanning;
            wide.searchBand = band;
            auto match = matchChannels(armHandX(reference), armHandX(sample), wide);
            REQUIRE(match.ok());
            CHECK(match->correspondence == expected->correspondence);
            CHECK(match->smoothWarp == expected->smoothWarp);
            CHECK(match->cost == expected->cost); // bit for bit
        }
    }
}
