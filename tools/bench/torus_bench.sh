#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The host torus benchmark of issue 11: instructions per frame (valgrind
# --tool=callgrind, counting only torus_frame, so set-up and exit are not
# counted) and us per frame (the fastest of interleaved batches, run
# natively) at 128x64, 400x240 and 640x480.
#
# usage: torus_bench.sh [--frames N] [--callgrind-out DIR] [--mesh] [--spin] TORUS_BENCH
#   TORUS_BENCH   the torus_bench executable (build/tools/bench/torus_bench)
#   --frames N    frames counted under callgrind per size (default 20)
#   --callgrind-out DIR  keep each size's callgrind.out there (for
#                 callgrind_annotate) instead of a temporary folder
#   --mesh, --spin  passed to torus_bench: enter through stp_renderer_mesh,
#                 spin the model (a new model transform each frame)
# Build the core as measured in docs/realtime.md (gcc 12, -O2):
#   cmake -S . -B build-o2 -DCMAKE_BUILD_TYPE= -DCMAKE_C_FLAGS=-O2 && \
#   cmake --build build-o2 --target torus_bench
#   tools/bench/torus_bench.sh build-o2/tools/bench/torus_bench
set -euo pipefail

frames=20
keep=""
extra=()
while [ $# -gt 1 ]; do
    case $1 in
    --frames) frames=$2; shift 2 ;;
    --callgrind-out) keep=$2; shift 2 ;;
    --mesh | --spin) extra+=("$1"); shift ;;
    *) echo "torus_bench.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
[ $# -eq 1 ] || { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
exe=$1
[ -x "$exe" ] || { echo "torus_bench.sh: $exe is not an executable" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "torus_bench.sh: valgrind not found" >&2; exit 1; }

if [ -n "$keep" ]; then
    mkdir -p "$keep"
    dir=$keep
else
    dir=$(mktemp -d)
    trap 'rm -rf "$dir"' EXIT
fi

sizes="128x64 400x240 640x480"
declare -A instr us
for s in $sizes; do
    out=$dir/callgrind.out.$s
    valgrind --tool=callgrind --toggle-collect=torus_frame --callgrind-out-file="$out" \
        "$exe" ${extra[@]+"${extra[@]}"} --rounds 0 --frames "$frames" --size "$s" >/dev/null 2>"$dir/valgrind.$s.log" ||
        { echo "torus_bench.sh: callgrind run at $s failed (log: $dir/valgrind.$s.log)" >&2; exit 1; }
    total=$(sed -n 's/^summary: \([0-9]*\).*/\1/p' "$out")
    [ -n "$total" ] || total=$(sed -n 's/^totals: \([0-9]*\).*/\1/p' "$out")
    [ -n "$total" ] || { echo "torus_bench.sh: no total in $out" >&2; exit 1; }
    instr[$s]=$(awk -v t="$total" -v f="$frames" 'BEGIN { printf "%.3f", t / f / 1e6 }')
done
while read -r s t; do
    us[$s]=$t
done < <("$exe" ${extra[@]+"${extra[@]}"})

printf "%-10s %18s %12s\n" "size" "M instr/frame" "us/frame"
for s in $sizes; do
    printf "%-10s %18s %12s\n" "$s" "${instr[$s]}" "${us[$s]}"
done
