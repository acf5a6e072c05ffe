#include "analysis/decompose/exogenous.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/km2o_experiment.h"
#include "tests/analysis/decompose/exogenous_reference.h"
#include "tests/analysis/decompose/test_corpus.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

using namespace bunraku::analysis;

TEST_CASE("KM2O identification recovers the known inputs of a simulated ARX series")
{
    ArxSimulationOptions simOptions;
    simOptions.finalTime = 300;
    simOptions.seed = 11;
    const ArxSimulation sim = simulateArx(simOptions);
    ExogenousOptions reading = recommendedKm2oReading();
    reading.correlationLength = 4;
    for (std::size_t i = 0; i < 2; ++i) {
        auto est = estimateExogenousInputs(sim.cells[i], reading);
        REQUIRE(est.ok());
        INFO("function " << i + 1);
        CHECK(relativeError(est->functionInput, sim.functionInputs[i]) < 0.03);
        for (int j = 1; j < 3; ++j) CHECK(relativeError(est->emotionInputs.col(j), sim.emotionInputs[i][std::size_t(j)]) < 0.03);
        CHECK(est->emotionInputs.col(0).cwiseAbs().maxCoeff() == 0.0);
        // The AR(2) data gamma_+(2, .) approximate the simulation's a_1, a_2 (eq. 4.37).
        const double a1 = i == 0 ? 0.5 : 0.25;
        const double a2 = i == 0 ? 1.0 / 3.0 : 0.2;
        CHECK(est->langevin[0].gammaPlus(2, 1) == Approx(a1).margin(0.08));
        CHECK(est->langevin[0].gammaPlus(2, 0) == Approx(a2).margin(0.08));
    }
}

