#pragma once
/// The instruction-set level of the hand-written kernels (the CWT's convolutions, matching's
/// band distances, window sums and dynamic-programme scans). Each kernel has a plain version
/// and, on x86-64, AVX2/FMA and AVX-512 ones compiled into the same build (the build targets
/// baseline x86-64) and chosen at run time. The level can be lowered, to measure or test what a
/// CPU without AVX-512 (or without AVX2) runs, by the environment variable
///     BUNRAKU_SIMD=plain | avx2 | avx512
/// read once, on first use; and AVX-512 can be left out of a build with the CMake option
/// -DBUNRAKU_SIMD_AVX512=OFF.

#include <vector>

namespace bunraku::analysis {

/// Ordered: each level runs everything the lower ones run.
enum class SimdLevel {
    Plain,  ///< portable C++ (what the compiler makes of it for baseline x86-64)
    Avx2,   ///< AVX2 + FMA, 256-bit vectors, 16 registers
    Avx512, ///< AVX-512 F/VL/DQ/BW: 32 vector registers, 512-bit vectors where they pay
};

/// The best level this CPU (and this build) runs.
SimdLevel cpuSimdLevel();

/// The level the kernels dispatch to: cpuSimdLevel(), lowered by BUNRAKU_SIMD when that is
/// set (a level the CPU lacks is not raised to; an unknown value is reported once on stderr and
/// ignored), lowered further in a thread that holds a ScopedSimdLevel.
SimdLevel simdLevel();

/// Every level up to simdLevel(), Plain first: what the tests compare with each other.
std::vector<SimdLevel> runnableSimdLevels();

/// "plain", "avx2" or "avx512".
const char* simdLevelName(SimdLevel level);

/// For tests and benchmarks: the kernels called from this thread run at `level` (never above
/// the process's level) while this object lives.
class ScopedSimdLevel {
public:
    explicit ScopedSimdLevel(SimdLevel level);
    ~ScopedSimdLevel();
    ScopedSimdLevel(const ScopedSimdLevel&) = delete;
    ScopedSimdLevel& operator=(const ScopedSimdLevel&) = delete;

private:
    int m_previous;
};

} // namespace bunraku::analysis
