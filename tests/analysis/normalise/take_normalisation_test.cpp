#include "analysis/normalise/average_take.h"
#include "analysis/normalise/coupling.h"
#include "analysis/normalise/take_normalisation.h"
#include "analysis/normalise/variance_evaluation.h"

#include "tests/analysis/normalise/synthetic_takes.h"

#include <catch2/catch.hpp>

#include <numbers>

using namespace bunraku::analysis;
using bunraku::test::sineWarp;
using bunraku::test::warpedTake;

namespace {

// A thesis-like cell: 5 takes of 106 frames, take 4 unwarped, take 1 late and with an extra
// event (the outlier), the others warped differently; mild measurement noise everywhere.
std::vector<Take> makeCell()
{
    std::vector<Take> takes;
    takes.push_back(warpedTake([](double u) { return u - 6.0 + 4.0 * std::sin(u / 30.0); }, 106, 1, 0.3, 1, 11));
    takes.push_back(warpedTake(sineWarp(7.0, 106, 1.0), 106, 2, 0.3, 0, 12));
    takes.push_back(warpedTake(sineWarp(-6.0, 106, -1.0), 106, 3, 0.3, 0, 13));
    takes.push_back(warpedTake([](double u) { return u; }, 106, 4, 0.3, 0, 14));
    takes.push_back(warpedTake(sineWarp(5.0, 106, 2.0), 106, 5, 0.3, 0, 15));
    return takes;
}

std::vector<const Take*> pointers(const std::vector<Take>& takes)
{
    std::vector<const Take*> out;
    for (const auto& take : takes) out.push_back(&take);
    return out;
}

Take puppetTake()
{
    return warpedTake([](double u) { return u; }, 106, 1);
}

} // namespace

TEST_CASE("coupling presets group the puppet channels as thesis 3.6 and 3.9 describe", "[coupling]")
{
    const Take take = puppetTake();
    CHECK(couplingFor(take, "independent")->sets.size() == 24);
    CHECK(couplingFor(take, "all")->sets.size() == 1);
    CHECK(couplingFor(take, "per-part")->sets.size() == 4);
    CHECK(couplingFor(take, "per-coordinate")->sets.size() == 6);

    const Coupling method1 = *couplingFor(take, "method1");
    CHECK(method1.sets.size() == 6 + 12); // arm+hand per coordinate; head, shoulder alone
    CHECK(method1.sets[0] == std::vector<Eigen::Index>{puppetChannel(2, Dof::X), puppetChannel(3, Dof::X)});
    CHECK(method1.names[0] == "arm+hand.x");

    const Coupling method2 = *couplingFor(take, "method2");
    REQUIRE(method2.sets.size() == 12);
    CHECK(method2.sets[0] == std::vector<Eigen::Index>{puppetChannel(0, Dof::X), puppetChannel(1, Dof::X)});
    CHECK(method2.sets[1] == std::vector<Eigen::Index>{puppetChannel(2, Dof::X), puppetChannel(3, Dof::X)});
    CHECK(method2.names[11] == "arm+hand.roll");

    // Every preset covers every channel exactly once.
    for (const auto& preset : couplingPresetNames()) {
        std::vector<int> seen(24, 0);
        const Coupling coupling = *couplingFor(take, preset);
        for (const auto& set : coupling.sets)
            for (auto c : set) ++seen[std::size_t(c)];
        INFO(preset);
        CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    }
}

TEST_CASE("explicit couplings are parsed and bad ones are clear errors", "[coupling]")
{
    const Take take = puppetTake();
    const Coupling coupling = *couplingFor(take, "arm.x+hand.x;head.yaw+head.pitch+head.roll");
    REQUIRE(coupling.sets.size() == 2 + 19);
    CHECK(coupling.sets[1].size() == 3);
    auto unknown = couplingFor(take, "arm.x+knee.x");
    REQUIRE_FALSE(unknown.ok());
    CHECK(unknown.error().code == ErrorCode::NotFound);
    CHECK(unknown.error().message.find("knee.x") != std::string::npos);
    CHECK(couplingFor(take, "arm.x+arm.x").error().message.find("twice") != std::string::npos);
    CHECK(couplingFor(take, "method3").error().message.find("method2") != std::string::npos);

    Take axis;
    axis.channels = sixDofChannels("axis");
    axis.values = Eigen::MatrixXd::Zero(10, 6);
    CHECK(couplingFor(axis, "method2").error().message.find("head") != std::string::npos);
    CHECK(couplingFor(axis, "all")->sets.size() == 1);
}