TEST_CASE("with M = 0 the Markov estimate reduces to the least-squares cell means")
{
    const ArxSimulation sim = simulateArx({});
    ExogenousOptions reading;
    reading.correlationLength = 0;
    auto est = estimateExogenousInputs(sim.cells[0], reading);
    REQUIRE(est.ok());
    CHECK((est->functionInput - est->cellMeans.col(0)).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((est->emotionInputs.col(2) - (est->cellMeans.col(2) - est->cellMeans.col(0))).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((est->functionComponent - est->cellMeans.col(0)).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("the thesis range of initial times leaves the last frame without an estimate")
{
    const ArxSimulation sim = simulateArx({});
    ExogenousOptions reading;
    reading.correlationLength = 3;
    reading.initialTimes = InitialTimeRange::Thesis;
    auto est = estimateExogenousInputs(sim.cells[1], reading);
    REQUIRE(est.ok());
    const Eigen::Index last = est->functionInput.size() - 1;
    CHECK(std::isnan(est->functionInput(last)));
    CHECK(est->estimateCount(last) == 0);
    CHECK(est->estimateCount(last - 1) == 1);
    CHECK(std::isfinite(relativeError(est->functionInput, sim.functionInputs[1])));
}

TEST_CASE("a correlation length above M_max is rejected by the input estimate with the limit named")
{
    const ArxSimulation sim = simulateArx({});
    ExogenousOptions reading;
    reading.correlationLength = 52; // M_max = 51 for T = 300
    auto est = estimateExogenousInputs(sim.cells[0], reading);
    REQUIRE_FALSE(est.ok());
    CHECK(est.error().message.find("M_max = 51") != std::string::npos);
}

TEST_CASE("the km2o experiment has the thesis's shape: T = 1000 below T = 300, T = 300 minimal at moderate M")
{
    Km2oExperimentOptions options;
    options.seeds = 2;
    options.finalTime = 300;
    auto short300 = runKm2oExperiment(options);
    options.finalTime = 1000;
    auto long1000 = runKm2oExperiment(options);
    REQUIRE(short300.ok());
    REQUIRE(long1000.ok());
    REQUIRE(short300->correlationLengths.size() == 18);
    for (std::size_t m = 0; m < 18; ++m) {
        INFO("M = " << short300->correlationLengths[m]);
        CHECK(long1000->errorPercent[m] < short300->errorPercent[m]);
        // T = 300 magnitudes near the thesis's Table 4.4 (within a factor of 2)
        CHECK(short300->errorPercent[m] < 2.0 * short300->thesisErrorPercent[m]);
        CHECK(short300->errorPercent[m] > 0.5 * short300->thesisErrorPercent[m]);
    }
    const auto& p = short300->errorPercent;
    const auto best = std::min_element(p.begin(), p.end()) - p.begin();
    const int bestM = short300->correlationLengths[std::size_t(best)];
    CHECK(bestM >= 4);
    CHECK(bestM <= 8);
    CHECK(p.back() > 1.5 * p[std::size_t(best)]); // rises again for long correlation lengths
    CHECK(long1000->thesisErrorPercent.front() == Approx(0.1)); // the 0.1 % unit converted
}

TEST_CASE("the KM2O corpus decomposition reconstructs the takes and reports P per cell")
{
    const auto known = bunraku::test::knownComponentsCorpus(106, 5, 2, 0.3);
    Km2oDecompositionOptions options;
    options.lastCandidateLength = 6;
    auto result = decomposeKm2o(known.corpus, options);
    REQUIRE(result.ok());
    CHECK(result->candidateLengths.size() == 6);
    CHECK(result->correlationLength >= 1);
    CHECK(result->correlationLength <= 6);
    CHECK(result->cellErrorPercent.rows() == 2);
    CHECK(result->cellErrorPercent.cols() == 6);
    const auto& d = result->components;
    // white fluctuations: gamma ~ 0, so y, z stay close to the true components
    for (std::size_t i = 0; i < 2; ++i) {
        const double rel = (d.functions[i].values - known.y[i]).norm() / known.y[i].norm();
        CHECK(rel < 0.05);
    }
    for (const auto& eta : d.fluctuations) {
        const Take* take = known.corpus.find(eta.labels.function, eta.labels.emotion, eta.labels.takeIndex);
        const auto* z = d.emotion(eta.labels.function, eta.labels.emotion);
        CHECK((d.function(eta.labels.function)->values + z->values + eta.values - take->values).cwiseAbs().maxCoeff() < 1e-9);
    }
    CHECK(result->meanCellErrorPercent == Approx(result->cellErrorPercent.mean()));
}

TEST_CASE("the KM2O corpus decomposition rejects M above M_max")
{
    auto known = bunraku::test::knownComponentsCorpus(106, 2, 1);
    Km2oDecompositionOptions options;
    options.correlationLength = 30;
    auto tooLong = decomposeKm2o(known.corpus, options);
    REQUIRE_FALSE(tooLong.ok());
    CHECK(tooLong.error().message.find("M_max = 29") != std::string::npos);
    // Cells with one take are no error (one_take_cells_test.cpp), M_max still is.
    known.corpus.takes.erase(known.corpus.takes.begin() + 1); // bow/calm keeps one take
    auto single = decomposeKm2o(known.corpus, options);
    REQUIRE_FALSE(single.ok());
    CHECK(single.error().message.find("M_max = 29") != std::string::npos);
}

namespace {

/// Equal shapes and equal bits (NaN where the other has the same NaN).
template <class A, class B> bool sameBits(const A& a, const B& b)
{
    using Scalar = typename A::Scalar;
    return a.rows() == b.rows() && a.cols() == b.cols() &&
           (a.size() == 0 || std::memcmp(a.derived().data(), b.derived().data(), std::size_t(a.size()) * sizeof(Scalar)) == 0);
}

void requireSameEstimate(const ExogenousEstimate& fast, const ExogenousEstimate& peer)
{
    CHECK(fast.correlationLength == peer.correlationLength);
    CHECK(sameBits(fast.functionInput, peer.functionInput));
    CHECK(sameBits(fast.emotionInputs, peer.emotionInputs));
    CHECK(sameBits(fast.functionComponent, peer.functionComponent));
    CHECK(sameBits(fast.emotionComponents, peer.emotionComponents));
    CHECK(sameBits(fast.cellMeans, peer.cellMeans));
    CHECK(sameBits(fast.estimateCount, peer.estimateCount));
    REQUIRE(fast.langevin.size() == peer.langevin.size());
    for (std::size_t j = 0; j < fast.langevin.size(); ++j) {
        CHECK(sameBits(fast.langevin[j].gammaPlus, peer.langevin[j].gammaPlus));
        CHECK(sameBits(fast.langevin[j].gammaMinus, peer.langevin[j].gammaMinus));
        CHECK(sameBits(fast.langevin[j].varianceForward, peer.langevin[j].varianceForward));
        CHECK(sameBits(fast.langevin[j].varianceBackward, peer.langevin[j].varianceBackward));
        CHECK(sameBits(fast.langevin[j].partialForward, peer.langevin[j].partialForward));
    }
}

} // namespace

TEST_CASE("cells prepared once give every M's estimate bit for bit as the per-window computation", "[km2o][exogenous]")
{
    ArxSimulationOptions simOptions;
    simOptions.finalTime = 105; // the demo corpus's 106 frames: M_max = 29
    simOptions.seed = 5;
    const ArxSimulation sim = simulateArx(simOptions);
    std::vector<Eigen::MatrixXd> cells = sim.cells[0];
    SECTION("noisy cells") {}
    SECTION("a noise-free cell (flat KM2O data for every M)")
    {
        for (Eigen::Index k = 1; k < cells[2].cols(); ++k) cells[2].col(k) = cells[2].col(0);
    }
    auto prepared = ExogenousCells::prepare(cells, 29);
    REQUIRE(prepared.ok());
    for (auto range : {InitialTimeRange::Full, InitialTimeRange::Thesis})
        for (int first : {0, 1, 2})
            for (auto average : {WindowAverage::Uniform, WindowAverage::VarianceWeighted})
                for (int m : {0, 1, 2, 7, 29}) {
                    ExogenousOptions options{m, first, range, average};
                    INFO("M = " << m << ", first offset " << first << ", thesis range " << (range == InitialTimeRange::Thesis)
                                << ", variance-weighted " << (average == WindowAverage::VarianceWeighted));
                    auto peer = bunraku::test::reference::referenceExogenousEstimate(cells, options);
                    auto fast = prepared->estimate(options);
                    auto direct = estimateExogenousInputs(cells, options);
                    REQUIRE(peer.ok() == fast.ok());
                    REQUIRE(direct.ok() == fast.ok());
                    if (!peer.ok()) {
                        CHECK(fast.error().message == peer.error().message);
                        continue;
                    }
                    requireSameEstimate(*fast, *peer);
                    requireSameEstimate(*direct, *peer);
                }
    ExogenousOptions beyond;
    beyond.correlationLength = 30;
    CHECK_THAT(prepared->estimate(beyond).error().message, Catch::Contains("M_max = 29"));
}

TEST_CASE("KM2O with M chosen by P gives the components of that M given, bit for bit", "[km2o]")
{
    const auto known = bunraku::test::knownComponentsCorpus(106, 5, 2, 0.3);
    auto chosen = decomposeKm2o(known.corpus);
    REQUIRE(chosen.ok());
    Km2oDecompositionOptions given;
    given.correlationLength = chosen->correlationLength;
    auto direct = decomposeKm2o(known.corpus, given);
    REQUIRE(direct.ok());
    CHECK(sameBits(direct->cellErrorPercent, chosen->cellErrorPercent));
    CHECK(direct->meanCellErrorPercent == chosen->meanCellErrorPercent);
    for (std::size_t i = 0; i < chosen->components.functions.size(); ++i)
        CHECK(sameBits(direct->components.functions[i].values, chosen->components.functions[i].values));
    for (std::size_t c = 0; c < chosen->components.emotions.size(); ++c)
        CHECK(sameBits(direct->components.emotions[c].values, chosen->components.emotions[c].values));
    for (std::size_t k = 0; k < chosen->components.fluctuations.size(); ++k)
        CHECK(sameBits(direct->components.fluctuations[k].values, chosen->components.fluctuations[k].values));
}
