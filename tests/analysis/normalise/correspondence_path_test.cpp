#include "analysis/normalise/correspondence_path.h"
#include "analysis/normalise/feature_matching.h"
#include "analysis/wavelet/simd_level.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

using namespace bunraku::analysis;

namespace {

// A band whose cell (t, u) costs cost(t, u); cells outside the sample are left at +inf.
BandCost makeBand(Eigen::Index referenceFrames, Eigen::Index sampleFrames, int searchBand,
                  const std::function<double(Eigen::Index, Eigen::Index)>& cost)
{
    BandCost band;
    band.searchBand = searchBand;
    band.sampleFrames = sampleFrames;
    band.cost = Eigen::MatrixXd::Constant(referenceFrames, 2 * searchBand + 1, std::numeric_limits<double>::infinity());
    for (Eigen::Index t = 0; t < referenceFrames; ++t)
        for (Eigen::Index j = 0; j < band.cost.cols(); ++j) {
            const Eigen::Index u = t - searchBand + j;
            if (u >= 0 && u < sampleFrames) band.cost(t, j) = cost(t, u);
        }
    return band;
}

bool nonDecreasingInBand(const Eigen::VectorXi& path, int searchBand, Eigen::Index sampleFrames)
{
    for (Eigen::Index t = 0; t < path.size(); ++t) {
        if (path[t] < 0 || path[t] >= sampleFrames || std::abs(path[t] - t) > searchBand) return false;
        if (t > 0 && path[t] < path[t - 1]) return false;
    }
    return true;
}

} // namespace

TEST_CASE("greedy reproduces the plateau-then-jump of thesis Table 3.3", "[path]")
{
    // Every frame's best sample frame is itself, except frame 96, whose best is 102 (a look-alike
    // event), and frames 103..105, whose best is 106. The thesis's forward scan may not go back
    // after 96 -> 102, so 96..102 all take 102, then 103 and 104 jump to 106 (Table 3.3).
    auto target = [](Eigen::Index t) -> Eigen::Index { return t >= 103 && t <= 105 ? 106 : t; };
    const BandCost band = makeBand(110, 110, 20, [&](Eigen::Index t, Eigen::Index u) {
        if (t == 96) return u == 102 ? 0.0 : 1.0;
        return double(std::abs(u - target(t)));
    });
    const Eigen::VectorXi greedy = greedyPath(band);
    const std::vector<int> table33{102, 102, 102, 102, 102, 102, 102, 106, 106};
    for (int i = 0; i < 9; ++i) CHECK(greedy[96 + i] == table33[std::size_t(i)]);
    CHECK(greedy[95] == 95);
    CHECK(nonDecreasingInBand(greedy, 20, 110));

    // The optimal path does not get trapped: it pays 1 at frame 96 and follows the diagonal.
    const Eigen::VectorXi optimal = optimalPath(band);
    CHECK(optimal[97] == 97);
    CHECK(optimal[101] == 101);
    CHECK(pathCost(band, optimal) < pathCost(band, greedy));
}

TEST_CASE("the optimal path never costs more than the greedy one", "[path]")
{
    std::mt19937 random(42);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::Index referenceFrames = 5 + Eigen::Index(uniform(random) * 60);
        const Eigen::Index sampleFrames = std::max<Eigen::Index>(1, referenceFrames + Eigen::Index(uniform(random) * 20) - 8);
        const int searchBand = 1 + int(uniform(random) * 12);
        if (referenceFrames - 1 - searchBand > sampleFrames - 1) continue;
        const BandCost band = makeBand(referenceFrames, sampleFrames, searchBand, [&](Eigen::Index, Eigen::Index) { return uniform(random); });
        const Eigen::VectorXi greedy = greedyPath(band);
        const Eigen::VectorXi optimal = optimalPath(band);
        INFO("trial " << trial);
        REQUIRE(nonDecreasingInBand(greedy, searchBand, sampleFrames));
        REQUIRE(nonDecreasingInBand(optimal, searchBand, sampleFrames));
        CHECK(pathCost(band, optimal) <= pathCost(band, greedy) + 1e-12);
    }
}

