#!/usr/bin/env bash
# End-to-end test of a crash in a real window under Xvfb, driven by xdotool: drag body B (an unsaved change), then
# end the app by the signal of a crash (SIGSEGV). The app must say that it crashed, where the unsaved change is and
# the calls that led to it; the copy must hold the dragged scene. The next start tells where the copy is.
# Usage: e2e_crash.sh SATVIZ SCENE WORKDIR. Exits 77 (skipped) when Xvfb or xdotool is missing.
set -euo pipefail
app=$1 scene=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

rm -rf "$work"
mkdir -p "$work"
cp "$scene" "$work/scene.json"
start_app "$work/scene.json"
read_canvas
# Body B's origin on screen, from the camera; dragged 60 px right and 24 px up.
read -r bx by < <(body_on_screen B "$work/scene.json")
drag "$bx" "$by" 60 -24
copy="$work/state/satviz/unsaved/scene.unsaved-$pid.json"
for _ in $(seq 50); do [ -f "$copy" ] && break; sleep 0.1; done
[ -f "$copy" ] || { echo "FAILED: no copy of the unsaved drag at $copy"; ls -R "$work/state" 2> /dev/null; exit 1; }

kill -SEGV $pid
# Ended by the signal, after its report: 128 + 11.
wait_for_exit $((128 + 11)) "the crash report?"
grep -qxF "satviz: crashed (signal 11); the unsaved changes are in $copy" "$work/app.log" ||
  { echo "FAILED: the app did not say where the unsaved changes are:"; cat "$work/app.log"; exit 1; }
sed -n '/^satviz: the calls that led to it:$/,$p' "$work/app.log" | grep -q "satviz(" ||
  { echo "FAILED: the app did not print the calls that led to the crash:"; cat "$work/app.log"; exit 1; }
echo "the app said it crashed, where the unsaved changes are, and the calls that led there"
# The copy: B moved by the drag (right and up, by about the pointer's 60 px and 24 px), A where it was.
python3 - "$work/scene.json" "$copy" "$zoom" << 'PY' || exit 1
import json, sys
before, after = (json.load(open(f)) for f in sys.argv[1:3])
zoom = float(sys.argv[3])
def position(scene, name):
    return next(b for b in scene["bodies"] if b["name"] == name).get("position", [0, 0])
(x0, y0), (x1, y1) = position(before, "B"), position(after, "B")
dx, dy = (x1 - x0) * zoom, (y1 - y0) * zoom
if not (40 <= dx <= 70 and 12 <= dy <= 30):
    sys.exit(f"FAILED: in the copy B moved ({dx:.1f}, {dy:.1f}) px, the pointer (60, 24)")
if position(before, "A") != position(after, "A"):
    sys.exit("FAILED: in the copy A moved, and nothing moved it")
print(f"the copy holds the drag: B moved ({dx:.1f}, {dy:.1f}) px")
PY

cp "$work/app.log" "$work/crash.log"
# The next start says where the changes are.
start_app "$work/scene.json"
for _ in $(seq 50); do grep -q "^satviz: satviz ended before" "$work/app.log" && break; sleep 0.1; done
grep -qF "satviz: satviz ended before these changes were saved; they are in $copy" "$work/app.log" ||
  { echo "FAILED: the next start did not tell where the unsaved changes are:"; cat "$work/app.log"; exit 1; }
tap ctrl+q 0.12
wait_for_exit 0
[ -f "$copy" ] || { echo "FAILED: the copy is gone though nobody took it back"; exit 1; }
echo "PASSED: a crash keeps the unsaved drag in a copy, says where, and the next start says it again"
