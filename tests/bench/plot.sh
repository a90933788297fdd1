#!/usr/bin/env bash
# Plots satviz-bench's CSV files with gnuplot: run time against vertex count, and run time against error.
# Usage: tests/bench/plot.sh CSV_DIR OUT_DIR (writes OUT_DIR/time-vs-vertices.png and OUT_DIR/time-vs-error.png).
set -euo pipefail
csv=$1 out=$2
command -v gnuplot > /dev/null || { echo "plot.sh: gnuplot is not installed (apt-get install gnuplot-nox)" >&2; exit 2; }
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One data file per query for the vertex-count plot: n ns.
queries=()
while IFS= read -r query; do queries+=("$query"); done < <(tail -n +2 "$csv/timing.csv" | cut -d, -f1 | sort -u |
  grep -v -E "traced|float|Sweep|TOI|b2TimeOfImpact|;")
# A colour of its own for every query, and a dash pattern per library: solid satviz, dashed Box2D, dotted
# Chipmunk, dash-dot textbook.
palette=(e41a1c 377eb8 4daf4a 984ea3 ff7f00 a65628 f781bf 17becf 999999 000000 bcbd22 1f3a93)
plots=""
i=0
for query in "${queries[@]}"; do
  i=$((i + 1))
  grep -F "$query," "$csv/timing.csv" | awk -F, -v q="$query" '$1 == q { print $2, $3 }' | sort -n > "$work/q$i.dat"
  case "$query" in
    box2d*) dash=2 ;;
    chipmunk*) dash=3 ;;
    textbook*) dash=4 ;;
    *) dash=1 ;;
  esac
  colour=${palette[$(((i - 1) % ${#palette[@]}))]}
  plots+="'$work/q$i.dat' using 1:2 with linespoints lw 2 dt $dash pt 7 lc rgb '#$colour' title '$query', "
done
gnuplot << GNUPLOT
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output "$out/time-vs-vertices.png"
set title "Run time against vertex count (both polygons have n vertices)"
set logscale xy
set xlabel "vertices per polygon"
set ylabel "ns per query"
set key top left
set grid
plot ${plots%, }
GNUPLOT

# Run time at n = 8 against the worst error and against the wrong answers: one point per query, in the legend.
errors=""
wrongs=""
j=0
while IFS=, read -r query pairs wrong fp fn median worst ns8; do
  [ "$query" = query ] && continue
  awk -v n="$ns8" 'BEGIN { exit !(n > 0) }' || continue
  j=$((j + 1))
  echo "$ns8 $([ "$wrong" = 0 ] && echo 0.5 || echo "$wrong")" > "$work/w$j.dat"
  colour=${palette[$(((j - 1) % ${#palette[@]}))]}
  wrongs+="'$work/w$j.dat' using 1:2 with points pt $((4 + j % 8)) lc rgb '#$colour' ps 2 lw 2 title '$query', "
  if [ -n "$worst" ]; then
    echo "$ns8 $worst" > "$work/e$j.dat"
    errors+="'$work/e$j.dat' using 1:2 with points pt $((4 + j % 8)) lc rgb '#$colour' ps 2 lw 2 title '$query', "
  fi
done < "$csv/accuracy.csv"
gnuplot << GNUPLOT
set terminal pngcairo size 1200,640 font "DejaVu Sans,11"
set output "$out/time-vs-error.png"
set multiplot layout 1,2 title "Run time (8-gons) against error, against a quadruple-precision reference"
set logscale xy
set grid
set key outside center bottom horizontal maxcols 3 font ",9"
set xrange [10:1000]
set xlabel "ns per query, n = 8"
set ylabel "worst |depth error| or |t error|"
set format y "10^{%L}"
plot ${errors%, }
set ylabel "wrong yes/no answers (none drawn at 0.5)"
set format y "%g"
set yrange [0.3:*]
plot ${wrongs%, }
unset multiplot
GNUPLOT
echo "plot.sh: wrote $out/time-vs-vertices.png and $out/time-vs-error.png"