TEST_CASE("normalising a take gives coupled channels one correspondence", "[normalise]")
{
    const std::vector<Take> cell = makeCell();
    NormaliseOptions options;
    auto result = normaliseTake(cell[3], cell[1], options);
    REQUIRE(result.ok());
    CHECK(result->normalised.frameCount() == 106);
    CHECK(result->normalised.channels == cell[3].channels);
    CHECK(result->matches.size() == 12);
    for (int q = 0; q < 6; ++q) {
        CHECK(result->correspondence.col(puppetChannel(0, Dof(q))) == result->correspondence.col(puppetChannel(1, Dof(q))));
        CHECK(result->correspondence.col(puppetChannel(2, Dof(q))) == result->correspondence.col(puppetChannel(3, Dof(q))));
    }
    // x_nor(t) = x_smp(t_smp(t)).
    const Eigen::Index t = 50;
    const int u = result->correspondence(t, 7);
    CHECK(result->normalised.values(t, 7) == cell[1].values(u, 7));

    Take missing = cell[1];
    missing.channels[5].dof = "twist";
    auto error = normaliseTake(cell[3], missing, options);
    REQUIRE_FALSE(error.ok());
    CHECK(error.error().message.find("head.roll") != std::string::npos);
}

TEST_CASE("normalisation lowers every take's variance but the outlier's, as in thesis 3.8", "[normalise][evaluation]")
{
    const std::vector<Take> cell = makeCell();
    NormaliseOptions options;
    options.match.path = PathMethod::Optimal;
    auto normalised = normaliseTakes(cell[3], pointers(cell), options);
    REQUIRE(normalised.ok());
    std::vector<const Take*> normalisedTakes;
    for (const auto& one : *normalised) normalisedTakes.push_back(&one.normalised);
    auto table = varianceTable(cell[3], pointers(cell), normalisedTakes);
    REQUIRE(table.ok());
    CHECK(table->takeNames.size() == 5);
    CHECK(table->before.cols() == 24);
    CHECK(table->totalBefore[3] == 0.0); // the reference itself
    CHECK(table->totalAfter[3] == 0.0); // every frame mapped to itself: its own numbers, exactly
    CHECK((*normalised)[3].normalised.values == cell[3].values);
    for (int k : {1, 2, 4}) {
        INFO("take " << k + 1 << ": before " << table->totalBefore[k] << " after " << table->totalAfter[k]);
        CHECK(table->totalAfter[k] < 0.5 * table->totalBefore[k]);
    }
    // The outlier keeps its extra event: it stays the farthest from the reference.
    CHECK(table->totalAfter[0] > table->totalAfter.segment(1, 4).maxCoeff());
}

