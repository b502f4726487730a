#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# What each render method of the quality bench costs: instructions executed
# inside stp_renderer_render (valgrind --tool=callgrind --toggle-collect=stp_renderer_render,
# unaffected by machine load; the scene's entry, the same for every method,
# is left out), per frame, mean over the shared scenes, at 128x64 and
# 400x240, and the ratio to the first method (Bayer 4x4, 16 levels).
# Usage: tools/bench/quality_cost.sh BUILD_DIR [SCENES_DIR]
set -eu
build=${1:?usage: tools/bench/quality_cost.sh BUILD_DIR [SCENES_DIR]}
here=$(cd "$(dirname "$0")/../.." && pwd)
scenes=${2:-$here/../shared/scenes}
bench=$build/tools/bench/bench_quality
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
names="tetra-s1 tetra-s2 mount-s2 teapot-s1 teapot-s2 gears-s1 balls-s1 balls-s2"
count() { # method scene size -> instructions in stp_renderer_render
    valgrind --tool=callgrind --toggle-collect=stp_renderer_render --callgrind-out-file="$work/cg" \
        "$bench" --scenes "$scenes" --once "$1" --scene "$2" --size "$3" >/dev/null 2>&1
    callgrind_annotate "$work/cg" 2>/dev/null | sed -n 's/^ *\([0-9,]*\) .*PROGRAM TOTALS.*/\1/p' | tr -d ,
}
printf '%-22s %14s %7s %14s %7s\n' "instructions/frame" "128x64" "ratio" "400x240" "ratio"
base_small="" base_large=""
"$bench" --list | while IFS= read -r method; do
    line=$(printf '%-22s' "$method")
    for size in 128x64 400x240; do
        total=0
        for scene in $names; do
            total=$((total + $(count "$method" "$scene" "$size")))
        done
        mean=$((total / 8))
        if [ "$size" = 128x64 ]; then base=${base_small:-$mean}; base_small=$base
        else base=${base_large:-$mean}; base_large=$base; fi
        line="$line $(printf '%14d %6.2fx' "$mean" "$(echo "$mean / $base" | bc -l)")"
    done
    echo "$line"
done
