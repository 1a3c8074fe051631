#!/usr/bin/env bash
# Our MikkTSpace tangents against the reference implementation (npm `mikktspace`, installed once
# into the build folder) on real faired meshes, undecimated and decimated to 10%.
#   mikktspace_reference_test.sh BUILD_DIR DUMP_TOOL MODELS_DIR
set -euo pipefail
build=$1 dump=$2 models=$3
here=$(cd "$(dirname "$0")" && pwd)
if [ ! -d "$models/vxl" ]; then echo "SKIP: shared models folder $models is absent"; exit 77; fi
command -v node >/dev/null && command -v npm >/dev/null || { echo "SKIP: node and npm are needed (Debian: nodejs npm)"; exit 77; }
prefix=$build/npm
if [ ! -f "$prefix/node_modules/mikktspace/package.json" ]; then
  mkdir -p "$prefix"
  npm install --prefix "$prefix" --no-audit --no-fund --silent mikktspace@1.1.1 >/dev/null
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$dump" "$out" "$models/vxl/3tnk.vxl" "$models/vxl/hmec.vxl" "$models/vox/robo.vox" "$models/vox/crabby.vox" >/dev/null
node "$here/mikktspace_reference.mjs" "$prefix/node_modules" "$out"/*.bin
