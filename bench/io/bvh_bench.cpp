// BVH reading speed (issue "Real motion capture in", point 6):
// - parseBvh/readBvh and the whole puppet import (part map, calibration, skeleton, 24 channels)
//   of a 25 MB and a 135 MB (108,000-frame) Bandai-like take, made from a shared Bandai file;
// - assimp's BVH importer on the same 25 MB file in the same run: the library
//   (Assimp::Importer::ReadFile, no post-processing) and the `assimp info` command (Debian's
//   assimp-utils), whose ratio to readBvh is the target (>= 5x);
// - the hierarchy parser with 10,000 to 400,000 sibling joints (linear: the time per joint stays flat).
#include "bench/io/big_bvh.h"

#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

using namespace bunraku;

namespace {

std::filesystem::path scratch() { return std::filesystem::temp_directory_path() / "bunraku-bench-io"; }

/// 18,800 frames of the Bandai take: 25 MB.
constexpr long k25MbFrames = 18800;
constexpr long k135MbFrames = 108000;

std::filesystem::path fileOrSkip(benchmark::State& state, long frames)
{
    const auto file = bench::bigBandaiLikeTake(scratch(), frames);
    if (file.empty()) state.SkipWithError(("the Bandai take is missing: " + bench::bandaiTake().string()).c_str());
    return file;
}

void readBvhFile(benchmark::State& state)
{
    const auto file = fileOrSkip(state, state.range(0));
    if (file.empty()) return;
    for (auto _ : state) {
        auto bvh = analysis::io::readBvh(file);
        if (!bvh) state.SkipWithError(bvh.error().message.c_str());
        benchmark::DoNotOptimize(bvh);
    }
    state.counters["MB"] = double(std::filesystem::file_size(file)) / 1e6;
}
BENCHMARK(readBvhFile)->Arg(k25MbFrames)->Arg(k135MbFrames)->Unit(benchmark::kMillisecond)->UseRealTime();

void importBvhPuppetTake(benchmark::State& state)
{
    const auto file = fileOrSkip(state, state.range(0));
    if (file.empty()) return;
    for (auto _ : state) {
        auto bvh = analysis::io::readBvh(file);
        if (!bvh) state.SkipWithError(bvh.error().message.c_str());
        auto take = analysis::io::bvhToPuppetTake(*bvh);
        if (!take) state.SkipWithError(take.error().message.c_str());
        benchmark::DoNotOptimize(take);
    }
}
BENCHMARK(importBvhPuppetTake)->Arg(k25MbFrames)->Arg(k135MbFrames)->Unit(benchmark::kMillisecond)->UseRealTime();

void assimpImporter(benchmark::State& state)
{
    const auto file = fileOrSkip(state, k25MbFrames);
    if (file.empty()) return;
    for (auto _ : state) {
        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile(file.string(), 0);
        if (scene == nullptr || scene->mNumAnimations == 0) state.SkipWithError(importer.GetErrorString());
        benchmark::DoNotOptimize(scene);
    }
}
BENCHMARK(assimpImporter)->Unit(benchmark::kMillisecond)->UseRealTime();

void assimpInfoCommand(benchmark::State& state)
{
    const auto file = fileOrSkip(state, k25MbFrames);
    if (file.empty()) return;
    const std::string command = "assimp info '" + file.string() + "' > /dev/null 2>&1";
    for (auto _ : state)
        if (std::system(command.c_str()) != 0) state.SkipWithError("`assimp info` failed: install assimp-utils (scripts/install-deps.sh)");
}
BENCHMARK(assimpInfoCommand)->Unit(benchmark::kMillisecond)->UseRealTime();

std::string siblings(long count)
{
    std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 1 Xposition\n";
    for (long k = 0; k < count; ++k) text += "JOINT j" + std::to_string(k) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n}\n";
    return text + "}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0\n";
}

void parseSiblingHierarchy(benchmark::State& state)
{
    const std::string text = siblings(state.range(0));
    for (auto _ : state) {
        auto file = analysis::io::parseBvh(text, "wide.bvh");
        if (!file) state.SkipWithError(file.error().message.c_str());
        benchmark::DoNotOptimize(file);
    }
    // Seconds per joint (printed with an SI prefix, e.g. 300n = 300 ns).
    state.counters["per_joint"] = benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(parseSiblingHierarchy)->Arg(10000)->Arg(40000)->Arg(100000)->Arg(400000)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
