# SPDX-License-Identifier: MIT
# What the app's end-to-end scripts share; each sources it first (it reads the script's own arguments):
#  - the skip when Xvfb or xdotool is missing (exit 77, which ctest reports as skipped);
#  - the script run again inside a virtual display of 1280x800;
#  - tap, place, click, start_app, wait_for_exit, read_canvas, body_on_screen and drag below.
for tool in xvfb-run xdotool; do
  if ! command -v "$tool" > /dev/null; then
    echo "SKIPPED: $tool is not installed (apt-get install xvfb xauth xdotool)"
    exit 77
  fi
done
if [ -z "${SATVIZ_E2E_DISPLAY:-}" ]; then
  # -noreset: Xvfb otherwise starts over when its last client leaves (the app ended by a script that starts it
  # again), and a client that connects meanwhile finds no display ("Can't open display").
  exec xvfb-run -a -s "-screen 0 1280x800x24 -noreset" env SATVIZ_E2E_DISPLAY=1 bash "$0" "$@"
fi

# A key held for 80 ms, as a person presses it (ImGui 1.86 reads the keys once per frame, and the app queues key
# events so that a press between two frames is still seen), then $2 seconds (default 0.15) for the app to act on it.
tap() {
  xdotool keydown "$1"
  sleep 0.08
  xdotool keyup "$1"
  sleep "${2:-0.15}"
}

# Where the app announced an item of its interface ("satviz: WHAT at X,Y" on its output), once it is shown.
place() {
  for _ in $(seq 50); do grep -qF "satviz: $1 at " "$work/app.log" && break; sleep 0.1; done
  grep -F "satviz: $1 at " "$work/app.log" | sed -n 's/.* at \([0-9]*\),\([0-9]*\)$/\1 \2/p' | head -n 1
}

# Clicks the item the app announced as WHAT; fails when it never showed.
click() {
  local x y
  read -r x y < <(place "$1") || { echo "FAILED: the app never showed $1"; cat "$work/app.log"; exit 1; }
  xdotool mousemove "$x" "$y"
  sleep 0.2
  xdotool click 1
  sleep 0.3
}

# Starts "$app" with these arguments in the background, its output in $work/app.log, its settings in $work/config
# and its copies of unsaved scenes in $work/state (so the user's are left alone); sets pid, kills the app if the
# script ends early (printing the app's report if it crashed), and waits until the window and its canvas are shown.
start_app() {
  export XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state"
  local keep=()
  if [ -n "${SATVIZ_E2E_PRELOAD:-}" ]; then
    # The sanitizer build (tests/CMakeLists.txt): Mesa's software GL driver, loaded before the app so that it stays
    # until the leak check at exit. libGLX_mesa loads it for the window's GL context and unloads it when
    # glfwTerminate closes the display; the driver keeps 240 bytes of one-time allocations in its own globals, and
    # unloaded, it takes their only pointers with it. LeakSanitizer then reports them from frames of a module gone,
    # which it cannot name and no suppression can match. Loaded first, the driver is never unloaded and still holds
    # them; the app's own allocations are checked as before. (LD_PRELOAD puts it ahead of the sanitizer's runtime.)
    keep=(env "LD_PRELOAD=$SATVIZ_E2E_PRELOAD" "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0")
  fi
  "${keep[@]}" "$app" "$@" > "$work/app.log" 2>&1 &
  pid=$!
  trap 'kill $pid 2> /dev/null || true; sed -n "/^satviz: crashed/,\$p" "$work/app.log" | head -n 80' EXIT
  xdotool search --sync --onlyvisible --name '^satviz$' > /dev/null
  for _ in $(seq 50); do grep -q "canvas at" "$work/app.log" && break; sleep 0.1; done
}

# Waits up to 10 s for the app to end (after ctrl+q, or a signal the script sent it) and requires its exit status to
# be $1: 0 for a quit, 128 + N for signal N. An app that faults or aborts on its way out (a destructor, the sanitizer
# build's leak check) fails here with its output. One that does not end is killed, and the test fails ($2, if given,
# says what may have held it).
wait_for_exit() {
  local expected=$1 status=0
  for _ in $(seq 100); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
  trap - EXIT
  if kill -0 $pid 2> /dev/null; then
    kill $pid
    wait $pid 2> /dev/null || true
    echo "FAILED: the app did not end within 10 s${2:+ ($2)}"
    cat "$work/app.log"
    exit 1
  fi
  wait $pid || status=$?
  if [ "$status" -ne "$expected" ]; then
    echo "FAILED: the app ended with status $status$( ((status > 128)) && echo " (signal $((status - 128)))"), not $expected:"
    cat "$work/app.log"
    exit 1
  fi
}

# The canvas and its camera as the app announced them: sets cx cy (its corner in the window), cw ch (its size), vx vy
# (the world point at its centre) and zoom (pixels per unit).
read_canvas() {
  read -r cx cy cw ch vx vy zoom < <(sed -n 's/^satviz: canvas at \([0-9]*\),\([0-9]*\) size \([0-9]*\)x\([0-9]*\) camera \([-0-9.e]*\),\([-0-9.e]*\) zoom \([-0-9.e]*\)$/\1 \2 \3 \4 \5 \6 \7/p' "$work/app.log")
}

# Where body $1 of the scene file $2 has its origin in the window, by the camera read_canvas read: prints "x y".
body_on_screen() {
  python3 - "$2" "$1" "$cx" "$cy" "$cw" "$ch" "$vx" "$vy" "$zoom" << 'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
cx, cy, cw, ch, vx, vy, zoom = map(float, sys.argv[3:])
x, y = next(b for b in scene["bodies"] if b["name"] == sys.argv[2]).get("position", [0, 0])
print(int(cx + cw / 2 + (x - vx) * zoom), int(cy + ch / 2 - (y - vy) * zoom))
PY
}

# A drag with the left button as a hand makes it: press at ($1, $2), move there by ($3, $4) pixels in six steps,
# release.
drag() {
  xdotool mousemove "$1" "$2"
  sleep 0.3
  xdotool mousedown 1
  sleep 0.2
  for i in $(seq 1 6); do
    xdotool mousemove $(($1 + $3 * i / 6)) $(($2 + $4 * i / 6))
    sleep 0.03
  done
  sleep 0.2
  xdotool mouseup 1
}