TEST_CASE("the average take without the outlier is a better reference than one take", "[normalise][average]")
{
    const std::vector<Take> cell = makeCell();
    AverageOptions options;
    options.baseTake = 3;
    options.excludedTakes = {0}; // "4ave"
    options.normalise.match.path = PathMethod::Optimal;
    auto average = averageTake(pointers(cell), options);
    REQUIRE(average.ok());
    CHECK(average->frameCount() == 106);
    CHECK(average->labels.takeIndex == 0);
    CHECK(average->labels.source.find("average") != std::string::npos);

    // Thesis 3.7: the average take follows the mean timing of its members. Truth: for base
    // frame t_b, t_bar = mean_k psi_k(t_b) (psi_k the true correspondence of take k), value
    // template(t_b); resampled at integer t.
    std::vector<bunraku::test::Warp> members{[](double u) { return u; }, sineWarp(7.0, 106, 1.0),
                                             sineWarp(-6.0, 106, -1.0), sineWarp(5.0, 106, 2.0)};
    std::vector<Eigen::VectorXd> psi;
    for (const auto& phi : members) psi.push_back(bunraku::test::trueCorrespondence(phi, 106, 106));
    Eigen::VectorXd meanTime = Eigen::VectorXd::Zero(106);
    for (const auto& one : psi) meanTime += one / double(psi.size());
    // Invert t_b -> t_bar at integer t by linear interpolation, then sample the template there.
    Take truth = warpedTake([](double u) { return u; }, 106, 0);
    for (Eigen::Index t = 0; t < 106; ++t) {
        double base = 0;
        if (t <= meanTime[0]) base = 0;
        else if (t >= meanTime[105]) base = 105;
        else {
            Eigen::Index k = 0;
            while (meanTime[k + 1] < double(t)) ++k;
            base = double(k) + (double(t) - meanTime[k]) / (meanTime[k + 1] - meanTime[k]);
        }
        for (int c = 0; c < 24; ++c) truth.values(t, c) = bunraku::test::templateValue(c, base);
    }
    // Interior (the ends are clamped and see the CWT's zero padding): the average is close to
    // the truth - much closer than the base take, which keeps its own timing.
    const double averageError = squaredDifference(truth, *average).sum();
    const double baseError = squaredDifference(truth, cell[3]).sum();
    INFO("average " << averageError << " base " << baseError);
    CHECK(averageError < 0.5 * baseError);

    // 5ave (all takes) lets the outlier's extra event in: farther from the 4-take truth.
    options.excludedTakes.clear();
    auto all = averageTake(pointers(cell), options);
    REQUIRE(all.ok());
    CHECK(squaredDifference(truth, *all).sum() > averageError);

    // Bad indices are clear errors.
    options.baseTake = 7;
    CHECK(averageTake(pointers(cell), options).error().message.find("base take") != std::string::npos);
    options.baseTake = 3;
    options.excludedTakes = {3};
    CHECK_FALSE(averageTake(pointers(cell), options).ok());
}

TEST_CASE("the reference suggestion avoids the late outlier (thesis 3.6.1)", "[evaluation]")
{
    const std::vector<Take> cell = makeCell();
    auto suggestion = suggestReference(pointers(cell));
    REQUIRE(suggestion.ok());
    CHECK(suggestion->outlier[0]);
    CHECK_FALSE(suggestion->outlier[3]);
    CHECK(suggestion->takeIndex != 0);
    CHECK(suggestion->startFrame[0] > suggestion->startFrame[3]);
    CHECK(suggestion->reason.find("outliers") != std::string::npos);
    CHECK_FALSE(suggestReference({}).ok());
}

TEST_CASE("a cell of 120 takes is suggested with 32 alignments a take and still finds its late outliers", "[evaluation]")
{
    // Issue 30: the outlier test compared every pair (n^2 timing alignments: 1,000 takes took
    // 92 s). Beyond 33 takes each take meets 32 others spread over the cell.
    std::vector<Take> cell;
    for (int k = 0; k < 120; ++k) {
        const bool late = k % 40 == 7; // 3 outliers: the first take's late start and its extra event
        if (late) cell.push_back(warpedTake([](double u) { return u - 6.0 + 4.0 * std::sin(u / 30.0); }, 106, k + 1, 0.3, 1, 100 + k));
        else cell.push_back(warpedTake(sineWarp(double(k % 11) - 5.0, 106, double(k % 5) - 2.0), 106, k + 1, 0.3, 0, 100 + k));
    }
    auto suggestion = suggestReference(pointers(cell));
    REQUIRE(suggestion.ok());
    CHECK(suggestion->alignments == 120u * kOutlierPeers);
    for (int k = 0; k < 120; ++k) {
        INFO("take " << k + 1);
        CHECK(suggestion->outlier[std::size_t(k)] == (k % 40 == 7));
    }
    CHECK(suggestion->takeIndex % 40 != 7);

    // Up to 33 takes every pair is still compared (the thesis's cells of 5 unchanged).
    const std::vector<Take> five = makeCell();
    auto small = suggestReference(pointers(five));
    REQUIRE(small.ok());
    CHECK(small->alignments == 5u * 4u);
}

