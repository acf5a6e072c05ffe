#!/usr/bin/env bash
# Installs every build, test and run dependency of Bunraku Motion Workbench from Debian
# bookworm's packages. Non-interactive, idempotent, safe to re-run: packages already present
# are left alone and apt-get is only called when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev libqt6openglwidgets6 libgl-dev
  libqcustomplot-dev libqcustomplot2.1-qt6
  libeigen3-dev libglm-dev nlohmann-json3-dev libcli11-dev catch2 libtinygltf-dev
  libfftw3-dev libassimp-dev libbenchmark-dev assimp-utils
  xvfb xauth libgl1-mesa-dri libglx-mesa0 libegl-mesa0 mesa-utils
  fonts-dejavu-core ffmpeg chromium
  librsvg2-bin help2man file dpkg-dev
  lintian desktop-file-utils appstream shared-mime-info man-db strace
  # a clean Debian root to install the package into with apt (scripts/clean-root-check.sh)
  mmdebstrap
  # Blender 3.4: the real client the BVH and glTF exports are checked against (tests/cli)
  blender
  clang-14 libfuzzer-14-dev
  python3 python3-numpy python3-pywt python3-statsmodels
  # the Python module (bindings/python, docs/PYTHON.md): pybind11, and its tests and example
  pybind11-dev python3-dev python3-pytest python3-pandas python3-matplotlib mypy
  # Snakemake: the batch workflow over motion-capture libraries (workflows/Snakefile)
  snakemake
)

# The Khronos glTF validator, the peer of the .glb exports' tests (tests/support/gltf_validator.h):
# npm's package, installed globally when node's npm is there (else those tests skip, or fail under CI).
install_gltf_validator() {
  if command -v npm >/dev/null 2>&1 && [ ! -d "$(npm root -g)/gltf-validator" ]; then
    echo "install-deps: installing npm gltf-validator"
    npm install -g --no-audit --no-fund gltf-validator@2.0.0-dev.3.10
  fi
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  install_gltf_validator
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_gltf_validator
