#!/usr/bin/env bash
# Installs the Debian package with apt into a clean Debian bookworm root and uses it there as a
# new user would (packaging/README.md, "Installed into a clean root"):
#   A. a minbase root and the package with its Depends only (--no-install-recommends): the
#      programs start, the workbench starts from its desktop entry's Exec line (on the X display
#      of the host), the tutorial's commands (docs/TUTORIAL.md) run on the Bandai waves, MP4
#      export without ffmpeg fails with a clear message; remove and purge leave nothing behind;
#   B. the same root with what a desktop has (shared-mime-info, desktop-file-utils, xdg-utils,
#      gio, hicolor-icon-theme, man-db) and the package installed as apt does by default, with its
#      Recommends (ffmpeg): man pages, file types and default application, a double click on a BVH
#      (gio open, then xdg-open) opens it in the workbench, MP4 export works; remove and purge
#      leave nothing behind and take the file types and the default application away again.
#
# Usage: scripts/clean-root-check.sh [PACKAGE.deb]   (default: the newest build/*.deb)
# Needs root (chroot, mounts), mmdebstrap and Xvfb (scripts/install-deps.sh), the Debian mirror of
# the machine's apt sources, and the Bandai waves (../shared/data/bandai or BUNRAKU_BANDAI_DIR,
# mounted read-only into the root). The programs show their windows on an Xvfb of its own
# (xvfb-run -a, or -n $BUNRAKU_XVFB_DISPLAY), whose socket is mounted into the root. The base root is cached as a tarball in
# ${XDG_CACHE_HOME:-~/.cache}/bunraku-clean-root (rebuilt after 7 days or when the mirror
# changes), with the .debs apt downloads; BUNRAKU_CLEAN_ROOT_CACHE overrides the folder.
# Exit 0: everything held; 1: a check failed (each is named); 77: it cannot run here (no root,
# mmdebstrap, Xvfb, mirror or data) - 1 instead when CI=true.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
self="$repo/scripts/clean-root-check.sh"
package_name=bunraku-motion-workbench
app_id=org.bunraku.MotionWorkbench

say() { printf '== %s\n' "$*"; }
cannot_run() {
  echo "clean-root-check: cannot run: $*" >&2
  if [ "${CI:-}" = "true" ]; then exit 1; fi
  exit 77
}

# --- Arguments and prerequisites ------------------------------------------------------------------
deb="${1:-}"
if [ -z "$deb" ]; then
  deb="$(ls -t "$repo"/build/${package_name}_*.deb 2>/dev/null | head -n 1 || true)"
  [ -n "$deb" ] || cannot_run "no package given and none in $repo/build (cmake --build build --target package)"
fi
[ -f "$deb" ] || { echo "clean-root-check: $deb: no such package" >&2; exit 1; }
deb="$(realpath "$deb")"
bandai="$(realpath -m "${BUNRAKU_BANDAI_DIR:-$repo/../shared/data/bandai}")"
if [ "$(id -u)" -ne 0 ]; then
  # Where apt-get runs through sudo (scripts/install-deps.sh), so does this: chroot and mounts.
  if command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
    exec sudo -n --preserve-env "$self" "$deb"
  fi
  cannot_run "needs root (chroot and mounts); run it with sudo"
fi
for tool in mmdebstrap unshare chroot Xvfb xvfb-run; do
  command -v "$tool" >/dev/null || cannot_run "$tool is not installed (scripts/install-deps.sh installs it)"
done
[ -f "$bandai/wave-right-hand_normal_001.bvh" ] && [ -f "$bandai/wave-right-hand_exhausted_005.bvh" ] \
  || cannot_run "the Bandai Namco waves are not in $bandai (see ../shared/data/bandai/README.md)"

# The Debian bookworm suites of the machine's apt sources, as mmdebstrap mirror lines.
mirrors="$(apt-get indextargets --format '$(REPO_URI) $(RELEASE) $(COMPONENT)' 'Created-By: Packages' 2>/dev/null \
           | awk '$2 ~ /^bookworm(-updates|-security)?$/ { key = $1 " " $2; if (!(key in c)) order[n++] = key;
                    if (index(" " c[key] " ", " " $3 " ") == 0) c[key] = c[key] " " $3 }
                  END { for (i = 0; i < n; ++i) print "deb " order[i] c[order[i]] }')"
