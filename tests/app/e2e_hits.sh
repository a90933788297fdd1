#!/usr/bin/env bash
# End-to-end test of the hits in time order in a real window under Xvfb, driven by xdotool: lesson 17's corner
# scene with the hits layer, one step forward, then a click on each hit's dot on the time bar. The app must show
# each hit at the instant and the place worked out here from the scene (the ball's straight path to the bottom
# cushion, its elastic bounce, then its path to the right cushion), the earlier hit first.
# Usage: e2e_hits.sh SATVIZ SCENE WORKDIR. Exits 77 (skipped) when Xvfb or xdotool is missing.
set -euo pipefail
app=$1 scene=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

rm -rf "$work"
mkdir -p "$work"
# The scene with the hits layer on, in the window's size.
python3 - "$scene" "$work/scene.json" << 'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["view"]["layers"].append("hits")
scene["view"].pop("size", None)
json.dump(scene, open(sys.argv[2], "w"), indent=1)
PY
start_app "$work/scene.json"
xdotool mousemove 300 300
tap period
for _ in $(seq 50); do grep -q "^satviz: hit 2 of step 1 at " "$work/app.log" && break; sleep 0.1; done

# Clicks hit $1's dot; prints the line the app shows it with.
show_hit() {
  local x y
  read -r x y < <(sed -n "s/^satviz: hit $1 of step 1 at \([0-9]*\),\([0-9]*\)$/\1 \2/p" "$work/app.log" | tail -n 1)
  [ -n "${x:-}" ] || { echo "FAILED: the app drew no hit $1 on the time bar" >&2; cat "$work/app.log" >&2; exit 1; }
  xdotool mousemove "$x" "$y"
  sleep 0.2
  xdotool click 1
  for _ in $(seq 30); do grep -q "^satviz: hit $1 of step 1 shown: " "$work/app.log" && break; sleep 0.1; done
  grep "^satviz: hit $1 of step 1 shown: " "$work/app.log" | tail -n 1
}
first=$(show_hit 2)
import -window root "$work/hit2.png" 2> /dev/null || true
second=$(show_hit 1)
python3 - "$work/scene.json" "$first" "$second" << 'PY' || exit 1
import json, sys
scene = json.load(open(sys.argv[1]))
bodies = {b["name"]: b for b in scene["bodies"]}
ball, bottom, right = bodies["ball"], bodies["bottom"], bodies["right"]
r = ball["circle"]["radius"]
(x, y), (vx, vy) = ball["position"], ball["velocity"]
dt = scene["world"]["dt"]
# Down to the bottom cushion's top face, bounce (restitution 1, no friction), on to the right cushion's left face.
top = bottom["position"][1] + bottom["box"][1] / 2
t1 = (y - r - top) / (-vy * dt)
x1, y1 = x + vx * dt * t1, y + vy * dt * t1
left = right["position"][0] - right["box"][0] / 2
t2 = t1 + (left - r - x1) / (vx * dt)
x2, y2 = x1 + vx * dt * (t2 - t1), y1 - vy * dt * (t2 - t1)
names = [b["name"] for b in scene["bodies"]]
def check(line, number, t, other, at):
    words = line.split()
    got = dict(time=float(words[8]), a=int(words[10]), b=int(words[11]),
               pos=[float(v) for v in words[13:17]])
    ball_side = 1 if got["b"] == names.index("ball") else 0
    p = got["pos"][2 * ball_side: 2 * ball_side + 2]
    bodies_ok = {got["a"], got["b"]} == {names.index("ball"), names.index(other)}
    if not bodies_ok or abs(got["time"] - t) > 1e-9 or abs(p[0] - at[0]) > 1e-9 or abs(p[1] - at[1]) > 1e-9:
        sys.exit(f"FAILED: hit {number} shown {got}; expected the ball and {other} at t = {t}, the ball at {at}")
    print(f"hit {number}: the ball and {other} at t = {t:g}, the ball at ({at[0]:g}, {at[1]:g})")
check(sys.argv[3], 1, t1, "bottom", (x1, y1))
check(sys.argv[2], 2, t2, "right", (x2, y2))
PY
tap ctrl+q
wait_for_exit 0
echo "PASSED: clicking a hit on the time bar shows its bodies at its instant, in time order"
