// Motion axis and design speed (issue 5 targets): axis of 106 frames < 1 ms, re-synthesis after
// one control-point move < 2 ms (also with a full 22-joint skeleton, issue 12), axis of 100,000
// frames < 200 ms. Results: docs/PERFORMANCE.md.
#include "analysis/axis/axis_channels.h"
#include "analysis/axis/inertia_axis.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/axis/segment_inertia.h"
#include "analysis/design/motion_design.h"
#include "analysis/io/take_reader.h"
#include "analysis/skeleton/take_resample.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

namespace {

using namespace bunraku::analysis;

/// A puppet take of `frames` frames: the body sways and bows, each part wiggles.
Take swayingTake(Eigen::Index frames)
{
    static const Eigen::Vector3d rest[4] = {{0, 0, 103}, {0, 0, 100}, {0, -13, 98}, {0, -13, 70}};
    Take take;
    take.channels = puppetChannels();
    take.values.resize(frames, kPuppetChannelCount);
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double t = double(f);
        const RigidTransform body{Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * std::sin(t / 9.0), Eigen::Vector3d::UnitZ()) *
                                                     Eigen::AngleAxisd(0.25 * std::sin(t / 13.0) + 0.1, Eigen::Vector3d::UnitY())),
                                  Eigen::Vector3d(5.0 * std::sin(t / 11.0), 3.0 * std::cos(t / 7.0), 2.0 * std::sin(t / 5.0))};
        for (int p = 0; p < kPuppetPartCount; ++p) {
            const RigidTransform wiggle{Eigen::Quaterniond(Eigen::AngleAxisd(0.25 * std::sin((t + 7 * p) / 6.0),
                                                                             Eigen::Vector3d(0.2, 1.0, 0.3).normalized())),
                                        rest[p]};
            setPartPose(take, f, p * kDofCount, body * wiggle);
        }
    }
    return take;
}

const AxisModel& model()
{
    static const AxisModel m = makeAxisModel(defaultBodyDescription());
    return m;
}

void axisOfTake(benchmark::State& state)
{
    const Take take = swayingTake(state.range(0));
    for (auto _ : state) {
        auto axis = computeMotionAxis(model(), take);
        benchmark::DoNotOptimize(axis);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(axisOfTake)->Arg(106)->Arg(100000)->Unit(benchmark::kMillisecond);

/// What an editor does on a control-point drag of a 106-frame design: move one point, re-synthesise
/// the take (gains of 1.1 on every phrase, so the whole of step 2 runs).
void dragControlPoint(benchmark::State& state, const DesignBasis& basis)
{
    const GainSet gains = extractGains(basis.coordinates, basis.coordinates * 1.1, {0, 40, 70, 105},
                                       {"x", "y", "z", "rx", "ry", "rz"}).value();
    WarpCurve warp = identityWarp(106, 8);
    double offset = 0.0;
    for (auto _ : state) {
        offset = offset > 3.0 ? -3.0 : offset + 0.5;
        warp = moveControlPoint(warp, 6, {warp.points[6].output, 48.0 + offset});
        DesignedMotion designed = designMotion(basis, warp, gains);
        benchmark::DoNotOptimize(designed);
    }
}

/// What an editor does on a control-point drag: move one point, re-synthesise the take.
void redesignAfterDrag(benchmark::State& state)
{
    const Take take = swayingTake(106);
    const DesignBasis basis = prepareDesign(model(), take).value();
    dragControlPoint(state, basis);
}
BENCHMARK(redesignAfterDrag)->Unit(benchmark::kMillisecond);

/// The same drag on a take with its full skeleton (issue 12: < 2 ms): a Bandai wave (22 joints
/// + 5 End Sites) resampled to a 106-frame cell; the designed take carries every joint.
void redesignFullSkeletonAfterDrag(benchmark::State& state)
{
    const std::filesystem::path file = std::filesystem::path(BUNRAKU_SHARED_DIR) / "data/bandai/wave-right-hand_normal_001.bvh";
    auto wave = io::readTakeFile(file);
    if (!wave) {
        state.SkipWithError(("needs the shared Bandai data: " + file.string()).c_str());
        return;
    }
    const Take take = resampleTake(*wave, evenlySpacedFrames(wave->frameCount(), 106));
    const DesignBasis basis = prepareDesign(model(), take).value();
    dragControlPoint(state, basis);
    state.counters["joints"] = double(take.skeleton->jointSlots());
}
BENCHMARK(redesignFullSkeletonAfterDrag)->Unit(benchmark::kMillisecond);

/// The same drag on the whole body (issue 25: < 16 ms to the result): a Bandai wave read with
/// every joint as a part (132 channels), its axis the performer's segments (segment_inertia.h);
/// the designed take recombines all 22 joints and carries the skeleton.
void redesignWholeBodyAfterDrag(benchmark::State& state)
{
    const std::filesystem::path file = std::filesystem::path(BUNRAKU_SHARED_DIR) / "data/bandai/wave-right-hand_normal_001.bvh";
    io::ImportOptions options;
    options.bvhLayout = io::BvhTakeLayout::AllJoints;
    auto wave = io::readTakeFile(file, options);
    if (!wave) {
        state.SkipWithError(("needs the shared Bandai data: " + file.string()).c_str());
        return;
    }
    const Take take = resampleTake(*wave, evenlySpacedFrames(wave->frameCount(), 106));
    const SegmentBody body = segmentBody(take).value();
    const DesignBasis basis = prepareDesign(body.model, take).value();
    dragControlPoint(state, basis);
    state.counters["channels"] = double(take.channels.size());
}
BENCHMARK(redesignWholeBodyAfterDrag)->Unit(benchmark::kMillisecond);

/// The one-off cost the basis saves on every drag: axis + relative motion of the functional take.
void prepareDesignBasis(benchmark::State& state)
{
    const Take take = swayingTake(106);
    for (auto _ : state) {
        auto basis = prepareDesign(model(), take);
        benchmark::DoNotOptimize(basis);
    }
}
BENCHMARK(prepareDesignBasis)->Unit(benchmark::kMillisecond);

/// Sampling the shipped body's mass points and moments (once per body description).
void makeModel(benchmark::State& state)
{
    for (auto _ : state) {
        AxisModel m = makeAxisModel(defaultBodyDescription());
        benchmark::DoNotOptimize(m);
    }
}
BENCHMARK(makeModel)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
