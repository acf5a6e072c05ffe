#pragma once
/// Tests that cannot pass by accident: a test that needs a peer it compares against or reads
/// (python3-pywt, statsmodels, ffmpeg/ffprobe, the shared Bandai data, a built executable) calls
/// requirePeer first. When the peer is missing:
///  - under CI=true the test FAILS, saying what is missing and how to get it;
///  - otherwise the test stops and is reported as skipped: it prints
///    "bunraku-test: skipped: <what>" (ctest's SKIP_REGULAR_EXPRESSION, set for every test in
///    cmake/BunrakuTargets.cmake, shows it as Skipped) and the run ends with a summary line
///    counting the skips. Catch2 v2 has no SKIP of its own.
///
///   if (!bunraku::test::requirePeer(pywtAvailable(), "python3-pywt", "apt-get install python3-pywt")) return;

#include <string>

namespace bunraku::test {

/// The text ctest looks for to report a test as skipped.
inline constexpr const char* kSkipMarker = "bunraku-test: skipped:";

/// True when CI=true (or 1) is set in the environment.
bool runningInCi();

/// True when `available`; else fails the test under CI, or records a skip. The caller returns at
/// once when it returns false.
bool requirePeer(bool available, const std::string& what, const std::string& howToGet);

/// Skips recorded in this process.
int skippedCount();

/// "N test case(s) skipped: ..." on standard output when any were skipped (the test mains call it
/// after the run).
void printSkipSummary();

} // namespace bunraku::test
