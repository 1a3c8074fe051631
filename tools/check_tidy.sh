#!/usr/bin/env bash
# Runs clang-tidy (.clang-tidy's focused check set, every finding an error) over the host-free
# code: libvoxelfair/, tools/ and examples/. The MeshLab adapters are left out (their findings
# would be MeshLab's headers'). Needs only a configured build folder for compile_commands.json:
# build-tidy/, configured without the plugins, in a few seconds.
#
#   tools/check_tidy.sh                 all files, 2 jobs
#   tools/check_tidy.sh FILE...         only these
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
build=${VOXELFAIR_TIDY_BUILD_DIR:-$here/build-tidy}
jobs=${VOXELFAIR_TIDY_JOBS:-2}
command -v clang-tidy >/dev/null && command -v run-clang-tidy >/dev/null || bash "$here/voxelfair.sh" setup

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DVOXELFAIR_BUILD_PLUGINS=OFF \
  -DVOXELFAIR_BUILD_BENCHMARKS=OFF -DVOXELFAIR_BUILD_TESTS=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null

if (($#)); then
  files=("$@")
else
  mapfile -t files < <(git ls-files 'libvoxelfair/*.cpp' 'tools/*.cpp' 'examples/*.cpp')
fi
# run-clang-tidy takes regular expressions: anchor each path.
patterns=()
for f in "${files[@]}"; do patterns+=("$here/$f\$"); done
run-clang-tidy -quiet -p "$build" -j "$jobs" "${patterns[@]}" 2>/dev/null | grep -v '^[0-9]* warnings\? generated\.$' \
  | tee "$build/tidy.log" || true
# run-clang-tidy's exit status is not reliable across versions: fail on any diagnostic.
if grep -qE '(warning|error):' "$build/tidy.log"; then
  echo "clang-tidy: findings above (.clang-tidy)" >&2
  exit 1
fi
echo "clang-tidy: ${#files[@]} files clean"
