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

# Under the sanitizers, this path's exit leaves a few hundred bytes of Mesa's GLX driver, unloaded by then, so that
# LeakSanitizer names no module to suppress (tests/lsan.supp): leak checking is off for this run only. The end-to-end
# test (e2e.sh) checks the app's own allocations for leaks.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  xvfb-run -a -s "-screen 0 1280x800x24" "$app" "$scene" --measure-fps 5 > "$work/app.log" 2>&1 || {
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
