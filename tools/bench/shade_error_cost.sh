#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Error against run time of the face shader's configurations
# (tools/bench/shade_error_cost.c): the max and mean error against the
# double reference over the non-extreme accuracy cases (computed on the host
# with the 32-bit target arithmetic, the Cortex-M0+'s values), Cortex-M0+
# instructions per face (QEMU mps2-an385, -icount shift=0) and host
# instructions per face (valgrind --tool=callgrind, gcc -O2, 64-bit host
# arithmetic).  Writes OUT_DIR/shade_error_cost.md (a table naming the
# dominated configurations) and OUT_DIR/shade_error_cost.png (error against
# M0+ instructions, the Pareto front drawn).
# usage: tools/bench/shade_error_cost.sh [OUT_DIR]   (default: docs)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mkdir -p "${1:-$here/docs}" && cd "${1:-$here/docs}" && pwd)
for tool in cc qemu-system-arm arm-none-eabi-gcc valgrind callgrind_annotate gnuplot; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found" >&2; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
src=(tools/bench/shade_error_cost.c tests/shade_accuracy/cases.c tests/shade_accuracy/case_reference.c tests/reference/shade_ref.c src/shade.c
     src/shade_fast.c src/fix.c src/recip.c src/div64.c)
inc=(-I include -I src -I tests -I tests/shade_accuracy)
cd "$here"
cc -O2 -std=c99 -ffp-contract=off -DSHADE_COST_HOST -DSTP_WIDE_ARITH=0 "${inc[@]}" "${src[@]}" -lm -o "$work/err32"
cc -O2 -std=c99 -ffp-contract=off -DSHADE_COST_HOST "${inc[@]}" "${src[@]}" -lm -o "$work/host"
"$work/err32" >"$work/errors.txt"
cmake -S tools/bench/shade_cost_m0 -B "$work/m0" -DCMAKE_TOOLCHAIN_FILE="$here/cmake/toolchain-arm-none-eabi.cmake" \
    -DSTP_CPU=cortex-m0plus >"$work/m0.log" 2>&1 && cmake --build "$work/m0" >>"$work/m0.log" 2>&1 ||
    { cat "$work/m0.log" >&2; exit 1; }
timeout -k 5 600 qemu-system-arm -M mps2-an385 -kernel "$work/m0/shade_cost_m0.elf" -display none -serial null \
    -monitor none -semihosting-config enable=on,target=native -icount shift=0 >"$work/m0.txt" 2>&1 ||
    { cat "$work/m0.txt" >&2; exit 1; }
k=0
: >"$work/rows.txt"
while read -r name count max mean all; do
    m0=$(sed -n "s/^stipple: cost $name \([0-9]*\).*/\1/p" "$work/m0.txt")
    valgrind --tool=callgrind --toggle-collect=stp_shade_fast_face --callgrind-out-file="$work/cg" \
        "$work/host" --config "$k" >/dev/null 2>&1
    ir=$(callgrind_annotate "$work/cg" 2>/dev/null | sed -n 's/^ *\([0-9,]*\) .*PROGRAM TOTALS.*/\1/p' | tr -d ,)
    echo "$name $count $max $mean $m0 $((ir / count)) $all" >>"$work/rows.txt"
    k=$((k + 1))
done <"$work/errors.txt"
# dominated: another configuration costs no more M0+ instructions and errs no more (max), one strictly
awk '{ name[NR] = $1; max[NR] = $3; m0[NR] = $5; line[NR] = $0 }
     END { for (i = 1; i <= NR; i++) {
               by = ""
               for (j = 1; j <= NR; j++)
                   if (j != i && m0[j] <= m0[i] && max[j] <= max[i] && (m0[j] < m0[i] || max[j] < max[i]))
                       by = by (by == "" ? "" : ",") name[j]
               print line[i], (by == "" ? "front" : "dominated-by:" by) } }' "$work/rows.txt" >"$work/table.txt"
{
    echo "| configuration | cases | max error | mean error | M0+ instructions/face | host instructions/face | Pareto | max error, extremes too |"
    echo "|---|---|---|---|---|---|---|---|"
    awk '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, ($8 == "front" ? "on the front" : "dominated by " substr($8, 14)), $7 }' \
        "$work/table.txt"
} >"$out/shade_error_cost.md"
sort -k5,5n "$work/table.txt" | awk '$8 == "front"' >"$work/front.txt"
gnuplot <<GP
set terminal pngcairo size 800,500
set output "$out/shade_error_cost.png"
set logscale y
set xlabel "Cortex-M0+ instructions per face (QEMU -icount)"
set ylabel "max error against the double reference"
set title "Face shader: error against run time (non-extreme cases)"
set key top right
plot "$work/front.txt" using 5:3 with lines lw 2 title "Pareto front", \
     "$work/table.txt" using 5:3 with points pt 7 ps 1.5 title "configurations", \
     "$work/table.txt" using 5:3:1 with labels offset 0,1 notitle
GP
cat "$out/shade_error_cost.md"
