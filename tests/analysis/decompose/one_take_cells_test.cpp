// KM2O on corpora whose cells hold one take (docs/KM2O.md, "Cells with one take"): a one-take
// cell's gamma_+ and V_+ are those of the pooled diff series of its function's cells with
// K >= 2; a function without such a cell keeps its least-squares components.
#include "analysis/decompose/arma.h"
#include "analysis/decompose/exogenous.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/km2o_experiment.h"
#include "analysis/decompose/least_squares.h"
#include "tests/analysis/decompose/test_corpus.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace bunraku::analysis;

namespace {

/// The ARX simulation of eq. 4.39 (T = 300, K = 5) with cell `single` of every function cut to
/// its first take.
ArxSimulation withOneTakeCell(std::size_t single)
{
    ArxSimulationOptions options;
    options.finalTime = 300;
    options.seed = 11;
    ArxSimulation sim = simulateArx(options);
    for (auto& cells : sim.cells) cells[single] = Eigen::MatrixXd(cells[single].leftCols(1));
    return sim;
}

/// The corpus without the takes `drop` says yes to.
template <class Drop> Corpus without(Corpus corpus, Drop drop)
{
    std::erase_if(corpus.takes, [&](const Take& take) { return drop(take.labels); });
    return corpus;
}

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

} // namespace

TEST_CASE("a one-take cell's KM2O data are the direct Yule-Walker solution of the pooled diff series", "[km2o][one-take]")
{
    const ArxSimulation sim = withOneTakeCell(2);
    const auto& cells = sim.cells[0];
    constexpr int m = 4;
    ExogenousOptions reading = recommendedKm2oReading();
    reading.correlationLength = m;
    auto est = estimateExogenousInputs(cells, reading);
    REQUIRE(est.ok());

    // The peer: R_pool = (K_1 R_diff^1 + K_2 R_diff^2) / ((K_1 - 1) + (K_2 - 1)) by hand, solved directly.
    Eigen::VectorXd pooled = Eigen::VectorXd::Zero(m + 1);
    for (std::size_t j = 0; j < 2; ++j) {
        const Eigen::MatrixXd diff = cells[j].colwise() - cells[j].rowwise().mean();
        auto r = biasedAutocovariance(diff, m);
        REQUIRE(r.ok());
        pooled += 5.0 * *r;
    }
    pooled /= 8.0;
    const auto& langevin = est->langevin[2];
    for (int n = 1; n <= m; ++n) {
        auto direct = yuleWalkerPredictor(pooled, n);
        REQUIRE(direct.ok());
        for (int s = 0; s < n; ++s) CHECK(langevin.gammaPlus(n, s) == Approx(-direct->coefficients(n - s - 1)).epsilon(1e-9));
        CHECK(langevin.varianceForward(n) == Approx(direct->innovationVariance).epsilon(1e-9)); // no K/(K-1) again
    }
    CHECK(langevin.varianceForward(0) == Approx(pooled(0)).epsilon(1e-12));
    // The dynamics of eq. 4.39 (a_1 = 1/2, a_2 = 1/3 for function 1) from the pooled series.
    CHECK(langevin.gammaPlus(2, 1) == Approx(0.5).margin(0.08));
    CHECK(langevin.gammaPlus(2, 0) == Approx(1.0 / 3.0).margin(0.08));

    // The cells with five takes keep their own gamma and V_+: as with all cells of five takes.
    ArxSimulationOptions full;
    full.finalTime = 300;
    full.seed = 11;
    auto all = estimateExogenousInputs(simulateArx(full).cells[0], reading);
    REQUIRE(all.ok());
    for (std::size_t j = 0; j < 2; ++j) {
        CHECK(est->langevin[j].gammaPlus == all->langevin[j].gammaPlus);
        CHECK(est->langevin[j].varianceForward == all->langevin[j].varianceForward);
    }
}

