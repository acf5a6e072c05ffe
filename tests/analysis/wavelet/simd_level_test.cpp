#include "analysis/wavelet/simd_level.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

using namespace bunraku::analysis;

TEST_CASE("BUNRAKU_SIMD lowers the kernels' level, never above what the CPU runs", "[simd]")
{
    // ctest also runs the kernel tests with BUNRAKU_SIMD=avx2 and =plain (tests/analysis/*/CMakeLists.txt).
    const char* requested = std::getenv("BUNRAKU_SIMD");
    SimdLevel expected = cpuSimdLevel();
    if (requested && std::string(requested) == "plain") expected = SimdLevel::Plain;
    if (requested && std::string(requested) == "avx2") expected = std::min(expected, SimdLevel::Avx2);
    INFO("BUNRAKU_SIMD=" << (requested ? requested : "(unset)") << ", CPU runs " << simdLevelName(cpuSimdLevel()));
    CHECK(simdLevel() == expected);
    const auto levels = runnableSimdLevels();
    REQUIRE(!levels.empty());
    CHECK(levels.front() == SimdLevel::Plain);
    CHECK(levels.back() == expected);
}

TEST_CASE("a scoped level lowers this thread's kernels and restores them", "[simd]")
{
    const SimdLevel process = simdLevel();
    {
        ScopedSimdLevel plain(SimdLevel::Plain);
        CHECK(simdLevel() == SimdLevel::Plain);
        CHECK(runnableSimdLevels().size() == 1);
        {
            ScopedSimdLevel higher(SimdLevel::Avx512); // never above the process's level
            CHECK(simdLevel() == process);
        }
        CHECK(simdLevel() == SimdLevel::Plain);
    }
    CHECK(simdLevel() == process);
    CHECK(std::string(simdLevelName(SimdLevel::Avx2)) == "avx2");
}
