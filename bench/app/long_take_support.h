#pragma once
// Support of bench_long_take: the synthetic long take written once per size into the temporary
// folder (never committed; `bunraku demo --long N` writes the same file), the process's memory
// figures, and a probe of the GUI thread's longest stall.
#include "analysis/synth/long_take.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace bunraku::bench {

/// Frames of the long take: BUNRAKU_LONG_FRAMES, default 432,000 (an hour at 120 Hz).
inline long long longTakeFrames()
{
    const char* text = std::getenv("BUNRAKU_LONG_FRAMES");
    const long long frames = text ? std::atoll(text) : 0;
    return frames >= 2 ? frames : 432000;
}

/// The long take's BVH file for `frames` frames and `seed`, written when missing. Empty on error.
inline std::filesystem::path longTakeFile(long long frames, std::uint64_t seed = 1)
{
    const auto folder = std::filesystem::temp_directory_path() / "bunraku-bench-long" /
                        (std::to_string(frames) + "-" + std::to_string(seed));
    const auto file = folder / analysis::synth::longTakeFileName();
    std::error_code error;
    if (std::filesystem::is_regular_file(file, error)) return file;
    analysis::synth::LongTakeOptions options;
    options.frames = frames;
    options.seed = seed;
    auto written = analysis::synth::writeLongTake(options, folder);
    return written ? *written : std::filesystem::path();
}

/// A field of /proc/self/status in MB ("VmHWM": the peak resident size, "VmRSS": the current).
inline double statusMegabytes(const std::string& field)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(field + ":", 0) == 0) return std::atof(line.c_str() + field.size() + 1) / 1024.0;
    return 0.0;
}

/// Resets the peak resident size (VmHWM) to the current one (Linux: clear_refs 5).
inline void resetPeakMemory()
{
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
}

/// Runs the GUI event loop until `done` holds (checked every 5 ms), measuring the longest gap
/// between two ticks of a 4 ms timer: how long the GUI thread was busy at a stretch (input and
/// paints wait that long). Returns the longest gap in ms; `seconds` gets the time taken.
inline double runMeasuringStalls(const std::function<bool()>& done, double* seconds = nullptr, int timeoutMs = 600000)
{
    QEventLoop loop;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(4);
    QElapsedTimer sinceTick, total;
    double longest = 0.0;
    QObject::connect(&probe, &QTimer::timeout, &loop, [&] {
        longest = std::max(longest, double(sinceTick.nsecsElapsed()) * 1e-6);
        sinceTick.restart();
        if (done() || total.elapsed() > timeoutMs) loop.quit();
    });
    total.start();
    sinceTick.start();
    probe.start();
    if (!done()) loop.exec();
    if (seconds) *seconds = double(total.nsecsElapsed()) * 1e-9;
    return longest;
}

/// The main of a benchmark program that opens windows: a QApplication named `name`, the
/// benchmarks, then `release` (windows go before the QApplication).
inline int runQtBenchmarks(int argc, char** argv, const char* name, const std::function<void()>& release)
{
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("BunrakuBench"));
    QApplication::setApplicationName(QString::fromLatin1(name));
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    release();
    return 0;
}

} // namespace bunraku::bench
