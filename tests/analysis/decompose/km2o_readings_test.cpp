#include "analysis/decompose/km2o_experiment.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

TEST_CASE("Table 4.4 as printed and in percent")
{
    const auto printed = thesisTable44Printed(1000);
    const auto percent = thesisTable44Percent(1000);
    REQUIRE(printed.size() == 18);
    REQUIRE(percent.size() == 18);
    CHECK(printed[0] == 1.00);
    CHECK(percent[0] == Approx(0.100));
    CHECK(thesisTable44Printed(300) == thesisTable44Percent(300));
    CHECK(thesisTable44Printed(500).empty());
}

TEST_CASE("one noise series shared by all cells: the cells of a take differ only by their inputs")
{
    ArxSimulationOptions options;
    options.noise = NoiseSharing::SharedAcrossCells;
    options.takes = 7;
    const ArxSimulation shared = simulateArx(options);
    REQUIRE(shared.cells[0][1].cols() == 7);
    for (int i = 0; i < 2; ++i) {
        // x^{i2}_k - x^{i1}_k is driven by v^{i2} alone: the same for every take k
        const Eigen::MatrixXd difference = shared.cells[std::size_t(i)][1] - shared.cells[std::size_t(i)][0];
        for (Eigen::Index k = 1; k < difference.cols(); ++k) CHECK((difference.col(k) - difference.col(0)).norm() < 1e-9);
    }
    options.noise = NoiseSharing::PerCell;
    const ArxSimulation independent = simulateArx(options);
    const Eigen::MatrixXd difference = independent.cells[0][1] - independent.cells[0][0];
    CHECK((difference.col(1) - difference.col(0)).norm() > 1e-4);
}

TEST_CASE("the km2o experiment's error floor falls with the number of takes, as 1/K")
{
    Km2oExperimentOptions options;
    options.finalTime = 1000;
    options.firstM = options.lastM = 20;
    options.seeds = 2;
    const auto five = runKm2oExperiment(options);
    REQUIRE(five.ok());
    options.takes = 50;
    const auto fifty = runKm2oExperiment(options);
    REQUIRE(fifty.ok());
    const double ratio = five->errorPercent[0] / fifty->errorPercent[0];
    INFO("P(M = 20, T = 1000): K = 5 " << five->errorPercent[0] << " %, K = 50 " << fifty->errorPercent[0] << " %");
    CHECK(ratio > 6.0);  // the variance floor: 1 / (K (T + 1))
    CHECK(ratio < 15.0);
    options.takes = 1;
    CHECK(runKm2oExperiment(options).error().code == ErrorCode::InvalidArgument);
}

TEST_CASE("with one shared noise series and seeds 1-3 the T = 1000 row read in percent is met within 0.8-1.25x for M = 5..11")
{
    Km2oExperimentOptions options;
    options.finalTime = 1000;
    options.firstM = 5;
    options.lastM = 11;
    options.seeds = 3; // seeds 1-3: a mean inside the 40-seed spread docs/KM2O.md reports
    options.noise = NoiseSharing::SharedAcrossCells;
    const auto result = runKm2oExperiment(options);
    REQUIRE(result.ok());
    const auto printed = thesisTable44Printed(1000);
    for (std::size_t i = 0; i < result->correlationLengths.size(); ++i) {
        const int m = result->correlationLengths[i];
        const double ratio = result->errorPercent[i] / printed[std::size_t(m - 3)];
        INFO("M = " << m << ": " << result->errorPercent[i] << " % vs " << printed[std::size_t(m - 3)] << " (printed)");
        CHECK(ratio > 0.8);
        CHECK(ratio < 1.25);
    }
}
