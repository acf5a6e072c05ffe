#include "analysis/decompose/km2o_experiment.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace bunraku::analysis {
namespace {

struct TableParameters {
    double amplitude[2];
    double inputPeriod;
    double emotionPeriod[2]; // j = 2, 3
    double x0, x1, noise;
};

TableParameters tableFor(int finalTime)
{
    if (finalTime == 1000) return {{5.0, 4.0}, 220.0, {180.0, 200.0}, 10.0, 5.0, 1.0e-3};
    return {{2.0, 3.0}, 140.0, {120.0, 100.0}, -5.83, 1.39, 1.4e-3};
}

constexpr double kArxA1[2] = {1.0 / 2.0, 1.0 / 4.0};
constexpr double kArxA2[2] = {1.0 / 3.0, 1.0 / 5.0};

} // namespace

ExogenousOptions recommendedKm2oReading()
{
    ExogenousOptions reading;
    reading.firstWindowOffset = 1; // drop the order-0 estimate u = x_mean(T0) where later offsets reach
    reading.initialTimes = InitialTimeRange::Full;
    reading.average = WindowAverage::Uniform;
    return reading;
}

ArxSimulation simulateArx(const ArxSimulationOptions& options)
{
    const TableParameters p = tableFor(options.finalTime);
    const double c = options.noiseScale.value_or(p.noise);
    const int frames = options.finalTime + 1;
    ArxSimulation sim;
    sim.finalTime = options.finalTime;
    std::mt19937_64 rng(options.seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixXd shared(frames, options.takes);
    for (Eigen::Index t = 0; t < shared.rows(); ++t)
        for (Eigen::Index k = 0; k < shared.cols(); ++k) shared(t, k) = normal(rng);
    for (int i = 0; i < 2; ++i) {
        Eigen::VectorXd u(frames);
        std::vector<Eigen::VectorXd> v(3, Eigen::VectorXd::Zero(frames));
        for (int t = 0; t < frames; ++t) {
            const double growth = std::exp(0.005 * t);
            u(t) = p.amplitude[i] * growth * std::sin(10.0 * t / p.inputPeriod);
            for (int j = 1; j < 3; ++j)
                v[std::size_t(j)](t) = -p.amplitude[i] * growth * std::cos(10.0 * t / p.emotionPeriod[j - 1]);
        }
        std::vector<Eigen::MatrixXd> cells;
        for (int j = 0; j < 3; ++j) {
            Eigen::MatrixXd x(frames, options.takes);
            for (int k = 0; k < options.takes; ++k) {
                x(0, k) = p.x0;
                x(1, k) = p.x1;
                for (int t = 2; t < frames; ++t)
                    x(t, k) = -kArxA1[i] * x(t - 1, k) - kArxA2[i] * x(t - 2, k) + u(t) + v[std::size_t(j)](t) +
                              c * (options.noise == NoiseSharing::SharedAcrossCells ? shared(t, k) : normal(rng));
            }
            cells.push_back(std::move(x));
        }
        sim.cells.push_back(std::move(cells));
        sim.functionInputs.push_back(std::move(u));
        sim.emotionInputs.push_back(std::move(v));
    }
    return sim;
}

double meanInputError(const ArxSimulation& simulation, const ExogenousOptions& options, bool* failed)
{
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < simulation.cells.size(); ++i) {
        auto est = estimateExogenousInputs(simulation.cells[i], options);
        if (!est) {
            if (failed) *failed = true;
            return std::numeric_limits<double>::quiet_NaN();
        }
        sum += relativeError(est->functionInput, simulation.functionInputs[i]);
        ++count;
        for (int j = 1; j < int(simulation.cells[i].size()); ++j) {
            sum += relativeError(est->emotionInputs.col(j), simulation.emotionInputs[i][std::size_t(j)]);
            ++count;
        }
    }
    if (failed) *failed = false;
    return sum / count;
}

std::vector<double> thesisTable44Printed(int finalTime)
{
    if (finalTime == 300)
        return {1.40, 0.91, 0.79, 0.83, 0.82, 0.85, 0.91, 0.94, 1.03, 1.20, 1.38, 1.51, 1.68, 1.83, 2.04, 2.25, 2.45, 2.68};
    if (finalTime == 1000)
        return {1.00, 0.43, 0.25, 0.19, 0.18, 0.17, 0.16, 0.15, 0.14, 0.13, 0.12, 0.11, 0.11, 0.11, 0.11, 0.11, 0.12, 0.13};
    return {};
}

std::vector<double> thesisTable44Percent(int finalTime)
{
    std::vector<double> values = thesisTable44Printed(finalTime);
    if (finalTime == 1000)
        for (double& value : values) value *= 0.1; // the thesis prints T = 1000 in units of 0.1 %
    return values;
}

Result<Km2oExperimentResult> runKm2oExperiment(const Km2oExperimentOptions& options, const RunControl& control)
{
    if (options.finalTime < 10)
        return makeError(ErrorCode::InvalidArgument, "km2o experiment: T must be at least 10");
    if (options.seeds < 1) return makeError(ErrorCode::InvalidArgument, "km2o experiment: --seeds must be at least 1");
    if (options.takes < 2 || options.takes > 1000)
        return makeError(ErrorCode::InvalidArgument,
                         "km2o experiment: --takes must be in 2..1000, got " + std::to_string(options.takes));
    const int maxM = maxCorrelationLength(options.finalTime + 1);
    if (options.firstM < 0 || options.lastM < options.firstM || options.lastM > maxM)
        return makeError(ErrorCode::InvalidArgument,
                         "km2o experiment: M range " + std::to_string(options.firstM) + ":" + std::to_string(options.lastM) +
                             " must lie in 0..M_max = " + std::to_string(maxM) + " (floor(3 sqrt(T+1)) - 1, T = " +
                             std::to_string(options.finalTime) + ")");
    Km2oExperimentResult result;
    result.finalTime = options.finalTime;
    const auto thesis = thesisTable44Percent(options.finalTime);
    for (int m = options.firstM; m <= options.lastM; ++m) {
        result.correlationLengths.push_back(m);
        result.errorPercent.push_back(0.0);
        result.thesisErrorPercent.push_back(m >= 3 && m <= 20 && !thesis.empty() ? thesis[std::size_t(m - 3)]
                                                                                 : std::numeric_limits<double>::quiet_NaN());
    }
    for (int seed = 0; seed < options.seeds; ++seed) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "km2o experiment cancelled");
        ArxSimulationOptions simOptions;
        simOptions.finalTime = options.finalTime;
        simOptions.noiseScale = options.noiseScale;
        simOptions.seed = options.firstSeed + std::uint64_t(seed);
        simOptions.noise = options.noise;
        simOptions.takes = options.takes;
        const ArxSimulation sim = simulateArx(simOptions);
        for (std::size_t index = 0; index < result.correlationLengths.size(); ++index) {
            ExogenousOptions reading = options.reading;
            reading.correlationLength = result.correlationLengths[index];
            bool failed = false;
            const double p = meanInputError(sim, reading, &failed);
            if (failed)
                return makeError(ErrorCode::Numerical, "km2o experiment: identification failed at M = " +
                                                           std::to_string(reading.correlationLength));
            result.errorPercent[index] += 100.0 * p / options.seeds;
        }
        control.report(double(seed + 1) / options.seeds);
    }
    return result;
}

} // namespace bunraku::analysis
