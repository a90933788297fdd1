#!/usr/bin/env bash
# End-to-end test of the smallest window in a real window under Xvfb, driven by xdotool: a window asked for smaller
# than the side panel and a readable canvas need (360 x 600 pixels beside the panel, and beside the lesson column
# while a lesson is open) is enlarged to it before its first frame, and stays so when shrunk.
# Usage: e2e_size.sh SATVIZ SCENE WORKDIR. Exits 77 (skipped) when Xvfb or xdotool is missing.
set -euo pipefail
app=$1 scene=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

rm -rf "$work"
mkdir -p "$work"
# The side panel is 388 pixels wide (with its scroll bar), the lesson column 440; the menu and status bars take some 40 pixels.
check_size() {
  local least=$1 what=$2 width height tries # geometry: the size last seen, for the caller
  # The app enlarges the window on one of its next frames: a loaded machine may take seconds to draw them.
  for tries in $(seq 40); do
    sleep 0.25
    geometry=$(xdotool search --name '^satviz$' getwindowgeometry | sed -n 's/.*Geometry: //p')
    width=${geometry%x*} height=${geometry#*x}
    if [ "$width" -ge "$least" ] && [ "$height" -ge 640 ]; then
      echo "$what: ${geometry}"
      return
    fi
  done
  echo "FAILED: $what: the window is ${geometry} after 10 s, smaller than ${least}x640"
  exit 1
}
# The canvas the app announces first is the one it keeps, framed for it: at least 360 x 600, with the camera of a
# window opened at that size (a first frame at 200 x 150 had a 64 x 108 canvas and a camera fitted to it).
first_canvas() {
  sed -n 's/.*canvas at [0-9]*,[0-9]* size \([0-9]*x[0-9]*\) camera \(.*\)$/\1 \2/p' "$work/app.log" | head -n 1
}
# Quits by ctrl+q with the pointer on the window (without a window manager the keys go to the window under it).
quit() {
  xdotool mousemove 200 200
  tap ctrl+q
  wait_for_exit 0
}
start_app "$scene" --window 200x150
check_size 748 "asked for 200x150"
tiny=$(first_canvas)
grown=$geometry
read -r canvas_size _ <<< "$tiny"
if [ "${canvas_size%x*}" -lt 360 ] || [ "${canvas_size#*x}" -lt 600 ]; then
  echo "FAILED: asked for 200x150, the first canvas announced is $tiny, smaller than 360x600"
  exit 1
fi
quit
start_app "$scene" --window "$grown"
if [ "$(first_canvas)" != "$tiny" ]; then
  echo "FAILED: the first canvas at 200x150 is \"$tiny\", at $grown it is \"$(first_canvas)\""
  exit 1
fi
echo "first canvas at 200x150 as at $grown: $tiny"
quit
start_app "$scene" --window 200x150
check_size 748 "asked for 200x150 again"
xdotool search --name '^satviz$' windowsize 300 200
check_size 748 "shrunk to 300x200"
quit
start_app "$scene" --window 400x300 --lesson 1
check_size 1188 "with a lesson open"
quit
echo "PASSED: the window keeps room for the panels and a readable canvas"
