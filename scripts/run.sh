#!/usr/bin/env bash
# README command 1: install the dependencies, build Release and launch the workbench on the
# embedded demo corpus. Extra arguments go to bunraku-workbench (e.g. a corpus folder).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh" "$root/build" -DCMAKE_BUILD_TYPE=Release
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "run.sh: no display (DISPLAY/WAYLAND_DISPLAY unset); starting the workbench under Xvfb." >&2
  exec xvfb-run -a -s "-screen 0 1600x1000x24 -noreset" "$root/build/bin/bunraku-workbench" "$@"
fi
exec "$root/build/bin/bunraku-workbench" "$@"
