#!/usr/bin/env bash
# voxelfair's one entry point. Run as root on Debian 12 (or as a user with sudo).
#
#   bash voxelfair.sh demo    set up, build, and convert the bundled example tank -> out/
#   bash voxelfair.sh test    set up, build, and run the whole test suite (CTest)
#   bash voxelfair.sh setup   only install the Debian packages
#   bash voxelfair.sh build   set up and build (plugins, private MeshLab runtime, tests)
#   bash voxelfair.sh install set up, build, and install the plugins for the system's MeshLab GUI
#
# Every step is idempotent: packages are installed only when missing, the MeshLab SDK is fetched
# once into ~/.cache/voxelfair, and the build is incremental.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${VOXELFAIR_BUILD_DIR:-$here/build}
jobs=$(nproc 2>/dev/null || echo 2)

packages=(
  build-essential cmake pkg-config git ca-certificates dpkg-dev
  meshlab qtbase5-dev libqt5opengl5-dev libglew-dev libeigen3-dev libglm-dev zlib1g-dev libtinygltf-dev
  libgtest-dev libbenchmark-dev xvfb xauth x11-utils xdotool imagemagick python3 libvtk9-dev
  blender python3-numpy clang-format clang-tidy ccache goxel
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; elif command -v sudo >/dev/null; then sudo "$@"; else
    echo "voxelfair: installing packages needs root (run as root or install sudo)" >&2; exit 1; fi
}

setup() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "voxelfair: installing ${missing[*]}"
    as_root apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}" \
      libgl1-mesa-dri
  fi
  # Khronos' glTF validator (npm) for the export tests: Node from Debian when there is none.
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    as_root apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends nodejs npm
  fi
  local npm_dir=${VOXELFAIR_NPM_DIR:-$HOME/.cache/voxelfair/npm}
  if [ ! -f "$npm_dir/node_modules/gltf-validator/package.json" ]; then
    echo "voxelfair: installing gltf-validator (npm) into $npm_dir"
    mkdir -p "$npm_dir"
    npm install --prefix "$npm_dir" --no-audit --no-fund --silent gltf-validator
  fi
}

build() {
  setup
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$build" -j"$jobs"
}

demo() {
  build
  local out=${VOXELFAIR_DEMO_OUT:-$here/out}
  python3 "$here/meshlab_scripts/voxelfair_convert.py" --build "$build" \
    "$build/examples/tank.vxl" --output "$out"
}

run_tests() {
  build
  ctest --test-dir "$build" --output-on-failure -j"$jobs" "$@"
}

case "${1:-}" in
  setup) setup ;;
  build) build ;;
  demo) demo ;;
  test) shift; run_tests "$@" ;;
  install) build; as_root cmake --install "$build" ;;
  *) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
