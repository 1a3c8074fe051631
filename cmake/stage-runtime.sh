#!/usr/bin/env bash
# usage: stage-runtime.sh RUNTIME_DIR MESHLAB_LIBRARY_DIR PLUGIN.so...
# Builds RUNTIME_DIR/bin/{meshlabserver,meshlab} (copies) and
# RUNTIME_DIR/lib/x86_64-linux-gnu/meshlab/{libmeshlab-common.so,plugins/*} (links).
set -euo pipefail
runtime=$1; system_lib=$2; shift 2
lib="$runtime/lib/x86_64-linux-gnu/meshlab"
mkdir -p "$runtime/bin" "$lib/plugins"
for exe in meshlabserver meshlab; do
  src=$(command -v "$exe" || true)
  [ -n "$src" ] || { echo "stage-runtime: $exe is not installed (apt-get install meshlab)" >&2; exit 1; }
  # A copy, not a link: MeshLab finds its plugins relative to the binary's real path.
  if ! cmp -s "$src" "$runtime/bin/$exe"; then cp -f "$src" "$runtime/bin/$exe"; fi
done
ln -sfn "$system_lib/libmeshlab-common.so" "$lib/libmeshlab-common.so"
for p in "$system_lib"/plugins/*.so; do
  name=$(basename "$p")
  [ -e "$lib/plugins/$name" ] && [ ! -L "$lib/plugins/$name" ] && continue
  ln -sfn "$p" "$lib/plugins/$name"
done
for p in "$@"; do ln -sfn "$p" "$lib/plugins/$(basename "$p")"; done
