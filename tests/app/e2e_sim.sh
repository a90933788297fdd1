#!/usr/bin/env bash
# End-to-end test of the app's simulation in a real window under Xvfb, driven by xdotool: play lesson 14's head-on
# scene, pause, step back twice and forward once; the state the app shows at each of those steps must be the bits
# satviz-sim prints for that step. Then from Reset step to the hit, choose the contact from the step's list, and
# check the numbers of its response against the world's record as satviz-sim prints it.
# Usage: e2e_sim.sh SATVIZ SATVIZ_SIM SCENE WORKDIR. Exits 77 (skipped) when Xvfb or xdotool is missing.
set -euo pipefail
app=$1 sim=$2 scene=$3 work=$4
source "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

# The step of the last state the app printed, once it has printed the state of a step other than $1.
last_step() {
  for _ in $(seq 50); do
    local step
    step=$(grep '^satviz: state step ' "$work/app.log" | tail -n 1 | cut -d' ' -f4)
    if [ -n "$step" ] && [ "$step" != "$1" ]; then echo "$step"; return; fi
    sleep 0.1
  done
  echo "FAILED: the app printed no new state after step $1" >&2
  exit 1
}

# Compares the state the app printed for step $1 with satviz-sim's, bit for bit.
check_state() {
  "$sim" "$work/scene.json" --steps "$1" --every "$1" 2> /dev/null | tail -n 1 > "$work/sim-$1.json"
  grep "^satviz: state step $1 " "$work/app.log" | tail -n 1 > "$work/app-$1.txt"
  python3 - "$work/sim-$1.json" "$work/app-$1.txt" "$1" << 'PY' || exit 1
import json, sys
sim = json.load(open(sys.argv[1]))
shown = open(sys.argv[2]).read().split()[4:]
if sim["step"] != int(sys.argv[3]):
    sys.exit(f"FAILED: satviz-sim printed step {sim['step']}, not {sys.argv[3]}")
want = []
for body in sim["bodies"]:
    want += body["position"] + [body["angle"]] + body["velocity"] + [body["angular_velocity"]]
got = [float(v) for v in shown]
if got != want:
    sys.exit(f"FAILED: at step {sys.argv[3]} the app shows {got}, satviz-sim {want}")
print(f"step {sys.argv[3]}: the app's state equals satviz-sim's, bit for bit")
PY
}

rm -rf "$work"
mkdir -p "$work"
cp "$scene" "$work/scene.json"
start_app "$work/scene.json"
read -r _ _ < <(place "simulation Play")
xdotool mousemove 300 500

tap p
sleep 0.5
tap p
played=$(last_step 0)
[ "$played" -ge 5 ] || { echo "FAILED: half a second of play took $played steps"; exit 1; }
check_state "$played"
tap comma
tap comma
back=$(last_step "$played")
sleep 0.3
back=$(last_step "$played")
[ "$back" -eq $((played - 2)) ] || { echo "FAILED: two steps back from $played show step $back"; exit 1; }
check_state "$back"
tap period
forward=$(last_step "$back")
[ "$forward" -eq $((played - 1)) ] || { echo "FAILED: a step forward from $back shows step $forward"; exit 1; }
check_state "$forward"

# The hit: 1.5 m apart, closing at 4 m/s, they touch at 0.375 s, within step 23 (dt 1/60 s).
click "simulation Reset"
for _ in $(seq 23); do tap period; done
sleep 0.3
[ "$(last_step 0)" -eq 23 ] || { echo "FAILED: 23 steps forward from Reset show step $(last_step 0)"; exit 1; }
check_state 23
click "contact A B"
import -window root "$work/screenshot.png" 2> /dev/null || true
for _ in $(seq 30); do grep -q "^satviz: response step 23 A B: Velocities" "$work/app.log" && break; sleep 0.1; done
"$sim" "$work/scene.json" --steps 23 --every 1 2> /dev/null | sed -n '22p;23p' > "$work/sim-22-23.json"
python3 - "$work/app.log" "$work/sim-22-23.json" << 'PY' || exit 1
import json, re, sys
lines = [l for l in open(sys.argv[1]) if l.startswith("satviz: response step 23 A B: ")]
if not lines:
    sys.exit("FAILED: the app showed no response of A and B at step 23")
text = "".join(lines)
before, after = [json.loads(l) for l in open(sys.argv[2])]
vb = {b["name"]: b["velocity"][0] for b in before["bodies"]}
va = {b["name"]: b["velocity"][0] for b in after["bodies"]}
approach = re.search(r"Approach: vn = .* = (-?[0-9.]+) m/s", text)
if not approach or float(approach.group(1)) != round(vb["B"] - vb["A"], 2):
    sys.exit(f"FAILED: the approach speed shown is not vB - vA at step 22 ({vb}): {text}")
for name in ("A", "B"):
    m = re.search(name + r": v \((-?[0-9.]+), (-?[0-9.]+)\) -> \((-?[0-9.]+), (-?[0-9.]+)\)", text)
    if not m or float(m.group(1)) != round(vb[name], 2) or float(m.group(3)) != round(va[name], 2):
        sys.exit(f"FAILED: {name}'s velocities in the response are not satviz-sim's at steps 22 and 23: {text}")
print("the response of A and B at step 23 quotes the world's velocities before and after the step")
PY
tap ctrl+q
wait_for_exit 0
echo "PASSED: play, pause, back and forward show satviz-sim's states; the response quotes the world's record"
