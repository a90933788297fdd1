#!/bin/sh
# The screenshots of docs/programs.md, taken from the app in a 1280 x 800 window on an X display:
#   Xvfb :58 -screen 0 1280x800x24 &
#   DISPLAY=:58 app/screenshots/make.sh build/release/app/satviz
# Needs xdotool and ImageMagick's import. Run from the repository's top folder; writes app/screenshots/*.png.
set -eu
app=${1:?usage: make.sh PATH/TO/satviz}
out=app/screenshots
scenes=tutorials/scenes
log=$(mktemp)
trap 'rm -f "$log"' EXIT

# A key held about 80 ms, as a hand presses it, then time for the frame.
key() {
  xdotool keydown "$1"
  sleep 0.08
  xdotool keyup "$1"
  sleep 0.3
}

# Starts the app on scene $1 (more arguments passed on), waits for its first frames.
start() {
  "$app" --window 1280x800 "$@" > "$log" 2>&1 &
  pid=$!
  sleep 2.5
}

# Ends the app started last: it has no unsaved changes, so nothing asks.
stop() {
  kill "$pid"
  wait "$pid" 2> /dev/null || true
}

# The window's point of world point ($1, $2), from the canvas the app reports ("canvas at X,Y size WxH camera CX,CY
# zoom Z").
screen_of() {
  awk -v wx="$1" -v wy="$2" '/^satviz: canvas at/ {
      split($4, at, ","); split($6, size, "x"); split($8, centre, ",")
      x = at[1] + size[1] / 2 + (wx - centre[1]) * $10
      y = at[2] + size[2] / 2 - (wy - centre[2]) * $10
    } END { printf "%d %d\n", x, y }' "$log"
}

shot() {
  sleep 0.5
  import -window root -crop 1280x800+0+0 +repage "$out/$1"
}

# Stepping through the static test: overlapping_boxes at its third axis, B selected (its turning handle above it and,
# beside the still body, the diamond that sets its velocity).
start "$scenes/overlapping_boxes.json"
read -r bx by << EOF
$(screen_of 1.3 0.6)
EOF
xdotool mousemove "$bx" "$by" click 1
sleep 0.3
xdotool mousemove 5 400
key Left
key Left
shot step.png
stop

# The swept test, axis by axis, with its time bar: circle_and_polygon at its third axis.
start "$scenes/circle_and_polygon.json"
key Left
key Left
key Left
shot sweep.png
stop

# F1: the controls and the conventions.
start "$scenes/separated_triangle.json"
key F1
shot help.png
stop
