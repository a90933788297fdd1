#!/usr/bin/env bash
# End-to-end test of drawing and cutting in the app, in a real window under Xvfb driven by xdotool: d, then eight
# clicks draw a U (concave) below the boxes and a click on its first vertex closes it; x, then a drag across both
# prongs cuts it; ctrl+s saves, ctrl+q quits. The saved scene must hold the U cut in three: the base (still concave)
# and the two prong tops, their areas (shoelace sums of the saved outlines) adding up to the U's, each on its side
# of the cut.
# Usage: e2e_draw.sh SATVIZ SCENE WORKDIR. Exits 77 (skipped) when Xvfb or xdotool is missing.
set -euo pipefail
app=$1 scene=$2 work=$3
source "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

rm -rf "$work"
mkdir -p "$work"
cp "$scene" "$work/scene.json"
start_app "$work/scene.json"
read_canvas
echo "canvas at $cx,$cy size ${cw}x$ch, camera at $vx,$vy zoom $zoom"

# A world point on screen, from the camera.
screen() {
  awk -v cx="$cx" -v cy="$cy" -v cw="$cw" -v ch="$ch" -v vx="$vx" -v vy="$vy" -v z="$zoom" -v x="$1" -v y="$2" \
    'BEGIN { printf "%d %d\n", cx + cw / 2 + (x - vx) * z, cy + ch / 2 - (y - vy) * z }'
}
click_at() {
  local x y
  read -r x y < <(screen "$1" "$2")
  xdotool mousemove "$x" "$y"
  sleep 0.15
  xdotool mousedown 1
  sleep 0.08
  xdotool mouseup 1
  sleep 0.2
}

# The U: 3 wide, 2 tall, its 1 x 1 notch open upwards; area 5.
tap d 0.25
for p in "-3 -2.6" "0 -2.6" "0 -0.6" "-1 -0.6" "-1 -1.6" "-2 -1.6" "-2 -0.6" "-3 -0.6"; do
  click_at $p
done
import -window root "$work/drawing.png" 2> /dev/null || true
click_at -3 -2.6

# The cut: a drag from left of the U to right of it at y = -1.1, across both prongs.
tap x 0.25
read -r x0 y0 < <(screen -3.5 -1.1)
read -r x1 y1 < <(screen 0.5 -1.1)
xdotool mousemove "$x0" "$y0"
sleep 0.15
xdotool mousedown 1
sleep 0.1
for i in $(seq 1 8); do
  xdotool mousemove $((x0 + (x1 - x0) * i / 8)) $((y0 + (y1 - y0) * i / 8))
  sleep 0.04
done
sleep 0.2
xdotool mouseup 1
sleep 0.4
import -window root "$work/cut.png" 2> /dev/null || true
tap Escape 0.25

xdotool keydown ctrl
tap s 0.25
xdotool keyup ctrl
sleep 0.3
xdotool keydown ctrl
tap q 0.25
xdotool keyup ctrl
wait_for_exit 0 "unsaved changes?"
cat "$work/app.log"

python3 - "$work/scene.json" "$zoom" << 'PY' || exit 1
import json, math, sys
scene = json.load(open(sys.argv[1]))
pixel = 1 / float(sys.argv[2])
bodies = {b["name"]: b for b in scene["bodies"]}
names = sorted(bodies)
if names != ["A", "B", "polygon1", "polygon1.1", "polygon1.2"]:
    sys.exit(f"FAILED: expected A, B and the U cut in three (polygon1, polygon1.1, polygon1.2), saved {names}")

def world(body):
    # The outline in the world: the scene writes it in the body frame, at its position and angle.
    px, py = body.get("position", [0, 0])
    a = body.get("angle", 0)
    c, s = math.cos(a), math.sin(a)
    return [(px + c * x - s * y, py + s * x + c * y) for x, y in body["polygon"]]

def area(points):
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1])) / 2

parts = [world(bodies[n]) for n in ("polygon1", "polygon1.1", "polygon1.2")]
areas = [abs(area(p)) for p in parts]
# Every vertex was placed by a click, to within a pixel: the areas to within the perimeter times a pixel.
if abs(sum(areas) - 5) > 16 * pixel:
    sys.exit(f"FAILED: the parts' areas {areas} do not add up to the U's 5")
base = max(range(3), key=lambda i: areas[i])
if abs(areas[base] - 4) > 12 * pixel or len(parts[base]) < 8:
    sys.exit(f"FAILED: the base should be the U below the cut, area 4 and concave: {parts[base]}")
for i in range(3):
    ys = [y for _, y in parts[i]]
    below = i == base
    if below and max(ys) > -1.1 + 2 * pixel or not below and (min(ys) < -1.1 - 2 * pixel or abs(areas[i] - 0.5) > 6 * pixel):
        sys.exit(f"FAILED: part {i} is not on its side of the cut at y = -1.1: {parts[i]}")
print(f"PASSED: the drawn U was cut into parts of areas {', '.join(f'{a:.4f}' for a in areas)}, saved")
PY