TEST_CASE("the optimal path is the cheapest of all non-decreasing paths (exhaustive check)", "[path]")
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int trial = 0; trial < 30; ++trial) {
        const Eigen::Index frames = 6;
        const int searchBand = 2;
        const BandCost band = makeBand(frames, frames, searchBand, [&](Eigen::Index, Eigen::Index) { return uniform(random); });
        double best = std::numeric_limits<double>::infinity();
        Eigen::VectorXi path(frames);
        std::function<void(Eigen::Index)> search = [&](Eigen::Index t) {
            if (t == frames) {
                best = std::min(best, pathCost(band, path));
                return;
            }
            for (Eigen::Index u = 0; u < frames; ++u) {
                path[t] = int(u);
                search(t + 1);
            }
        };
        search(0);
        CHECK(pathCost(band, optimalPath(band)) == Approx(best).epsilon(1e-12));
    }
}

TEST_CASE("the smooth warp is monotone and passes through the centre of every run", "[path]")
{
    Eigen::VectorXi correspondence(10);
    correspondence << 0, 2, 2, 2, 3, 6, 6, 7, 9, 9;
    const Eigen::VectorXd warp = smoothWarp(correspondence);
    for (Eigen::Index t = 1; t < warp.size(); ++t) CHECK(warp[t] >= warp[t - 1]);
    CHECK(warp[2] == Approx(2.0)); // centre of the run 1..3
    CHECK(warp[4] == Approx(3.0));
    CHECK(warp[1] < 2.0);          // spread linearly towards the previous run
    CHECK(warp[3] > 2.0);
    CHECK(warp[5] == Approx(5.0)); // halfway between run centres 4 (3) and 5.5 (6)
    CHECK(warp[0] == 0.0);
    CHECK(warp[9] == Approx(9.0));
}

TEST_CASE("the matcher at every kernel level equals the paths through the full window-cost band", "[path][simd]")
{
    // Window costs written out from their definition (thesis eq. 3.21; window indices beyond the
    // ends replicate the edge frame), then both paths; the streamed matcher (running window
    // sums, skipped entries for greedy) must choose the same frames.
    std::mt19937 random(3);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Index referenceFrames = 40 + trial * 13;
        const Eigen::Index sampleFrames = referenceFrames + (trial % 5) - 2;
        const int tau = trial % 4;
        const int searchBand = 3 + trial % 7;
        FeatureMatrix reference(referenceFrames, 5), sample(sampleFrames, 5);
        for (Eigen::Index i = 0; i < reference.size(); ++i) reference.data()[i] = normal(random);
        for (Eigen::Index i = 0; i < sample.size(); ++i) sample.data()[i] = normal(random);
        auto clampRow = [](Eigen::Index i, Eigen::Index n) { return std::clamp<Eigen::Index>(i, 0, n - 1); };
        const BandCost band = makeBand(referenceFrames, sampleFrames, searchBand, [&](Eigen::Index t, Eigen::Index u) {
            double sum = 0.0;
            for (int s = -tau; s <= tau; ++s)
                sum += (reference.row(clampRow(t + s, referenceFrames)) - sample.row(clampRow(u + s, sampleFrames))).squaredNorm();
            return sum;
        });
        for (auto path : {PathMethod::Greedy, PathMethod::Optimal}) {
            Eigen::VectorXi expected;
            {
                ScopedSimdLevel plain(SimdLevel::Plain);
                expected = path == PathMethod::Greedy ? greedyPath(band) : optimalPath(band);
            }
            for (SimdLevel level : runnableSimdLevels()) {
                ScopedSimdLevel scope(level);
                auto streamed = matchFeatures(reference, sample, {tau, searchBand, path});
                REQUIRE(streamed.ok());
                INFO("trial " << trial << (path == PathMethod::Greedy ? " greedy" : " optimal") << ", kernels " << simdLevelName(level));
                CHECK(streamed->correspondence == expected);
                CHECK(streamed->cost == Approx(pathCost(band, expected)).epsilon(1e-9));
                CHECK((path == PathMethod::Greedy ? greedyPath(band) : optimalPath(band)) == expected);
            }
        }
    }
}

