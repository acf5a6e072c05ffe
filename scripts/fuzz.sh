#!/usr/bin/env bash
# Fuzzes every reader with libFuzzer for a fixed number of executions each (fuzz/README.md).
# Usage: scripts/fuzz.sh [RUNS] [TARGET...]
#   RUNS     executions per target (default 1000000; scripts/test.sh runs 20000 as a smoke test;
#            fuzz_scene_take, which runs assimp, a tenth of them)
#   TARGET   fuzz_bvh fuzz_take_csv fuzz_fastrak fuzz_corpus_manifest fuzz_project fuzz_warp_csv
#            fuzz_gains_json fuzz_scene_take (default: all)
# Builds the analysis layer with clang-14, -fsanitize=fuzzer,address,undefined in build-fuzz,
# starts each target from its seeds (fuzz/seeds/<target>, valid files) in a scratch corpus, and
# fails on the first crash, leak, timeout or allocation past the limits below; the input that
# caused it is kept in build-fuzz/findings/<target>/. Prints one line of figures per target.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
runs="${1:-1000000}"
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(fuzz_bvh fuzz_take_csv fuzz_fastrak fuzz_corpus_manifest fuzz_project fuzz_warp_csv fuzz_gains_json fuzz_scene_take)
fi
# BUNRAKU_FUZZ_BUILD: a build folder already configured with BUNRAKU_FUZZ=ON (scripts/test.sh
# builds its sanitizer tests and these targets in one folder); default build-fuzz, configured here.
build="${BUNRAKU_FUZZ_BUILD:-$root/build-fuzz}"
if ! grep -q '^BUNRAKU_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  generator=()
  if command -v ninja >/dev/null 2>&1 && [ ! -f "$build/CMakeCache.txt" ]; then generator=(-G Ninja); fi
  # -O1 with line tables: quick to build, fast enough to fuzz, stack traces with lines. Warnings
  # are errors in the gcc builds (scripts/build.sh); here clang's own (GCC pragmas) only show.
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
    -DCMAKE_CXX_COMPILER=clang++-14 -DBUNRAKU_FUZZ=ON -DBUNRAKU_WITH_QT=OFF -DBUNRAKU_BUILD_TESTS=OFF \
    -DBUNRAKU_BUILD_BENCHMARKS=OFF -DBUNRAKU_WERROR=OFF >/dev/null
fi
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}"

status=0
for target in "${targets[@]}"; do
  work="$build/work/$target"
  findings="$build/findings/$target"
  rm -rf "$work"
  mkdir -p "$work" "$findings"
  start=$(date +%s.%N)
  # Fixed seed: the same executions every run. Limits: 64 KiB inputs, a single allocation of at
  # most 256 MB and 1 GB in all (what the file claims is never allocated), 10 s per input.
  # assimp (Debian's library, behind fuzz_scene_take) leaks on some malformed files: its leaks
  # only are suppressed (fuzz/lsan_assimp.supp).
  lsan=""
  if [ "$target" = fuzz_scene_take ]; then lsan="suppressions=$root/fuzz/lsan_assimp.supp"; fi
  # fuzz_scene_take runs assimp on every input (some 40 executions a second under the
  # sanitizers): a tenth of the executions, so that the smoke run stays short.
  target_runs="$runs"
  if [ "$target" = fuzz_scene_take ]; then target_runs=$(( runs / 10 > 0 ? runs / 10 : 1 )); fi
  if LSAN_OPTIONS="$lsan" "$build/bin/$target" "$work" "$root/fuzz/seeds/$target" -runs="$target_runs" -seed=1 -max_len=65536 \
       -malloc_limit_mb=256 -rss_limit_mb=1024 -timeout=10 -print_final_stats=1 \
       -artifact_prefix="$findings/" >"$build/work/$target.log" 2>&1; then
    result="ok"
  else
    result="FAILED (see $build/work/$target.log, input in $findings/)"
    status=1
  fi
  end=$(date +%s.%N)
  executed=$(sed -n 's/^stat::number_of_executed_units: *//p' "$build/work/$target.log" | tail -1)
  peak=$(sed -n 's/^stat::peak_rss_mb: *//p' "$build/work/$target.log" | tail -1)
  coverage=$(grep -o 'cov: [0-9]*' "$build/work/$target.log" | tail -1 | cut -d' ' -f2)
  corpus=$(ls "$work" | wc -l)
  printf '%-22s %s: %s executions in %.1f s, coverage %s edges, %s corpus inputs, peak RSS %s MB\n' \
    "$target" "$result" "${executed:-?}" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" "${coverage:-?}" "$corpus" "${peak:-?}"
done
exit $status