[ -n "$mirrors" ] || cannot_run "no Debian bookworm mirror in the machine's apt sources (apt-get update first)"
main_host="$(printf '%s\n' "$mirrors" | awk 'NR == 1 { split($2, a, "/"); print a[3] }')"
timeout 20 bash -c "exec 3<>/dev/tcp/$main_host/80" 2>/dev/null || cannot_run "the mirror $main_host is not reachable"

# --- An X display of its own (xvfb-run), so focus changes do not reach other programs' windows -----
if [ -z "${BUNRAKU_CLEAN_ROOT_XVFB:-}" ]; then
  display_args=(-a)
  [ -n "${BUNRAKU_XVFB_DISPLAY:-}" ] && display_args=(-n "$BUNRAKU_XVFB_DISPLAY")
  exec env BUNRAKU_CLEAN_ROOT_XVFB=1 xvfb-run "${display_args[@]}" -s "-screen 0 1920x1080x24 -noreset" "$self" "$deb"
fi
display_number="$(printf '%s' "${DISPLAY:-}" | sed -n 's/^:\([0-9]\+\)\(\.[0-9]\+\)\?$/\1/p')"
[ -n "$display_number" ] && [ -S "/tmp/.X11-unix/X$display_number" ] \
  || cannot_run "xvfb-run gave DISPLAY=${DISPLAY:-} without a socket in /tmp/.X11-unix"

# --- Its own mount namespace: whatever happens, no mount outlives the script ----------------------
if [ -z "${BUNRAKU_CLEAN_ROOT_NAMESPACE:-}" ]; then
  exec env BUNRAKU_CLEAN_ROOT_NAMESPACE=1 unshare --mount --propagation private "$self" "$deb"
fi

# --- The cached base root ------------------------------------------------------------------------
cache="${BUNRAKU_CLEAN_ROOT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/bunraku-clean-root}"
mkdir -p "$cache/apt-archives/partial" "$cache/roots"
# One run at a time per cache (the tarball and apt's download folder are shared).
exec 9>"$cache/lock"
flock 9
started=$SECONDS
key="$(printf '%s\n%s\n' "$(mmdebstrap --version)" "$mirrors" | sha256sum | cut -c1-12)"
tarball="$cache/bookworm-minbase-$key.tar"
find "$cache" -maxdepth 1 -name 'bookworm-minbase-*.tar' -mtime +7 -delete
for stale in "$cache"/bookworm-minbase-*.tar; do
  [ -e "$stale" ] && [ "$stale" != "$tarball" ] && rm -f "$stale"
done
if [ ! -f "$tarball" ]; then
  say "making a clean bookworm root (mmdebstrap --variant=minbase) from: $(printf '%s' "$mirrors" | tr '\n' ';')"
  mirror_args=()
  while IFS= read -r line; do mirror_args+=("$line"); done <<<"$mirrors"
  # The package lists stay, so the first apt-get update in the root only refreshes them.
  mmdebstrap --quiet --variant=minbase --skip=cleanup/apt/lists bookworm "$tarball.partial.tar" "${mirror_args[@]}"
  mv "$tarball.partial.tar" "$tarball"
  say "base root cached: $tarball ($(du -h "$tarball" | cut -f1)) in $((SECONDS - started)) s"
else
  say "base root from the cache: $tarball ($(du -h "$tarball" | cut -f1))"
fi

# A root left by an interrupted run is deleted (nothing is mounted in it: its namespace is gone).
for old in "$cache"/roots/root.*; do
  [ -d "$old" ] || continue
  if ! grep -q " $old" /proc/self/mountinfo; then rm -rf --one-file-system "$old"; fi