TEST_CASE("long takes, transformed one coupling set at a time, recover a known shift", "[normalise]")
{
    // Above about 20,800 frames of 24 channels x 16 scales the features are computed a coupling
    // set at a time instead of for the whole take; both ways must find the same thing. The
    // sample is the reference 3 frames later: away from the ends, every frame maps to t + 3.
    auto wavy = [](int channel, double t) {
        double value = 0.0;
        for (int k = 1; k <= 4; ++k)
            value += std::sin(0.013 * k * (channel + 3) * t + 0.7 * k * channel) / k + 0.2 * std::cos(0.11 * k * t + channel);
        return value;
    };
    for (const Eigen::Index frames : {Eigen::Index(2000), Eigen::Index(21000)}) {
        Take reference, sample;
        for (Take* take : {&reference, &sample}) {
            take->channels = puppetChannels();
            take->labels = {"greeting", "none", take == &reference ? 1 : 2, "synthetic"};
            take->values.resize(frames, kPuppetChannelCount);
        }
        for (Eigen::Index t = 0; t < frames; ++t)
            for (int c = 0; c < kPuppetChannelCount; ++c) {
                reference.values(t, c) = wavy(c, double(t));
                sample.values(t, c) = wavy(c, double(t) - 3.0);
            }
        NormaliseOptions options;
        options.match.path = PathMethod::Optimal;
        auto result = normaliseTake(reference, sample, options);
        REQUIRE(result.ok());
        INFO(frames << " frames");
        CHECK(result->matches.size() == 12);
        int wrong = 0;
        for (Eigen::Index t = 100; t < frames - 100; ++t)
            for (int c = 0; c < kPuppetChannelCount; ++c) wrong += result->correspondence(t, c) != t + 3;
        CHECK(wrong == 0);
        CHECK(result->normalised.values.middleRows(100, frames - 200).isApprox(reference.values.middleRows(100, frames - 200)));
    }
}

TEST_CASE("a take 35 percent shorter is normalised by a global time scale then the local matching", "[normalise][lengths]")
{
    // The reference: 106 frames; the sample: the same motion hurried into 69 frames, with a
    // local wobble on top of the constant scale (138 -> 90 frames is the same ratio).
    const Take reference = warpedTake([](double u) { return u; }, 106, 4, 0.3, 0, 21);
    const double scale = 105.0 / 68.0;
    const auto phi = [&](double u) { return scale * u + 4.0 * std::sin(std::numbers::pi * u / 68.0); };
    const Take sample = warpedTake(phi, 69, 2, 0.3, 0, 22);
    const Eigen::VectorXd truth = bunraku::test::trueCorrespondence(phi, 106, 69);
    NormaliseOptions options;
    options.match.path = PathMethod::Optimal;
    options.match.timeScaling = TimeScaling::None; // the thesis's band alone: no admissible path
    CHECK_FALSE(normaliseTake(reference, sample, options).ok());
    for (TimeScaling scaling : {TimeScaling::Auto, TimeScaling::Global}) {
        options.match.timeScaling = scaling;
        auto normalised = normaliseTake(reference, sample, options);
        INFO((normalised.ok() ? std::string() : normalised.error().message));
        REQUIRE(normalised.ok());
        CHECK(normalised->normalised.frameCount() == 106);
        // correspondences are in the sample's frames, monotone, and near the truth
        double error = 0.0;
        for (Eigen::Index c = 0; c < normalised->correspondence.cols(); ++c) {
            for (Eigen::Index t = 1; t < 106; ++t) CHECK(normalised->correspondence(t, c) >= normalised->correspondence(t - 1, c));
            error += (normalised->correspondence.col(c).cast<double>() - truth).cwiseAbs().segment(10, 86).mean();
        }
        error /= double(normalised->correspondence.cols());
        INFO("mean |error| " << error << " sample frames");
        CHECK(error < 1.0);
        CHECK(normalised->correspondence.maxCoeff() <= 68);
        // the variance against the reference falls well below that of the sample padded in place
        const double before = squaredDifference(reference, sample).sum();
        const double after = squaredDifference(reference, normalised->normalised).sum();
        CHECK(after < 0.1 * before);
    }
    // equal lengths (and small differences) keep the thesis's matching unchanged
    CHECK(globalTimeScale(options.match, 106, 106) == 1.0);
    options.match.timeScaling = TimeScaling::Auto;
    CHECK(globalTimeScale(options.match, 106, 100) == 1.0); // within half of T_cmp = 20
    CHECK(globalTimeScale(options.match, 106, 69) == Approx(68.0 / 105.0));
}
