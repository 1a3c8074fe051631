#!/usr/bin/env bash
# GUI test: a real MeshLab window (the staged runtime's meshlab) under Xvfb opens a model
# through voxelfair's importer: the importer's parameter dialog appears, is accepted, the model
# loads and our report reaches MeshLab's log; screenshots of both go to OUT_DIR.
#
# usage: gui_import_test.sh MESHLAB_BINARY MODEL EXPECTED_LOG_TEXT OUT_DIR
set -euo pipefail
meshlab=$1 model=$2 expected=$3 out=$4
mkdir -p "$out"
work=$(mktemp -d /tmp/voxelfair-gui.XXXXXX)
chmod 700 "$work"

for n in $(seq 71 140); do [ -e "/tmp/.X$n-lock" ] || { display=":$n"; break; }; done
Xvfb "$display" -screen 0 1280x800x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb=$!
meshlab_pid=
cleanup() {
  [ -n "$meshlab_pid" ] && kill "$meshlab_pid" 2>/dev/null || true
  kill "$xvfb" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
export DISPLAY=$display XDG_CONFIG_HOME=$work XDG_RUNTIME_DIR=$work
for _ in $(seq 50); do xdpyinfo >/dev/null 2>&1 && break; sleep 0.1; done

"$meshlab" "$model" >"$work/meshlab.log" 2>&1 &
meshlab_pid=$!

# wait_for SECONDS COMMAND...: polls until COMMAND succeeds.
wait_for() {
  local seconds=$1; shift
  for _ in $(seq $((seconds * 5))); do "$@" >/dev/null 2>&1 && return 0; sleep 0.2; done
  return 1
}

if ! wait_for 60 xdotool search --onlyvisible --name '^Pre-Open Options$'; then
  echo "FAIL: the importer's parameter dialog did not appear"; cat "$work/meshlab.log"; exit 1
fi
sleep 0.5
import -window root "$out/import-dialog.png"
dialog=$(xdotool search --onlyvisible --name '^Pre-Open Options$' | head -n1)
xdotool windowfocus --sync "$dialog" key --clearmodifiers Return

if ! wait_for 60 grep -q "io_vxl: .*$expected" "$work/meshlab.log"; then
  echo "FAIL: no importer report containing '$expected' in MeshLab's log"; cat "$work/meshlab.log"; exit 1
fi
wait_for 30 grep -q "All files opened" "$work/meshlab.log" || true
sleep 1
import -window root "$out/imported.png"
if ! kill -0 "$meshlab_pid" 2>/dev/null; then
  echo "FAIL: MeshLab exited after the import"; cat "$work/meshlab.log"; exit 1
fi
grep "io_vxl:" "$work/meshlab.log"
echo "PASS: imported through the dialog; screenshots in $out"
