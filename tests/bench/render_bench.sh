#!/usr/bin/env bash
# Figure rendering speed: milliseconds per 800x600 figure, for one figure (a whole process: OpenGL context, fonts,
# shader compilation) and for a batch of 100 figures in one call (satviz-render's own per-figure timing after the
# first, drawing plus PNG encoding). Usage: tests/bench/render_bench.sh [BUILD_DIR] (default build/release).
set -euo pipefail
cd "$(dirname "$0")/../.."
render="${1:-build/release}/render/satviz-render"
[ -x "$render" ] || { echo "render_bench: $render not found (build the satviz-render target first)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

scenes=(tutorials/scenes/*.json)
echo "satviz-render, 800x600 figures of the ${#scenes[@]} tutorial scenes; $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"

start=$(date +%s%N)
"$render" -q --size 800x600 tutorials/scenes/overlapping_boxes.json -o "$out/one.png" 2> /dev/null
end=$(date +%s%N)
echo "one figure, whole process:        $(( (end - start) / 1000000 )) ms"

batch=()
while [ ${#batch[@]} -lt 100 ]; do
  for scene in "${scenes[@]}"; do
    [ ${#batch[@]} -lt 100 ] && batch+=("$scene")
  done
done
start=$(date +%s%N)
summary=$("$render" -q --size 800x600 "${batch[@]}" -o "$out/batch" 2>&1 | tail -1)
end=$(date +%s%N)
echo "batch of 100 figures, one process: $(( (end - start) / 1000000 )) ms in all, $(( (end - start) / 100000000 )) ms per figure"
echo "satviz-render's own timing:        ${summary#satviz-render: }"
