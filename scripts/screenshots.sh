#!/usr/bin/env bash
# Regenerates every screenshot in docs/ (docs/*.png) with the application itself: the workbench
# under Xvfb (--screenshot, taken once the analysis is idle) and `bunraku render` offscreen, on
# the embedded demo corpus and on the Bandai Namco takes (../shared/data/bandai; another folder
# with BUNRAKU_BANDAI_DIR). Usage: scripts/screenshots.sh [BUILD_DIR] (default: build).
#
# It builds nothing but calls scripts/build.sh when bunraku or bunraku-workbench is missing.
# Every image is written to a temporary file in docs/ and renamed over the old one once
# complete; the corpora, projects and takes it needs are made in /tmp/bunraku-screenshots,
# removed at the end. The workbench runs with its own empty settings (XDG_* folders in the
# scratch folder), so your saved layout, recent files and autosaves are neither used nor
# touched. Running it twice gives the same images.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
case "$build" in /*) ;; *) build="$PWD/$build" ;; esac
docs="$root/docs"
bandai="${BUNRAKU_BANDAI_DIR:-$root/../shared/data/bandai}"

if [ ! -x "$build/bin/bunraku" ] || [ ! -x "$build/bin/bunraku-workbench" ]; then
  echo "screenshots.sh: $build/bin has no bunraku or bunraku-workbench; building it (scripts/build.sh)" >&2
  bash "$root/scripts/build.sh" "$build" -DCMAKE_BUILD_TYPE=Release
fi
if [ ! -f "$bandai/wave-right-hand_normal_001.bvh" ] || [ ! -f "$bandai/bye_angry_001.bvh" ]; then
  echo "screenshots.sh: the Bandai Namco takes are not in $bandai (see its README; set BUNRAKU_BANDAI_DIR)" >&2
  exit 1
fi
bandai="$(cd "$bandai" && pwd)"

# One X server for the whole run: the workbench needs a display.
if [ -z "${BUNRAKU_SCREENSHOTS_XVFB:-}" ]; then
  command -v xvfb-run >/dev/null || { echo "screenshots.sh: xvfb-run is missing (apt-get install xvfb)" >&2; exit 1; }
  export BUNRAKU_SCREENSHOTS_XVFB=1
  exec xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" bash "$0" "$build"
fi

bunraku="$build/bin/bunraku"
workbench="$build/bin/bunraku-workbench"
# A fixed scratch folder: the status bar in the pictures names the corpus it opened, and the
# same name gives the same pictures. It is removed only when this script made it (its marker).
work=/tmp/bunraku-screenshots
marker="$work/.made-by-screenshots.sh"
if [ -e "$work" ] && [ ! -f "$marker" ]; then
  echo "screenshots.sh: $work exists and was not made by this script; move it away first" >&2
  exit 1
fi
rm -rf "$work"
mkdir -p "$work" && touch "$marker"
pending=""
cleanup() {
  [ -n "$pending" ] && rm -f "$pending"
  [ -f "$marker" ] && rm -rf "$work"
}
trap cleanup EXIT
export XDG_CONFIG_HOME="$work/config" XDG_DATA_HOME="$work/data" XDG_CACHE_HOME="$work/cache" XDG_RUNTIME_DIR="$work/runtime"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"

# shot NAME COMMAND...: runs COMMAND with "@OUT@" replaced by a temporary PNG in docs/, then
# renames it to docs/NAME.
shot() {
  local name="$1"; shift
  pending="$docs/.$name.partial.png"
  rm -f "$pending"
  local args=()
  for a in "$@"; do args+=("${a//@OUT@/$pending}"); done
  if ! "${args[@]}" >"$work/last.log" 2>&1 || [ ! -s "$pending" ]; then
    echo "screenshots.sh: making docs/$name failed:" >&2
    cat "$work/last.log" >&2
    exit 1
  fi
  mv -f "$pending" "$docs/$name"
  pending=""
  local size
  size="$(od -An -tu1 -j16 -N8 "$docs/$name" | awk '{print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8}')"
  echo "wrote docs/$name ($size, $(stat -c %s "$docs/$name") bytes)"
}

# project NAME TAKE_A TAKE_B EXTRA: a project file on the waves corpus (docs/FORMATS.md).
project() {
  printf '{"format": "bunraku-project", "version": 2, "corpus": "%s", "takeA": "%s", "takeB": "%s", "time_s": 2.0%s}\n' \
    "$work/waves" "$2" "$3" "$4" >"$work/$1.bunraku.json"
  echo "$1.bunraku.json"
}

# Inputs: the tutorial's corpus of the 15 waves, the guide's designed bye, the tutorial's designed wave.
"$bunraku" corpus "$bandai"/wave-right-hand_*.bvh -o "$work/waves" >/dev/null
(
  cd "$work"
  "$bunraku" phase --reference "$bandai/bye_normal_001.bvh" --sample "$bandai/bye_angry_001.bvh" -o bye-warp.csv
  "$bunraku" gains --reference "$bandai/bye_normal_001.bvh" --sample "$bandai/bye_angry_001.bvh" --warp bye-warp.csv -o bye-gains.json
  "$bunraku" design "$bandai/bye_normal_001.bvh" --warp bye-warp.csv --gains bye-gains.json -o bye-designed.bvh
  "$bunraku" normalise waves --function wave-right-hand --emotion normal --reference average --path optimal -o functional.bvh
  "$bunraku" normalise waves --function wave-right-hand --emotion exhausted --reference average --path optimal -o exhausted.bvh
  "$bunraku" phase --reference functional.bvh --sample exhausted.bvh -o warp.csv
  "$bunraku" gains --reference functional.bvh --sample exhausted.bvh --warp warp.csv -o gains.json
  "$bunraku" design functional.bvh --warp warp.csv --gains gains.json -o designed.bvh
) >"$work/inputs.log" 2>&1 || { cat "$work/inputs.log" >&2; exit 1; }
# The CLI's warp curve as the project's design.warp ([[output, source], ...]).
warp_json="$(awk -F, 'NR > 1 { printf "%s[%s, %s]", (n++ ? ", " : ""), $1, $2 }' "$work/warp.csv")"

cd "$work"
# The user guide and the README: the demo corpus at a laptop's size.
shot screenshot.png "$workbench" --window-size 1366x768 --screenshot @OUT@
shot screenshot-normalisation.png "$workbench" --window-size 1366x768 --raise Normalisation --screenshot @OUT@
# The user guide's real motion capture: the waves corpus, the fitted puppet, the walkthrough.
shot screenshot-bandai.png "$workbench" "$work/waves" --window-size 1700x920 --screenshot @OUT@
shot puppet-bandai.png "$bunraku" render "$bandai/wave-right-hand_active_001.bvh" --frame 60 --size 800x600 -o @OUT@
shot guide-bandai-open.png "$workbench" "$bandai/bye_angry_001.bvh" --figure both --window-size 1700x920 --screenshot @OUT@
shot guide-bandai-skeletons.png "$bunraku" render "$bandai/bye_normal_001.bvh" --take-b "$bandai/bye_angry_001.bvh" \
  --figure skeleton --time 1.5 --size 960x540 -o @OUT@
shot guide-bandai-bodies.png "$bunraku" render "$bandai/bye_normal_001.bvh" --take-b "$bandai/bye_angry_001.bvh" \
  --figure body --time 1.5 --size 960x540 -o @OUT@
shot guide-bandai-designed.png "$bunraku" render "$bandai/bye_normal_001.bvh" --take-b "$work/bye-designed.bvh" \
  --figure both --time 1.5 --size 960x540 -o @OUT@
# The tutorial (docs/TUTORIAL.md), at 1600x900, every figure the performer's skeleton.
tutorial=(--figure skeleton --window-size 1600x900)
shot tutorial-compare.png "$workbench" "$(project compare corpus/10 corpus/5 ', "view": {"twoTakeMode": 1}')" \
  "${tutorial[@]}" --screenshot @OUT@
shot tutorial-normalisation.png "$workbench" "$(project normalisation corpus/0 '' ', "parameters": {"normalise": {"path": "optimal"}}')" \
  "${tutorial[@]}" --raise Normalisation --screenshot @OUT@
shot tutorial-emotion.png "$workbench" \
  "$(project emotion corpus/5 live/weighted ', "parameters": {"normalise": {"path": "optimal"}, "design": {"emotionWeight": 2.0}}')" \
  "${tutorial[@]}" --raise Emotion --screenshot @OUT@
shot tutorial-design.png "$workbench" \
  "$(project design corpus/5 live/designed ", \"parameters\": {\"normalise\": {\"path\": \"optimal\"}, \"design\": {\"warp\": [$warp_json]}}")" \
  "${tutorial[@]}" --raise Design --screenshot @OUT@
shot tutorial-designed.png "$bunraku" render "$work/functional.bvh" --take-b "$work/designed.bvh" --figure skeleton \
  --time 3 --size 960x540 -o @OUT@