TEST_CASE("every kernel level gives a plain dynamic programme's path and cost on random features", "[path][simd]")
{
    // Reference: window costs from the definition and an O(frames x band^2) dynamic programme
    // with explicit back-pointers (ties to the earliest sample frame), independent of
    // PathBuilder. Sizes span several 96-frame restarts of the window sums and, in the last
    // trial, two 480-frame tiles of feature copies; feature counts that are not multiples of 4,
    // up to a coupling set's 32; bands narrower than a vector and wider than 64 columns a
    // quarter (several words of drop bits per quarter of the interleaved rows). Every kernel
    // level this CPU runs.
    std::mt19937 random(17);
    std::normal_distribution<double> normal;
    const double infinity = std::numeric_limits<double>::infinity();
    for (int trial = 0; trial < 9; ++trial) {
        const Eigen::Index referenceFrames = trial < 8 ? 90 + trial * 47 : 530;
        const Eigen::Index sampleFrames = referenceFrames + (trial % 3) * 9 - 4;
        const int tau = trial < 8 ? trial % 6 : 4;
        const int searchBand = trial < 8 ? 5 + trial * 9 : 140;
        const Eigen::Index features = trial < 8 ? 1 + trial * 5 : 32;
        FeatureMatrix reference(referenceFrames, features), sample(sampleFrames, features);
        for (Eigen::Index i = 0; i < reference.size(); ++i) reference.data()[i] = normal(random);
        for (Eigen::Index i = 0; i < sample.size(); ++i) sample.data()[i] = normal(random);
        auto clampRow = [](Eigen::Index i, Eigen::Index n) { return std::clamp<Eigen::Index>(i, 0, n - 1); };
        auto cost = [&](Eigen::Index t, Eigen::Index u) {
            double sum = 0.0;
            for (int s = -tau; s <= tau; ++s)
                sum += (reference.row(clampRow(t + s, referenceFrames)) - sample.row(clampRow(u + s, sampleFrames))).squaredNorm();
            return sum;
        };
        auto admissible = [&](Eigen::Index t, Eigen::Index u) { return u >= 0 && u < sampleFrames && std::abs(u - t) <= searchBand; };
        Eigen::MatrixXd total = Eigen::MatrixXd::Constant(referenceFrames, sampleFrames, infinity);
        Eigen::MatrixXi back = Eigen::MatrixXi::Constant(referenceFrames, sampleFrames, -1);
        for (Eigen::Index t = 0; t < referenceFrames; ++t)
            for (Eigen::Index u = 0; u < sampleFrames; ++u) {
                if (!admissible(t, u)) continue;
                if (t == 0) {
                    total(t, u) = cost(t, u);
                    continue;
                }
                double previous = infinity;
                for (Eigen::Index v = 0; v <= u; ++v)
                    if (total(t - 1, v) < previous) {
                        previous = total(t - 1, v);
                        back(t, u) = int(v);
                    }
                if (back(t, u) >= 0) total(t, u) = cost(t, u) + previous;
            }
        Eigen::Index best = 0;
        for (Eigen::Index u = 1; u < sampleFrames; ++u)
            if (total(referenceFrames - 1, u) < total(referenceFrames - 1, best)) best = u;
        Eigen::VectorXi expected(referenceFrames);
        for (Eigen::Index t = referenceFrames - 1; t >= 0; --t) {
            expected[t] = int(best);
            if (t > 0) best = back(t, best);
        }
        // Greedy from its definition: the cheapest admissible frame at or after the previous choice.
        Eigen::VectorXi greedy(referenceFrames);
        double greedyCost = 0.0;
        for (Eigen::Index t = 0; t < referenceFrames; ++t) {
            Eigen::Index choice = -1;
            for (Eigen::Index u = t > 0 ? greedy[t - 1] : 0; u < sampleFrames; ++u)
                if (admissible(t, u) && (choice < 0 || cost(t, u) < cost(t, choice))) choice = u;
            greedy[t] = int(choice);
            greedyCost += cost(t, choice);
        }
        INFO("trial " << trial << ": " << referenceFrames << " x " << sampleFrames << " frames, " << features
                      << " features, tau " << tau << ", T_cmp " << searchBand);
        for (SimdLevel level : runnableSimdLevels()) {
            ScopedSimdLevel scope(level);
            INFO("kernels " << simdLevelName(level));
            auto optimal = matchFeatures(reference, sample, {tau, searchBand, PathMethod::Optimal});
            REQUIRE(optimal.ok());
            CHECK(optimal->correspondence == expected);
            CHECK(optimal->cost == Approx(total(referenceFrames - 1, expected[referenceFrames - 1])).epsilon(1e-9));
            auto scanned = matchFeatures(reference, sample, {tau, searchBand, PathMethod::Greedy});
            REQUIRE(scanned.ok());
            CHECK(scanned->correspondence == greedy);
            CHECK(scanned->cost == Approx(greedyCost).epsilon(1e-9));
        }
    }
}

