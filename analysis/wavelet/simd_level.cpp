#include "analysis/wavelet/simd_level.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace bunraku::analysis {

namespace {

// -1: no override in this thread.
thread_local int t_override = -1;

SimdLevel detectedLevel()
{
#if defined(__GNUC__) && defined(__x86_64__)
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return SimdLevel::Plain;
#ifndef BUNRAKU_NO_AVX512
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq")
        && __builtin_cpu_supports("avx512bw"))
        return SimdLevel::Avx512;
#endif
    return SimdLevel::Avx2;
#else
    return SimdLevel::Plain;
#endif
}

SimdLevel processLevel()
{
    const SimdLevel cpu = cpuSimdLevel();
    const char* requested = std::getenv("BUNRAKU_SIMD");
    if (!requested || !*requested) return cpu;
    const std::string value = requested;
    for (SimdLevel level : {SimdLevel::Plain, SimdLevel::Avx2, SimdLevel::Avx512})
        if (value == simdLevelName(level)) return std::min(level, cpu);
    std::fprintf(stderr, "BUNRAKU_SIMD=%s is not one of plain, avx2, avx512: the kernels use %s\n", requested,
                 simdLevelName(cpu));
    return cpu;
}

} // namespace

SimdLevel cpuSimdLevel()
{
    static const SimdLevel level = detectedLevel();
    return level;
}

SimdLevel simdLevel()
{
    static const SimdLevel level = processLevel();
    return t_override < 0 ? level : std::min(level, SimdLevel(t_override));
}

std::vector<SimdLevel> runnableSimdLevels()
{
    std::vector<SimdLevel> levels;
    for (SimdLevel level : {SimdLevel::Plain, SimdLevel::Avx2, SimdLevel::Avx512})
        if (level <= simdLevel()) levels.push_back(level);
    return levels;
}

const char* simdLevelName(SimdLevel level)
{
    switch (level) {
    case SimdLevel::Avx512: return "avx512";
    case SimdLevel::Avx2: return "avx2";
    default: return "plain";
    }
}

ScopedSimdLevel::ScopedSimdLevel(SimdLevel level)
    : m_previous(t_override)
{
    t_override = int(level);
}

ScopedSimdLevel::~ScopedSimdLevel() { t_override = m_previous; }

} // namespace bunraku::analysis
