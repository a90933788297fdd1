#!/usr/bin/env bash
# Plots satviz-bench's CSV files with gnuplot: run time against vertex count, on the main pool and on near-contact
# pairs, and run time against error (from timing.csv, timing_near.csv and accuracy.csv), and the world's time per step against the body count (from world.csv, written by
# satviz-bench --world). Each figure is drawn when its CSV file is in CSV_DIR.
# Usage: tests/bench/plot.sh CSV_DIR OUT_DIR (writes OUT_DIR/time-vs-vertices.png, OUT_DIR/time-near-contact.png,
# OUT_DIR/time-vs-error.png, OUT_DIR/world-step-time.png).
set -euo pipefail
csv=$1 out=$2
command -v gnuplot > /dev/null || { echo "plot.sh: gnuplot is not installed (apt-get install gnuplot-nox)" >&2; exit 2; }
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
written=()

# A colour of its own for every query of a panel, and a dash pattern per library: solid satviz, dashed Box2D,
# dotted Chipmunk, dash-dot textbook.
palette=(e41a1c 377eb8 4daf4a 984ea3 ff7f00 a65628 f781bf 17becf 999999 000000 bcbd22 1f3a93 8c564b 2ca02c)

# The gnuplot plot list of one panel of a vertex-count plot: one line per query named in the arguments, from the
# timing file TIMING_CSV (query,n,ns).
panel() {
  local file=$1 prefix=$2 plots="" i=0 query
  shift 2
  for query in "$@"; do
    i=$((i + 1))
    awk -F, -v q="$query" '$1 == q { print $2, $3 }' "$file" | sort -n > "$work/$prefix$i.dat"
    [ -s "$work/$prefix$i.dat" ] || continue
    case "$query" in
      box2d*) dash=2 ;;
      chipmunk*) dash=3 ;;
      textbook*) dash=4 ;;
      *) dash=1 ;;
    esac
    colour=${palette[$(((i - 1) % ${#palette[@]}))]}
    plots+="'$work/$prefix$i.dat' using 1:2 with linespoints lw 2 dt $dash pt 7 ps 0.8 lc rgb '#$colour' title '$query', "
  done
  echo "${plots%, }"
}
if [ -f "$csv/timing.csv" ]; then
static=$(panel "$csv/timing.csv" s "satviz Overlap" "satviz Collide" "satviz Overlap float" "satviz Collide float" \
  "textbook Overlap" "textbook MTV" "box2d b2TestOverlap" "box2d b2CollidePolygons" "chipmunk cpShapesCollide")
moving=$(panel "$csv/timing.csv" m "satviz Sweep" "satviz SweepTime" "satviz Sweep float" "satviz RayCast" \
  "satviz RayCast float" "textbook TOI" "box2d b2TimeOfImpact" "box2d b2TimeOfImpact + b2CollidePolygons at t" \
  "box2d b2PolygonShape::RayCast")
gnuplot << GNUPLOT
set terminal pngcairo size 1400,640 font "DejaVu Sans,11"
set output "$out/time-vs-vertices.png"
set multiplot layout 1,2 title "Run time against vertex count (both polygons have n vertices; Box2D stops at 8)"
set logscale xy
set xlabel "vertices per polygon"
set ylabel "ns per query"
set key top left font ",9"
set grid
set title "Overlap and contact queries"
plot $static
set title "Sweeps and segment casts"
plot $moving
unset multiplot
GNUPLOT
written+=("$out/time-vs-vertices.png")
fi

# The near-contact pairs (timing_near.csv): 3 to 8 vertices, beside Box2D and the textbook loop.
if [ -f "$csv/timing_near.csv" ]; then
nearStatic=$(panel "$csv/timing_near.csv" ns "satviz Overlap" "satviz Collide" "textbook Overlap" "textbook MTV" \
  "box2d b2TestOverlap" "box2d b2CollidePolygons")
nearMoving=$(panel "$csv/timing_near.csv" nm "satviz Sweep" "satviz SweepTime" "textbook TOI" "box2d b2TimeOfImpact" \
  "box2d b2TimeOfImpact + b2CollidePolygons at t")
gnuplot << GNUPLOT
set terminal pngcairo size 1400,640 font "DejaVu Sans,11"
set output "$out/time-near-contact.png"
set multiplot layout 1,2 title "Near-contact pairs from pools no pass replays: run time against vertex count"
set logscale y
set xrange [2.5:8.5]
set xtics 1
set xlabel "vertices per polygon"
set ylabel "ns per query"
set key bottom left font ",9"
set grid
set title "Overlap and contact queries"
plot $nearStatic
set key bottom right
set title "Sweeps (a third of the pairs start overlapped)"
plot $nearMoving
unset multiplot
GNUPLOT
written+=("$out/time-near-contact.png")
fi

# Run time at n = 8 against the worst error and against the wrong answers: one point per query or variant, in the
# legend. The columns are found by their names in the header.
if [ -f "$csv/accuracy.csv" ]; then
errors=""
wrongs=""
j=0
while IFS="|" read -r query wrong worst ns8; do
  j=$((j + 1))
  colour=${palette[$(((j - 1) % ${#palette[@]}))]}
  point=$((4 + j % 10))
  echo "$ns8 $([ "$wrong" = 0 ] && echo 0.5 || echo "$wrong")" > "$work/w$j.dat"
  wrongs+="'$work/w$j.dat' using 1:2 with points pt $point lc rgb '#$colour' ps 2 lw 2 title '$query', "
  if [ -n "$worst" ]; then
    echo "$ns8 $worst" > "$work/e$j.dat"
    errors+="'$work/e$j.dat' using 1:2 with points pt $point lc rgb '#$colour' ps 2 lw 2 title '$query', "
  fi
done < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  $col["ns_n8"] > 0 && $1 !~ /traced/ {
    gsub(/;/, ",", $1); printf "%s|%s|%s|%s\n", $1, $col["wrong"], $col["error_max"], $col["ns_n8"] }' \
  "$csv/accuracy.csv")
gnuplot << GNUPLOT
set terminal pngcairo size 1400,820 font "DejaVu Sans,11"
set output "$out/time-vs-error.png"
set multiplot layout 1,2 title "Run time (8-gons) against error, against a quadruple-precision reference"
set logscale xy
set grid
set key outside center bottom horizontal maxcols 3 font ",9"
set xrange [10:1000]
set xlabel "ns per query, n = 8"
set ylabel "worst |depth error|, |t error| or ray-cast distance error"
set format y "10^{%L}"
plot ${errors%, }
set ylabel "wrong yes/no answers, touching pairs included (none drawn at 0.5)"
set format y "%g"
set yrange [0.3:*]
plot ${wrongs%, }
unset multiplot
GNUPLOT
written+=("$out/time-vs-error.png")
fi

# The world: ms per step against the number of bodies, a panel per scene, a line per configuration (satviz solid,
# Box2D dashed, satviz with one saving off dotted). The columns are found by their names in the header.
if [ -f "$csv/world.csv" ]; then
  world_panel() {
    local scene=$1 plots="" i=0 configuration
    while IFS= read -r configuration; do
      i=$((i + 1))
      awk -F, -v s="$scene" -v c="$configuration" 'NR == 1 { for (k = 1; k <= NF; ++k) col[$k] = k; next }
        $col["scene"] == s && $col["configuration"] == c { print $col["bodies"], $col["ms_step"] }' \
        "$csv/world.csv" | sort -n > "$work/$scene$i.dat"
      [ -s "$work/$scene$i.dat" ] || continue
      case "$configuration" in
        box2d*) dash=2 width=2 ;;
        satviz) dash=1 width=3 ;;
        *) dash=3 width=1.5 ;;
      esac
      colour=${palette[$(((i - 1) % ${#palette[@]}))]}
      plots+="'$work/$scene$i.dat' using 1:2 with linespoints lw $width dt $dash pt 7 ps 0.8 lc rgb '#$colour' "
      plots+="title '${configuration//;/,}', "
    done < <(awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) col[$k] = k; next }
      !seen[$col["configuration"]]++ { print $col["configuration"] }' "$csv/world.csv")
    echo "${plots%, }"
  }
  pile=$(world_panel pile)
  rain=$(world_panel rain)
  gnuplot << GNUPLOT
set terminal pngcairo size 1400,640 font "DejaVu Sans,11"
set output "$out/world-step-time.png"
set multiplot layout 1,2 title "Rigid-body world: ms per step against the number of bodies (median of the rounds, mixed shapes)"
set logscale xy
set xlabel "dynamic bodies"
set ylabel "ms per step"
set key top left font ",9"
set grid
set title "Pile: a grid falls and settles"
plot $pile
set title "Rain: rows land one after another"
plot $rain
unset multiplot
GNUPLOT
  written+=("$out/world-step-time.png")
fi
[ ${#written[@]} -gt 0 ] || { echo "plot.sh: no timing.csv, accuracy.csv or world.csv in $csv" >&2; exit 2; }
echo "plot.sh: wrote ${written[*]}"
