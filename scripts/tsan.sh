#!/usr/bin/env bash
# The workbench's threads under ThreadSanitizer (docs/RELIABILITY.md, "Threads"): the stage
# scheduler, the import and export workers (progress_task, file_controller, export_controller)
# and the video writer (video_export_job, ffmpeg_encoder), in one test executable,
# tests_app_threads, built alone in build-tsan with clang-14 and -fsanitize=thread (the analysis
# layer, render, widgets and app instrumented; Qt is Debian's, not instrumented: see
# tests/tsan_qt.supp for what that means and what is suppressed). Not part of scripts/test.sh
# (CI time): run it by hand. Usage: scripts/tsan.sh [Catch2 test spec...] (default: all but [ffmpeg])
# Fails on any ThreadSanitizer report that is not suppressed (halt_on_error) or any failed case.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUNRAKU_TSAN_BUILD:-$root/build-tsan}"
generator=()
if command -v ninja >/dev/null 2>&1 && [ ! -f "$build/CMakeCache.txt" ]; then generator=(-G Ninja); fi
# -O1: the build is what costs (every layer compiled once more, about 250 files); at -O0 the
# analysis (Eigen) ran too slowly for the tests' waits. Line tables for the reports' stacks.
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
  -DCMAKE_CXX_COMPILER=clang++-14 -DBUNRAKU_TSAN=ON -DBUNRAKU_PYTHON=OFF -DBUNRAKU_BUILD_BENCHMARKS=OFF \
  -DBUNRAKU_WERROR=OFF >/dev/null
cmake --build "$build" --target tests_app_threads --parallel "$(nproc)"
# Every case of the executable but the five tagged [ffmpeg] (or the given spec), under Xvfb (the
# tests open windows). The [ffmpeg] cases start ffmpeg from the video worker thread (QProcess
# forks there), and clang 14's ThreadSanitizer runtime stops at such a fork with its own
# "CHECK failed: tsan_rtl.cpp:234" before any report (docs/RELIABILITY.md, section 8); the worker's
# loop runs under TSan in the PNG cases. `scripts/tsan.sh "[ffmpeg]"` runs them (and stops so).
if [ "$#" -eq 0 ]; then
  set -- "~[ffmpeg]"
  echo "tsan.sh: every case but the five [ffmpeg] ones (a fork from a worker thread stops clang 14's TSan runtime)"
fi
(cd "$build" && TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$root/tests/tsan_qt.supp" \
   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ./bin/tests_app_threads "$@")