TEST_CASE("the inputs of one-take cells of the ARX simulation are recovered as well as with five takes", "[km2o][one-take]")
{
    ExogenousOptions reading = recommendedKm2oReading();
    reading.correlationLength = 4;
    ArxSimulationOptions fullOptions;
    fullOptions.seed = 11;
    const ArxSimulation full = simulateArx(fullOptions);
    for (std::size_t single : {std::size_t(0), std::size_t(2)}) { // the neutral cell, an emotional one
        const ArxSimulation sim = withOneTakeCell(single);
        for (std::size_t i = 0; i < 2; ++i) {
            INFO("function " << i + 1 << ", one-take cell " << single + 1);
            auto est = estimateExogenousInputs(sim.cells[i], reading);
            auto reference = estimateExogenousInputs(full.cells[i], reading);
            REQUIRE(est.ok());
            REQUIRE(reference.ok());
            const double u = relativeError(est->functionInput, sim.functionInputs[i]);
            CHECK(u < 0.03);
            CHECK(u < 2.0 * relativeError(reference->functionInput, full.functionInputs[i]) + 0.005);
            for (int j = 1; j < 3; ++j) {
                const double v = relativeError(est->emotionInputs.col(j), sim.emotionInputs[i][std::size_t(j)]);
                CHECK(v < 0.03);
                CHECK(v < 2.0 * relativeError(reference->emotionInputs.col(j), full.emotionInputs[i][std::size_t(j)]) + 0.005);
            }
        }
    }
}

TEST_CASE("the input estimate needs one cell with two takes and says so", "[km2o][one-take]")
{
    ArxSimulation sim = simulateArx({});
    for (auto& cell : sim.cells[0]) cell = Eigen::MatrixXd(cell.leftCols(1));
    auto est = estimateExogenousInputs(sim.cells[0], {});
    REQUIRE_FALSE(est.ok());
    CHECK(est.error().message.find("K >= 2") != std::string::npos);
}

TEST_CASE("KM2O on a corpus mixing one-take and multi-take cells: pooled, per function, or least squares", "[km2o][one-take]")
{
    const auto known = bunraku::test::knownComponentsCorpus(106, 5, 2, 0.3);
    // bow/warm keeps one take; every cell of walk keeps one.
    const Corpus mixed = without(known.corpus, [](const TakeLabels& l) {
        return l.takeIndex > 1 && (l.function == "walk" || l.emotion == "warm");
    });
    Km2oDecompositionOptions options;
    options.correlationLength = 2;
    auto result = decomposeKm2o(mixed, options);
    REQUIRE(result.ok());
    const Decomposition& d = result->components;
    REQUIRE(result->cells.size() == 6);
    for (std::size_t c = 0; c < d.emotions.size(); ++c) {
        const auto& cell = result->cells[c];
        CAPTURE(cell.function, cell.emotion);
        CHECK(cell.function == d.emotions[c].function);
        CHECK(cell.emotion == d.emotions[c].emotion);
        const bool walk = cell.function == "walk";
        const bool single = walk || cell.emotion == "warm";
        CHECK(cell.takes == (single ? 1 : 5));
        CHECK(cell.source == (walk ? Km2oCellSource::LeastSquares : single ? Km2oCellSource::Pooled : Km2oCellSource::OwnTakes));
        // P only for the KM2O cells; the mean is theirs.
        for (Eigen::Index ch = 0; ch < 2; ++ch) CHECK(std::isfinite(result->cellErrorPercent(ch, Eigen::Index(c))) == !walk);
    }
    CHECK(result->estimable());
    CHECK(result->meanCellErrorPercent == Approx(result->cellErrorPercent.leftCols(3).mean()));
    REQUIRE(result->notes.size() == 2);
    CHECK(result->notes[0].find("bow/warm has 1 take") != std::string::npos);
    CHECK(result->notes[0].find("bow/calm (5 takes), bow/cold (5 takes)") != std::string::npos);
    CHECK(result->notes[1].find("function 'walk': KM2O not estimable") != std::string::npos);
    CHECK(result->notes[1].find("walk/calm, walk/warm, walk/cold have 1 take each") != std::string::npos);
    CHECK(result->notes[1].find("K >= 2") != std::string::npos);
    CHECK(result->outcome().find("KM2O for 3 cells (1 with one take") != std::string::npos);
    CHECK(result->outcome().find("least squares for 3 cells") != std::string::npos);

    // walk: exactly its least-squares components.
    auto leastSquares = decomposeLeastSquares(mixed);
    REQUIRE(leastSquares.ok());
    CHECK(d.function("walk")->values == leastSquares->function("walk")->values);
    for (const char* emotion : {"warm", "cold"})
        CHECK(d.emotion("walk", emotion)->values == leastSquares->emotion("walk", emotion)->values);

    // bow's cells of five takes: as without the one-take cell (the Markov estimate is square).
    auto peer = decomposeKm2o(without(known.corpus, [](const TakeLabels& l) { return l.emotion == "warm" && l.function == "bow"; }),
                              options);
    REQUIRE(peer.ok());
    const Decomposition& p = peer->components;
    CHECK(relativeDifference(d.function("bow")->values, p.function("bow")->values) < 1e-12);
    CHECK(relativeDifference(d.emotion("bow", "cold")->values, p.emotion("bow", "cold")->values) < 1e-12);

    // bow/warm from its one take: the truth up to that take's own fluctuation (0.27 white per
    // sample against z of RMS 2.1), as least squares's z (the take minus the neutral mean): KM2O
    // 0.157, least squares 0.129 here (KM2O adds the sampling error of the pooled gamma).
    const Eigen::MatrixXd& zTrue = known.z[0][1];
    const double zError = relativeDifference(d.emotion("bow", "warm")->values, zTrue);
    const double lsError = relativeDifference(leastSquares->emotion("bow", "warm")->values, zTrue);
    INFO("bow/warm z relative error: KM2O " << zError << ", least squares " << lsError);
    CHECK(zError < 0.2);
    CHECK(zError < 1.3 * lsError);
    CHECK(result->cellErrorPercent.col(1).maxCoeff() < 1.0); // y + z reconstructs the take

    // No fluctuation analysis of one-take cells: their ARMA rows are empty.
    auto table = armaCellTable(d, 0, 2, 2);
    REQUIRE(table.ok());
    for (const auto& row : *table) {
        CAPTURE(row.function, row.emotion);
        CHECK(row.takes == (row.function == "walk" || row.emotion == "warm" ? 0 : 5));
    }
}

