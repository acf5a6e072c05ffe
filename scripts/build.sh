#!/usr/bin/env bash
# Configures and builds one build folder. Usage: scripts/build.sh BUILD_DIR [extra cmake args...]
# Uses Ninja when present, all cores, and warnings as errors for project code.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build_dir="$1"; shift
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ -f "$build_dir/CMakeCache.txt" ]; then generator=(); fi
cmake -S "$root" -B "$build_dir" "${generator[@]}" -DBUNRAKU_WERROR=ON "$@"
cmake --build "$build_dir" --parallel "$(nproc)"
