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

# Xvfb picks a free display itself and writes its number once it accepts connections
# (-displayfd), so neither a display taken by a parallel test nor a slow start under load can
# leave MeshLab without a screen. -noreset: by default the server resets when its last client
# leaves (our xdpyinfo probe), and a client connecting during that reset is refused.
Xvfb -displayfd 3 -noreset -screen 0 1280x800x24 -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
xvfb=$!
meshlab_pid=
cleanup() {
  [ -n "$meshlab_pid" ] && kill "$meshlab_pid" 2>/dev/null || true
  kill "$xvfb" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
for _ in $(seq 300); do
  [ -s "$work/display" ] && break
  kill -0 "$xvfb" 2>/dev/null || break
  sleep 0.1
done
if [ ! -s "$work/display" ]; then
  echo "FAIL: Xvfb did not start within 30 s"; cat "$work/xvfb.log"; exit 1
fi
export DISPLAY=":$(tr -dc 0-9 <"$work/display")" XDG_CONFIG_HOME=$work XDG_RUNTIME_DIR=$work
if ! xdpyinfo >/dev/null 2>&1; then
  echo "FAIL: Xvfb reported $DISPLAY but it does not answer"; cat "$work/xvfb.log"; exit 1
fi

"$meshlab" "$model" >"$work/meshlab.log" 2>&1 &
meshlab_pid=$!

# wait_for SECONDS COMMAND...: polls until COMMAND succeeds; gives up early if MeshLab died.
wait_for() {
  local seconds=$1; shift
  for _ in $(seq $((seconds * 5))); do
    "$@" >/dev/null 2>&1 && return 0
    kill -0 "$meshlab_pid" 2>/dev/null || { "$@" >/dev/null 2>&1; return; }
    sleep 0.2
  done
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