TEST_CASE("KM2O on a corpus of one take per cell is not estimable and gives the least-squares components", "[km2o][one-take]")
{
    const auto known = bunraku::test::knownComponentsCorpus(106, 5, 2, 0.3);
    const Corpus single = without(known.corpus, [](const TakeLabels& l) { return l.takeIndex > 1; });
    auto result = decomposeKm2o(single);
    REQUIRE(result.ok());
    CHECK_FALSE(result->estimable());
    CHECK(result->correlationLength == 0);
    CHECK(result->candidateLengths.empty());
    CHECK(result->meanErrorPercent.empty());
    CHECK(std::isnan(result->meanCellErrorPercent));
    CHECK(result->cellErrorPercent.rows() == 2);
    CHECK(result->cellErrorPercent.cols() == 6);
    CHECK(result->cellErrorPercent.array().isNaN().all());
    CHECK(result->outcome() == "KM2O not estimable (no cell has 2 takes): y, z by least squares for all 6 cells");
    REQUIRE(result->notes.size() == 2);
    CHECK(result->notes[0].find("bow/calm, bow/warm, bow/cold have 1 take each") != std::string::npos);
    for (const auto& cell : result->cells) CHECK(cell.source == Km2oCellSource::LeastSquares);

    auto leastSquares = decomposeLeastSquares(single);
    REQUIRE(leastSquares.ok());
    const Decomposition& d = result->components;
    for (std::size_t i = 0; i < d.functions.size(); ++i) CHECK(d.functions[i].values == leastSquares->functions[i].values);
    for (std::size_t c = 0; c < d.emotions.size(); ++c) CHECK(d.emotions[c].values == leastSquares->emotions[c].values);
    for (const auto& eta : d.fluctuations) CHECK(eta.values.cwiseAbs().maxCoeff() == 0.0); // a take minus its own mean
    // With one take, y is the neutral take and z the emotional take minus it (eq. 4.8).
    const Take* calm = single.find("bow", "calm", 1);
    const Take* cold = single.find("bow", "cold", 1);
    REQUIRE(calm);
    REQUIRE(cold);
    CHECK(d.function("bow")->values == calm->values);
    CHECK((d.emotion("bow", "cold")->values - (cold->values - calm->values)).cwiseAbs().maxCoeff() == 0.0);

    // A correlation length outside 1..M_max is still refused.
    Km2oDecompositionOptions options;
    options.correlationLength = 30;
    CHECK_FALSE(decomposeKm2o(single, options).ok());
}