done
root="$(mktemp -d "$cache/roots/root.XXXXXX")"
mounts=()
cleanup() {
  local status=$? i
  for ((i = ${#mounts[@]} - 1; i >= 0; --i)); do
    umount "${mounts[i]}" 2>/dev/null || umount -l "${mounts[i]}" 2>/dev/null || true
  done
  if grep -q " $root" /proc/self/mountinfo; then
    echo "clean-root-check: something is still mounted under $root: left in place" >&2
  else
    rm -rf --one-file-system "$root"
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

tar -C "$root" --numeric-owner -xpf "$tarball"
bind() { # bind SOURCE TARGET-IN-ROOT [ro]
  mkdir -p "$root$2"
  mount --bind "$1" "$root$2"
  mounts+=("$root$2")
  if [ "${3:-}" = ro ]; then mount -o remount,bind,ro "$root$2"; fi
}
mkdir -p "$root/proc" && mount -t proc proc "$root/proc" && mounts+=("$root/proc")
bind /sys /sys ro
mkdir -p "$root/dev" && mount --rbind /dev "$root/dev" && mounts+=("$root/dev")
mkdir -p "$root/dev/shm" && mount -t tmpfs -o mode=1777 shm "$root/dev/shm" && mounts+=("$root/dev/shm")
bind /tmp/.X11-unix /tmp/.X11-unix
bind "$cache/apt-archives" /var/cache/apt/archives
bind "$bandai" /mnt/bandai ro
cp /etc/resolv.conf "$root/etc/resolv.conf"
mkdir -p "$root/root/package" "$root/root/files"
cp "$deb" "$root/root/package/"
deb_in_root="/root/package/$(basename "$deb")"
xauth_env=()
if [ -n "${XAUTHORITY:-}" ] && [ -f "$XAUTHORITY" ]; then
  cp "$XAUTHORITY" "$root/root/.Xauthority"
  xauth_env=(XAUTHORITY=/root/.Xauthority)
fi

# Runs a bash script in the root, in the environment a login on that system has. Under pipefail a
# `grep -q` that stops reading early kills its writer with SIGPIPE and fails the pipeline when the
# writer has more to write: a large output is matched with `grep ... >/dev/null`, which reads it all.
inroot() {
  chroot "$root" /usr/bin/env -i HOME=/root USER=root LOGNAME=root SHELL=/bin/bash LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin DEBIAN_FRONTEND=noninteractive \
    DISPLAY="$DISPLAY" "${xauth_env[@]}" XDG_RUNTIME_DIR=/tmp/runtime-root BANDAI=/mnt/bandai \
    DEB="$deb_in_root" PACKAGE="$package_name" APP_ID="$app_id" \
    bash -euo pipefail -c "mkdir -p -m 700 /tmp/runtime-root; cd /root; $1"
}

failures=()
# check NAME SCRIPT: runs SCRIPT in the root; its output is shown; a failure is named at the end.
check() {
  local name="$1" begin=$SECONDS
  say "$name"
  if inroot "$2"; then
    echo "   ok ($((SECONDS - begin)) s)"
  else
    echo "   FAILED: $name" >&2
    failures+=("$name")
  fi
}
# Essential steps: nothing after them makes sense when they fail.
must() {
  local before=${#failures[@]}
  check "$1" "$2"
  [ ${#failures[@]} -eq "$before" ] || finish
}
finish() {
  say "clean-root-check: $((SECONDS - started)) s in all; downloaded: $(cat "$root/root/downloaded" 2>/dev/null | paste -sd' ' || echo '?')"
  if [ ${#failures[@]} -eq 0 ]; then
    say "clean-root-check: every check held for $(basename "$deb")"
    exit 0
  fi
  echo "clean-root-check: ${#failures[@]} check(s) failed:" >&2
  printf '  - %s\n' "${failures[@]}" >&2
  exit 1
}

# The shell functions the checks share (written into the root).
cat >"$root/root/lib.sh" <<'EOF'
# apt-get install, recording how much it downloaded (apt's "Need to get" line).
install_logged() {
  local what="$1"; shift
  apt-get install -y -o Dpkg::Use-Pty=0 "$@" >/tmp/apt.log 2>&1 || { cat /tmp/apt.log; return 1; }
  grep -E '^(Need to get|After this operation|Setting up)' /tmp/apt.log | grep -v '^Setting up' || true
  echo "$what: $(grep -c '^Setting up' /tmp/apt.log) packages set up, $(sed -n 's/^Need to get \([^/]*\)\(\/.*\)\? of archives.*/\1 to get/p' /tmp/apt.log)" >>/root/downloaded
}
# The installed desktop entry's Exec line with its field codes replaced by the given files, as
# words on stdout (one per line): what a desktop runs.
desktop_exec() {
  local entry=/usr/share/applications/$APP_ID.desktop exec
  exec="$(sed -n '/^\[Desktop Entry\]/,/^\[/ s/^Exec=//p' "$entry" | head -n 1)"
  [ -n "$exec" ] || { echo "$entry has no Exec line" >&2; return 1; }
  local word
  for word in $exec; do
    case "$word" in
      %F|%U) for f in "$@"; do printf '%s\n' "$f"; done ;;
      %f|%u) [ $# -gt 0 ] && printf '%s\n' "$1" ;;
      %i|%c|%k) ;;
      *) printf '%s\n' "$word" ;;
    esac
  done
}
# The files dpkg lists for the package, saved before removal.
save_file_list() { dpkg -L "$PACKAGE" | sort >/root/package-files; }
# Every path the package had is gone, unless another package owns it (a shared folder).
nothing_left() {
  local left=0 path
  while IFS= read -r path; do
    [ "$path" = "/." ] && continue
    [ -e "$path" ] || continue
    if [ -d "$path" ] && dpkg -S "$path" >/dev/null 2>&1; then continue; fi
    echo "left behind: $path"; left=1
  done </root/package-files
  return $left
}
# apt-get purge when remove left the package's configuration; dpkg forgets a package without
# conffiles at remove already, and apt-get purge would not find it.
purge() {
  if dpkg-query -W -f="\${Status}" "$PACKAGE" 2>/dev/null | grep -q .; then
    apt-get purge -y -qq "$PACKAGE" >/dev/null
  else
    echo "remove left nothing for purge (the package has no conffiles)"
  fi
  nothing_left
}
# The top-level X windows whose name matches the extended regular expression $1, as "id name" lines.
windows_named() { xwininfo -root -tree | grep -E -- "$1" | sed -n 's/^ *\(0x[0-9a-f]*\) "\([^"]*\)".*/\1 \2/p'; }
# Waits up to $2 seconds for a window whose name matches $1; prints its id.
wait_window() {
  local i
  for ((i = 0; i < $2 * 4; ++i)); do
    local found; found="$(windows_named "$1" | head -n 1)"
    if [ -n "$found" ]; then echo "${found%% *}"; return 0; fi
    sleep 0.25
  done
  echo "no window whose name matches '$1' within $2 s; named windows:" >&2
  xwininfo -root -tree | sed -n 's/^ *0x[0-9a-f]* "\(.*\)": .*/  \1/p' >&2
  return 1
}
# The process that owns window $1 (its _NET_WM_PID).
window_pid() { xprop -id "$1" _NET_WM_PID | sed -n 's/.* = \([0-9]\+\)$/\1/p'; }
# Stops process $1 (the workbench a check started), waiting up to 10 s before SIGKILL.
stop_process() {
  local pid="$1"
  [ -n "$pid" ] || return 0
  kill "$pid" 2>/dev/null || true
  for _ in $(seq 40); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.25; done
  kill -9 "$pid" 2>/dev/null || true
}
# The file signature a tutorial output of this name must start with.
valid_output() {
  local path="$1"
  if [ -d "$path" ]; then [ -n "$(ls -A "$path")" ] || { echo "$path: empty folder"; return 1; }; return 0; fi
  [ -s "$path" ] || { echo "$path: missing or empty"; return 1; }
  local head; head="$(head -c 9 "$path" | tr -d '\0' | tr -c '[:alnum:]{' '.')"
  case "$path" in
    *.png) [ "$head" != "${head#.PNG}" ] || { echo "$path: not a PNG ($head)"; return 1; } ;;
    *.glb) [ "${head#glTF}" != "$head" ] || { echo "$path: not glTF binary ($head)"; return 1; } ;;
    *.bvh) [ "${head#HIERARCHY}" != "$head" ] || { echo "$path: not a BVH ($head)"; return 1; } ;;
    *.json) [ "${head#\{}" != "$head" ] || { echo "$path: not a JSON object ($head)"; return 1; } ;;
  esac
}
EOF

# --- The tutorial's commands, as docs/TUTORIAL.md marks them (tests/cli/tutorial_script.cpp) -------
awk -v out="$root/root/tutorial" '
  /^```/ {
    if (block != "") { if (block == "file") close(file); block = ""; next }
    if ($0 == "```sh tutorial") block = "sh"
    else if ($0 ~ /^```json tutorial-file=/) { block = "file"; file = out "/" substr($0, 23); printf "" > file }
    else block = "other"
    next
  }
  block == "sh" { print > (out "/commands.sh") }
  block == "file" { print >> file }
' <(mkdir -p "$root/root/tutorial"; cat "$repo/docs/TUTORIAL.md")
[ -s "$root/root/tutorial/commands.sh" ] || { echo "clean-root-check: docs/TUTORIAL.md has no \`\`\`sh tutorial block" >&2; exit 1; }

# ==================================================================================================
say "A. minbase root, the package with its Depends only"
must "apt resolves the package's Depends from the mirror (apt-get install --no-install-recommends)" '
  . /root/lib.sh
  apt-get update -qq
  install_logged "A: the package with its Depends" --no-install-recommends "$DEB"
  dpkg-query -W -f="\${Status} \${Version}\n" "$PACKAGE"
  if dpkg-query -W -f="\${Status}" ffmpeg 2>/dev/null | grep -q "ok installed"; then echo "ffmpeg was installed without Recommends"; exit 1; fi
  save_file_list'
check "both programs find every library they link and answer --version" '
  missing="$(ldd /usr/bin/bunraku /usr/bin/bunraku-workbench /usr/lib/*/qt6/plugins/platforms/libqxcb.so 2>&1 | grep "not found" || true)"
  [ -z "$missing" ] || { echo "libraries no Depends pulled in:"; echo "$missing" | sort -u; exit 1; }
  bunraku --version | head -n 1
  bunraku-workbench --version | head -n 1
  zcat /usr/share/man/man1/bunraku.1.gz | grep "^\.TH BUNRAKU " >/dev/null || { echo "bunraku.1.gz has no .TH line"; exit 1; }'
check "the workbench starts from its desktop entry (Exec line, --screenshot) with its resources found" '
  . /root/lib.sh
  entry=/usr/share/applications/$APP_ID.desktop
  tryexec="$(sed -n "s/^TryExec=//p" "$entry")"
  command -v "$tryexec" >/dev/null || { echo "TryExec=$tryexec is not on PATH"; exit 1; }
  icon="$(sed -n "s/^Icon=//p" "$entry")"
  for size in 16 24 32 48 64 128 256 512; do
    [ -f /usr/share/icons/hicolor/${size}x${size}/apps/$icon.png ] || { echo "Icon=$icon: no ${size}x${size} PNG in hicolor"; exit 1; }
  done
  [ -f /usr/share/icons/hicolor/scalable/apps/$icon.svg ] || { echo "Icon=$icon: no scalable SVG in hicolor"; exit 1; }
  mapfile -t command < <(desktop_exec)
  echo "Exec: ${command[*]}"
  set +e
  "${command[@]}" --default-layout --screenshot /root/started.png >/root/started.out 2>&1
  status=$?
  set -e
  cat /root/started.out
  [ $status -eq 0 ] || { echo "the workbench exited with $status"; exit 1; }
  if grep -qi "warning\|could not\|cannot\|failed" /root/started.out; then echo "the workbench warned (above)"; exit 1; fi
  size=$(stat -c %s /root/started.png)
  echo "screenshot: $size bytes"
  [ "$size" -gt 50000 ] || { echo "the screenshot is too small to show the window"; exit 1; }'
check "the tutorial (docs/TUTORIAL.md) runs with the installed bunraku on the Bandai waves" '
  . /root/lib.sh
  cd /root/tutorial
  echo "$(grep -c "^bunraku" commands.sh) commands"
  bash -euo pipefail -x commands.sh >run.log 2>&1 || { tail -n 30 run.log; exit 1; }
  outputs="$(sed ":a;/\\\\$/{N;s/\\\\\n//;ba}" commands.sh | sed -n "s/.* -o \([^ ]*\).*/\1/p")"
  bad=0
  for output in $outputs; do valid_output "$output" || bad=1; done
  echo "outputs: $(echo $outputs)"
  bunraku info designed.bvh | grep -F "BVH: 22 joints + 5 End Sites, 132 channels, 216 frames" || { echo "designed.bvh is not the 22-joint, 216-frame take"; bad=1; }
  exit $bad'
check "without ffmpeg (a Recommends), MP4 export fails with a message naming ffmpeg" '
  set +e
  bunraku render "$BANDAI/bye_normal_001.bvh" --frames 0:3 -o /root/frames --mp4 /root/out.mp4 >/root/mp4.out 2>&1
  status=$?
  set -e
  cat /root/mp4.out
  [ $status -ge 1 ] && [ $status -lt 128 ] || { echo "exit status $status"; exit 1; }
  grep -q "ffmpeg" /root/mp4.out && [ ! -e /root/out.mp4 ]'
check "apt-get remove, then purge, leave no file of the package" '
  . /root/lib.sh
  apt-get remove -y -qq "$PACKAGE" >/dev/null
  nothing_left
  purge
  if dpkg-query -W -f="\${Status}" "$PACKAGE" 2>/dev/null | grep -q .; then dpkg-query -W -f="\${Status}\n" "$PACKAGE"; exit 1; fi'

# ==================================================================================================
say "B. the root with what a desktop has, the package installed with its Recommends"
must "apt installs the desktop's tools, then the package with its Recommends (ffmpeg)" '
  . /root/lib.sh
  # xdg-utils with its Recommends libfile-mimeinfo-perl: xdg-mime and xdg-open of a desktop
  # without gio/kde tools ask shared-mime-info (through mimetype) what a file is.
  install_logged "B: desktop tools" --no-install-recommends shared-mime-info desktop-file-utils xdg-utils \
    libfile-mimeinfo-perl libglib2.0-bin hicolor-icon-theme man-db x11-utils xdotool
  install_logged "B: the package with its Recommends" "$DEB"
  dpkg-query -W -f="ffmpeg \${Status}\n" ffmpeg | grep "ok installed"
  save_file_list'
check "the Python module imports with Debian's python3 (installed with the Recommends) and names the version" '
  # no __pycache__: the package has no maintainer scripts to remove one (py3clean), and purge
  # must leave no file behind
  export PYTHONDONTWRITEBYTECODE=1
  version="$(python3 -c "import bunraku; print(bunraku.__version__)")"
  echo "bunraku $version"
  bunraku --version | head -n 1 | grep -qF "$version" || { echo "bunraku.__version__ $version is not the program'"'"'s"; exit 1; }
  python3 -c "import bunraku, numpy; t = bunraku.Corpus.open(\"demo\").takes[0]; assert not t.values.flags.owndata; print(t)"'
check "man bunraku and man bunraku-workbench show the installed pages" '
  man -P cat bunraku 2>/dev/null | grep "bunraku help" >/dev/null || { echo "man bunraku: no page"; exit 1; }
  man -P cat bunraku-workbench 2>/dev/null | grep -- "--screenshot" >/dev/null || { echo "man bunraku-workbench: no page"; exit 1; }
  man -w bunraku bunraku-workbench'
check "the icon is in the directories the hicolor theme lists" '
  icon="$(sed -n "s/^Icon=//p" /usr/share/applications/$APP_ID.desktop)"
  for file in /usr/share/icons/hicolor/*/apps/$icon.*; do
    dir="${file#/usr/share/icons/hicolor/}"; dir="${dir%/*}"
    grep -qxF "[$dir]" /usr/share/icons/hicolor/index.theme || { echo "$file: hicolor has no folder $dir"; exit 1; }
    echo "$dir"
  done | paste -sd" "'
check "the file types are known and the workbench is their default application" '
  cp "$BANDAI/wave-right-hand_normal_001.bvh" /root/files/
  printf "HIERARCHY\nROOT x\n" >/root/files/no-extension
  echo "{}" >/root/files/session.bunraku.json
  # FBX, glTF and Collada takes: their first bytes (the types are known by name and contents).
  printf "Kaydara FBX Binary  \\000\\032\\000" >/root/files/walk.fbx
  printf "glTF\\002\\000\\000\\000" >/root/files/walk.glb
  echo "{\"asset\": {\"version\": \"2.0\"}}" >/root/files/walk.gltf
  printf "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\"/>\n" >/root/files/walk.dae
  bad=0
  expect() { # expect WHAT GOT WANTED
    if [ "$2" = "$3" ]; then echo "$1: $2"; else echo "$1: got \"$2\", expected \"$3\""; bad=1; fi
  }
  expect "xdg-mime query filetype x.bvh" "$(xdg-mime query filetype /root/files/wave-right-hand_normal_001.bvh)" application/x-bvh
  expect "gio: x.bvh" "$(gio info -a standard::content-type /root/files/wave-right-hand_normal_001.bvh | sed -n "s/^ *standard::content-type: //p")" application/x-bvh
  expect "gio: a file starting with HIERARCHY" "$(gio info -a standard::content-type /root/files/no-extension | sed -n "s/^ *standard::content-type: //p")" application/x-bvh
  expect "xdg-mime query filetype x.bunraku.json" "$(xdg-mime query filetype /root/files/session.bunraku.json)" application/x-bunraku-project
  for take in walk.fbx:model/x-fbx walk.glb:model/gltf-binary walk.gltf:model/gltf+json walk.dae:model/vnd.collada+xml; do
    expect "xdg-mime query filetype ${take%%:*}" "$(xdg-mime query filetype /root/files/${take%%:*})" "${take#*:}"
    expect "gio: ${take%%:*}" "$(gio info -a standard::content-type /root/files/${take%%:*} | sed -n "s/^ *standard::content-type: //p")" "${take#*:}"
  done
  for type in application/x-bvh application/x-bunraku-project application/x-bunraku-corpus model/x-fbx model/gltf-binary model/gltf+json model/vnd.collada+xml; do
    expect "xdg-mime query default $type" "$(xdg-mime query default $type)" "$APP_ID.desktop"
    expect "gio mime $type (default)" "$(gio mime $type | sed -n "1s/^Default application for .*: //p")" "$APP_ID.desktop"
  done
  exit $bad'
double_click='
  . /root/lib.sh
  file=/root/files/wave-right-hand_normal_001.bvh
  rm -rf /root/.config/Bunraku
  echo "$OPENER $file"
  # In the background: xdg-open of a desktop without its own opener waits for the program.
  $OPENER "$file" >/root/opener.out 2>&1 &
  # A BVH opens with the joint-map dialog first; Return accepts its proposal.
  dialog="$(wait_window "\"Joint map for wave-right-hand_normal_001\\.bvh" 60)" || { cat /root/opener.out; exit 1; }
  pid="$(window_pid "$dialog")"
  trap "stop_process $pid" EXIT
  echo "window \"Joint map for wave-right-hand_normal_001.bvh\" of process $pid: $(tr "\0" " " </proc/$pid/cmdline)"
  tr "\0" "\n" </proc/$pid/cmdline | grep -qxF "$file" || { echo "the workbench was not given $file"; exit 1; }
  xdotool windowfocus --sync "$dialog" key Return
  main="$(wait_window "\"[^\"]*wave-right-hand_normal_001[^\"]* - Bunraku Motion Workbench\"" 60)" || exit 1
  echo "main window: $(windows_named "^ *$main ")"
  [ "$(window_pid "$main")" = "$pid" ] || { echo "the window is not of process $pid"; exit 1; }'
check "a double click on a BVH (gio open) opens it in the workbench" "OPENER='gio open'; $double_click"
check "a double click on a BVH (xdg-open) opens it in the workbench" "OPENER=xdg-open; $double_click"
check "with ffmpeg, MP4 export writes the video" '
  bunraku render "$BANDAI/bye_normal_001.bvh" --frames 0:3 -o /root/frames-b --mp4 /root/out.mp4
  [ -s /root/out.mp4 ] && head -c 12 /root/out.mp4 | grep -q ftyp && echo "out.mp4: $(stat -c %s /root/out.mp4) bytes"'
check "apt-get remove, then purge, leave no file of the package and take its file types away" '
  . /root/lib.sh
  apt-get remove -y -qq "$PACKAGE" >/dev/null
  nothing_left
  purge
  type="$(xdg-mime query filetype /root/files/session.bunraku.json)"
  [ "$type" != application/x-bunraku-project ] || { echo "the project type is still known"; exit 1; }
  if grep -l "$APP_ID" /usr/share/applications/mimeinfo.cache /usr/share/mime/globs2 2>/dev/null; then echo "still in the caches above"; exit 1; fi
  echo "after purge: x.bunraku.json is $type"'
finish