TEST_CASE("column-major features and a column subset give the row-major matcher's path", "[path]")
{
    // Column-major series are read in place away from the takes' ends and copied near them:
    // takes of many tiles, bands narrow and wide, a subset of columns in a shuffled order,
    // compared with the same columns copied into a row-major matrix (itself checked against a
    // plain dynamic programme above).
    std::mt19937 random(29);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 6; ++trial) {
        const Eigen::Index referenceFrames = 700 + trial * 151;
        const Eigen::Index sampleFrames = referenceFrames + (trial % 3) * 17 - 8;
        const int tau = 1 + trial % 5;
        const int searchBand = trial % 2 == 0 ? 12 + trial : 70 + 11 * trial;
        FeatureSeries reference(referenceFrames, 13), sample(sampleFrames, 13);
        for (Eigen::Index i = 0; i < reference.size(); ++i) reference.data()[i] = normal(random);
        for (Eigen::Index i = 0; i < sample.size(); ++i) sample.data()[i] = normal(random);
        std::vector<Eigen::Index> columns{11, 3, 4, 0, 9, 12, 6};
        if (trial == 5) columns = allColumns(13);
        FeatureMatrix referenceRows(referenceFrames, Eigen::Index(columns.size()));
        FeatureMatrix sampleRows(sampleFrames, Eigen::Index(columns.size()));
        for (std::size_t k = 0; k < columns.size(); ++k) {
            referenceRows.col(Eigen::Index(k)) = reference.col(columns[k]);
            sampleRows.col(Eigen::Index(k)) = sample.col(columns[k]);
        }
        INFO("trial " << trial << ": T_cmp " << searchBand << ", tau " << tau);
        for (auto path : {PathMethod::Optimal, PathMethod::Greedy}) {
            auto series = matchFeatures(reference, sample, columns, {tau, searchBand, path});
            auto rows = matchFeatures(referenceRows, sampleRows, {tau, searchBand, path});
            REQUIRE(series.ok());
            REQUIRE(rows.ok());
            CHECK(series->correspondence == rows->correspondence);
            CHECK(series->cost == Approx(rows->cost).epsilon(1e-12));
        }
    }
    FeatureSeries small(50, 3);
    small.setRandom();
    auto outside = matchFeatures(small, small, std::vector<Eigen::Index>{0, 3}, {2, 5, PathMethod::Optimal});
    REQUIRE_FALSE(outside.ok());
    CHECK(outside.error().message.find("feature column 3") != std::string::npos);
    REQUIRE_FALSE(matchFeatures(small, small, std::vector<Eigen::Index>{}, {2, 5, PathMethod::Optimal}).ok());
}
