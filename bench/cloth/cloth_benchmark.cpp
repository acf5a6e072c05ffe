// The kimono's simulation speed (issue "The kimono"): at least 20x faster than real time on one
// core for a 30 Hz take (a 10 s take in under 0.5 s), at least 5x for the 5 Hz demo takes.
// Results: docs/PERFORMANCE.md ("The kimono").
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/io/take_reader.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

namespace {

using namespace bunraku::analysis;

/// A puppet take of `seconds` at `rateHz`: the body sways and bows, the arm swings.
Take swingingTake(double seconds, double rateHz)
{
    static const Eigen::Vector3d rest[4] = {{4, 0, 115}, {0, 0, 100}, {0, -9, 89}, {0, -9, 75}};
    Take take;
    take.rateHz = rateHz;
    take.channels = puppetChannels();
    const auto frames = Eigen::Index(std::lround(seconds * rateHz));
    take.values.resize(frames, kPuppetChannelCount);
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double t = double(f) / rateHz;
        const RigidTransform body{Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * std::sin(t), Eigen::Vector3d::UnitZ()) *
                                                     Eigen::AngleAxisd(0.4 * std::sin(0.7 * t) + 0.2, Eigen::Vector3d::UnitY())),
                                  Eigen::Vector3d(5.0 * std::sin(t), 3.0 * std::cos(1.3 * t), 0.0)};
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const double swing = p >= 2 ? 0.8 * std::sin(2.0 * M_PI * 0.8 * t) : 0.1 * std::sin(t + p);
            const Eigen::Quaterniond limb = p >= 2 ? Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitY()))
                                                   : Eigen::Quaterniond::Identity();
            setPartPose(take, f, p * kDofCount,
                        body * RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(swing, Eigen::Vector3d::UnitZ())) * limb, rest[p]});
        }
    }
    return take;
}

void reportRealTime(benchmark::State& state, double seconds)
{
    state.counters["real_time_factor"] = benchmark::Counter(seconds * double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_KimonoTenSeconds30Hz(benchmark::State& state)
{
    const Take take = swingingTake(10.0, 30.0);
    for (auto _ : state) benchmark::DoNotOptimize(simulateKimono(take));
    reportRealTime(state, 10.0);
}
BENCHMARK(BM_KimonoTenSeconds30Hz)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_KimonoDemoTake5Hz(benchmark::State& state)
{
    const Take take = swingingTake(21.2, 5.0); // a demo take's length, 48 substeps a frame
    for (auto _ : state) benchmark::DoNotOptimize(simulateKimono(take));
    reportRealTime(state, 21.2);
}
BENCHMARK(BM_KimonoDemoTake5Hz)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_KimonoFrameFromCheckpoint(benchmark::State& state)
{
    // A jump to the frame before a checkpoint: the most frames rebuilt (29).
    const Take take = swingingTake(10.0, 30.0);
    const auto simulation = simulateKimono(take);
    for (auto _ : state) benchmark::DoNotOptimize(kimonoFrame(*simulation, take, 59));
}
BENCHMARK(BM_KimonoFrameFromCheckpoint)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

} // namespace

BENCHMARK_MAIN();
