#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The error-against-run-time plot of a bench.csv (run_bench.sh writes both):
# one colour per numeric configuration, named in the legend (no labels at
# the points, which overlap where configurations cost the same), the point
# shape telling the measure apart.
# Usage: tools/bench/plot_bench.sh BENCH.csv OUT.png     (needs gnuplot)
set -eu
csv=$1 png=$2
command -v gnuplot >/dev/null || { echo "plot_bench.sh: gnuplot not found (Debian: gnuplot-nox)" >&2; exit 1; }
configs=$(awk -F, 'NR > 1 && $1 != "" { printf "%s ", $1 }' "$csv")
[ -n "$configs" ] || { echo "plot_bench.sh: $csv has no configurations" >&2; exit 1; }
term=png
gnuplot -e "set terminal" 2>&1 | grep -q pngcairo && term=pngcairo
gnuplot <<PLOT
set terminal $term size 1200,560 font ",10"
set output "$png"
set datafile separator ","
set key autotitle columnhead
set logscale xy
set format y "%g"
set grid
set termoption noenhanced
configs = "$configs"
n = words(configs)
# "every ::(i-1)::(i-1)": the i-th data row (the header is not counted), one configuration
set multiplot layout 1,2 title "stipple: error against run time per numeric configuration"
set key bottom right box opaque maxrows 5
set title "shading\n(circle: scene polygons, max; square: their mean; triangle: random geometry, mean)"
set title font ",9"
set xlabel "ns per shade (stp_shade_point)"
set ylabel "absolute shade error vs double reference"
set yrange [1e-9:1]
set xrange [50:5000]
plot for [i=1:n] "$csv" every ::(i-1)::(i-1) using "ns_per_shade":"scene_max" with points pt 7 ps 1.3 lc i title word(configs, i), \
     for [i=1:n] "$csv" every ::(i-1)::(i-1) using "ns_per_shade":"scene_mean" with points pt 5 ps 1.1 lc i notitle, \
     for [i=1:n] "$csv" every ::(i-1)::(i-1) using "ns_per_shade":"rand_mean" with points pt 9 ps 1.1 lc i notitle, \
     1.0/30 with lines dt 2 lc rgb "gray40" title "half an INTENSITY step"
set title "pictures\n(circle: share of differing pixels; square: 3x3-blurred mean abs difference)"
set xlabel "us per torus frame at 400x240 (1000 triangles)"
set ylabel "share of pixels / blurred mean abs difference"
set yrange [1e-8:1]
set xrange [100:20000]
plot for [i=1:n] "$csv" every ::(i-1)::(i-1) using "us_frame_400x240":(column("img_diff_pct")/100) with points pt 7 ps 1.3 lc i title word(configs, i), \
     for [i=1:n] "$csv" every ::(i-1)::(i-1) using "us_frame_400x240":"img_blur_mad" with points pt 5 ps 1.1 lc i notitle
unset multiplot
PLOT
[ -s "$png" ] || { echo "plot_bench.sh: gnuplot wrote no $png" >&2; exit 1; }
