#!/usr/bin/env bash
# A --measure-fps run of the app, in a real window under Xvfb, leaves the Recent list as it was, and prints its
# frame rate. Usage: measure_fps_recent.sh SATVIZ SCENE WORKDIR. Exits 77 (skipped) when Xvfb is missing.
set -euo pipefail
app=$1 scene=$2 work=$3
if ! command -v xvfb-run > /dev/null; then
  echo "SKIPPED: xvfb-run is not installed (apt-get install xvfb xauth)"
  exit 77
fi

rm -rf "$work"
mkdir -p "$work/config/satviz"
export XDG_CONFIG_HOME="$work/config"
printf '/elsewhere/old.json\n' > "$work/config/satviz/recent.txt"
cp "$work/config/satviz/recent.txt" "$work/recent-before.txt"

# Under the sanitizers (SATVIZ_E2E_PRELOAD, tests/CMakeLists.txt), Mesa's software GL driver is loaded before the
# app, so that it stays loaded until the leak check at exit (start_app in e2e_lib.sh says why).
keep=()
if [ -n "${SATVIZ_E2E_PRELOAD:-}" ]; then
  keep=(env "LD_PRELOAD=$SATVIZ_E2E_PRELOAD" "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0")
fi
xvfb-run -a -s "-screen 0 1280x800x24" "${keep[@]}" "$app" "$scene" --measure-fps 5 > "$work/app.log" 2>&1 || {
  echo "FAILED: the app exited with $? for --measure-fps 5:"
  cat "$work/app.log"
  exit 1
}
cat "$work/app.log"
grep -q "frames per second" "$work/app.log" || { echo "FAILED: no frame rate printed"; exit 1; }
if ! cmp -s "$work/recent-before.txt" "$work/config/satviz/recent.txt"; then
  echo "FAILED: the --measure-fps run changed the Recent list:"
  cat "$work/config/satviz/recent.txt"
  exit 1
fi
echo "the Recent list is unchanged"
