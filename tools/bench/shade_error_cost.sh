#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Error against run time of the shading configurations
# (tools/bench/shade_error_cost.c): for each configuration, the max and mean
# error against the double reference (tests/shade_accuracy/case_reference.c)
# over the accuracy cases (computed on the host with the 32-bit target
# arithmetic, the Cortex-M0+'s values; typical = the non-extreme cases,
# stiff = the extreme ones), Cortex-M0+ instructions per shade (QEMU
# mps2-an385, -icount shift=0), host instructions per shade (callgrind,
# gcc -O2, the host's 64-bit arithmetic) and AVR cycles per shade
# (ATmega2560 under simavr).  Writes OUT_DIR/error-cost.md (the
# table, naming the dominated configurations) and OUT_DIR/error-cost.svg
# (max error against M0+ instructions, the Pareto front drawn), and prints
# the table.
#
# usage: tools/bench/shade_error_cost.sh [--fast] [--cases N] [--cost-cases N] [OUT_DIR]
#   OUT_DIR        default docs (the committed table and plot)
#   --cases N      accuracy cases for the errors (default 30000: all of them)
#   --cost-cases N accuracy cases for the costs (default 3000: 903 typical)
#   --fast         errors only (host compiler alone: no QEMU, no callgrind,
#                  no simavr, no plot); writes OUT_DIR/error-cost.md (tests/error_cost)
# Exit status 77: a tool is missing.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
fast=0 cases=30000 cost_cases=3000 out=
while [ $# -gt 0 ]; do
    case $1 in
    --fast) fast=1 ;;
    --cases) cases=$2; shift ;;
    --cost-cases) cost_cases=$2; shift ;;
    -*) echo "usage: $0 [--fast] [--cases N] [--cost-cases N] [OUT_DIR]" >&2; exit 2 ;;
    *) out=$1 ;;
    esac
    shift
done
out=$(mkdir -p "${out:-$here/docs}" && cd "${out:-$here/docs}" && pwd)
cc=${CC:-cc}
tools=("$cc")
[ "$fast" = 1 ] || tools+=(qemu-system-arm arm-none-eabi-gcc valgrind callgrind_annotate gnuplot cmake avr-gcc simavr)
for tool in "${tools[@]}"; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found" >&2; exit 77; }
done
work=$(mktemp -d)
[ -n "${SHADE_COST_KEEP:-}" ] && echo "$0: work files kept in $work" >&2 || trap 'rm -rf "$work"' EXIT
cd "$here"

# The compile-time variants: name, core switches, run-time modes measured.
variants=(
    "F12|STP_FIX_FRAC_BITS=12|default exact point"
    "F16|STP_FIX_FRAC_BITS=16|default fast exact point levels16 levels256 fresnel-table fresnel-formula q14normal n15normal"
    "F20|STP_FIX_FRAC_BITS=20|default exact point"
    "F16-sqrtfast|STP_SQRT_FAST=1|default exact"
    "F16-lambert|STP_WITH_SPECULAR=0|default point"
)
# row label of variant $1 in mode $2
label() {
    case $2 in
    default) echo "$1" ;;
    levels16) echo "$1-16levels" ;;
    levels256) echo "$1-256levels" ;;
    *) echo "$1-$2" ;;
    esac
}
src=(tools/bench/shade_error_cost.c tests/shade_accuracy/cases.c tests/shade_accuracy/case_reference.c
     tests/reference/shade_ref.c src/shade.c src/shade_fast.c src/fix.c src/recip.c src/div64.c)
inc=(-I include -I src -I tests -I tests/shade_accuracy)
flags=(-O2 -std=c99 -Wall -Wextra -Werror -ffp-contract=off -DSHADE_COST_HOST)

: >"$work/rows.txt"
v=0
for spec in "${variants[@]}"; do
    IFS='|' read -r name defs modes <<<"$spec"
    v=$((v + 1))
    "$cc" "${flags[@]}" -DSTP_WIDE_ARITH=0 "-D$defs" "${inc[@]}" "${src[@]}" -lm -o "$work/err$v"
    "$work/err$v" --cases "$cases" >"$work/err$v.txt"
    if [ "$fast" = 0 ]; then
        "$cc" "${flags[@]}" "-D$defs" "${inc[@]}" "${src[@]}" -lm -o "$work/host$v"
        d=$work/m0-$v
        { cmake -S tools/bench/shade_cost_m0 -B "$d" -DCMAKE_TOOLCHAIN_FILE="$here/cmake/toolchain-arm-none-eabi.cmake" \
            -DSTP_CPU=cortex-m0plus -DSTP_DEFS="$defs" -DSHADE_COST_CASES="$cost_cases" &&
            cmake --build "$d"; } >"$d.log" 2>&1 || { cat "$d.log" >&2; exit 1; }
        timeout -k 5 900 qemu-system-arm -M mps2-an385 -kernel "$d/shade_cost_m0.elf" -display none -serial null \
            -monitor none -semihosting-config enable=on,target=native -icount shift=0 >"$d.txt" 2>&1 ||
            { cat "$d.txt" >&2; exit 1; }
        # AVR (ATmega2560, simavr): the first 140 typical cases from this variant's host build
        # (avr-gcc's double is 32 bits), the shades checked against the host's 32-bit arithmetic
        "$work/err$v" --emit-avr 140 >"$work/avr$v.h"
        avr-gcc -mmcu=atmega2560 -O2 -std=c99 -Wall -Wextra -Werror -ffp-contract=off -DSTP_WIDE_ARITH=0 "-D$defs" \
            -DSHADE_COST_AVR_CASES="\"$work/avr$v.h\"" -I include -I src -I tests/shade_accuracy \
            tools/bench/shade_error_cost.c src/shade_fast.c src/shade.c src/fix.c src/recip.c src/div64.c \
            -o "$work/avr$v.elf"
        timeout -k 5 900 simavr -m atmega2560 -f 16000000 "$work/avr$v.elf" 2>&1 |
            sed 's/\x1b\[[0-9;]*m//g; s/\.$//' | grep '^stipple: ' >"$work/avr$v.txt" || true
        "$work/err$v" --avr-digest 140 >"$work/avr$v.want"
        grep '^stipple: digest' "$work/avr$v.txt" | cmp -s - "$work/avr$v.want" ||
            { echo "$0: $name: the AVR's shades differ from the host's 32-bit arithmetic" >&2; cat "$work/avr$v.txt" >&2; exit 1; }
    fi
    for mode in $modes; do
        read -r _ n max mean sn smax smean d16 d256 < <(grep "^$mode " "$work/err$v.txt")
        m0=- ir=- avr=-
        if [ "$fast" = 0 ]; then
            avr=$(sed -n "s/^stipple: cost $mode \([0-9]*\) .*/\1/p" "$work/avr$v.txt")
            avr=${avr:--}
            read -r m0 cn < <(sed -n "s/^stipple: cost $mode \([0-9]*\) \([0-9]*\).*/\1 \2/p" "$d.txt")
            valgrind --tool=callgrind --toggle-collect=shade_one --callgrind-out-file="$work/cg" \
                "$work/host$v" --cases "$cost_cases" --only "$mode" >/dev/null 2>&1
            ir=$(callgrind_annotate "$work/cg" 2>/dev/null | sed -n 's/^ *\([0-9,]*\) .*PROGRAM TOTALS.*/\1/p' | tr -d ,)
            ir=$(((ir + cn / 2) / cn))
        fi
        case $mode in levels*) d16=- d256=- ;; esac
        echo "$(label "$name" "$mode") $defs $m0 $ir $n $max $mean $sn $smax $smean $d16 $d256 $avr" >>"$work/rows.txt"
    done
done

# rows.txt: label switches m0 host n max mean stiff_n stiff_max stiff_mean d16 d256 avr; add the
# worst error over all cases (field 14), then the Pareto verdict (field 15) on M0+ instructions against
# that worst error: a configuration is dominated when another costs at most 1 % more and errs at
# most 10 % more, and is clearly better in one of the two (over 1 % cheaper or over 10 % more
# exact); within both margins they are "equal" (the M0+ counts of one code differ by a few
# instructions with the code's placement, and the error by the cases each precision can hold).
# The Fresnel pair shades other cases (1 <= n < 2): compared with each other only.
awk -v fast="$fast" '{ w = ($6 + 0 > $9 + 0) ? $6 : $9; row[NR] = $0 " " w; name[NR] = $1; m0[NR] = $3; e[NR] = w
                       sub_[NR] = ($1 ~ /fresnel/) }
    END { for (i = 1; i <= NR; i++) {
              by = ""; same = ""
              if (sub_[i]) { print row[i], "subset"; continue }
              for (j = 1; j <= NR && !fast; j++) {
                  if (j == i || sub_[j] || m0[j] > 1.01 * m0[i] || e[j] > 1.1 * e[i]) continue
                  if (m0[j] < m0[i] / 1.01 || e[j] < e[i] / 1.1) by = by (by == "" ? "" : ",") name[j]
                  else same = same (same == "" ? "" : ",") name[j]
              }
              print row[i], (fast ? "-" : by != "" ? "dominated:" by : same != "" ? "front=" same : "front") } }' \
    "$work/rows.txt" >"$work/table.txt"

{
    echo "# Shading: error against run time"
    echo
    echo "Errors against the double reference over $cases accuracy cases (the Cortex-M0+'s 32-bit arithmetic, run"
    echo "on the host): typical = the non-extreme cases, stiff = the extreme ones; instructions per shade over the"
    echo "typical cases among the first $cost_cases (Cortex-M0+, host), CPU cycles per shade over the first 140 typical"
    echo "cases (AVR: ATmega2560 under simavr, avr-gcc -O2, its shades checked equal to the host's 32-bit"
    echo "arithmetic).  Generated by \`tools/bench/shade_error_cost.sh$([ "$fast" = 1 ] && echo " --fast")\`."
    echo
    echo "| configuration | switches | M0+ instr/shade | host instr/shade | AVR cycles/shade | typical max | typical mean | stiff max | stiff mean | worst | level ≠ reference at 16 / 256 levels (% typical) | Pareto (M0+ against worst) |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
    awk '{ p = $15
           if (p == "front") p = "**front**"
           else if (p ~ /^front=/) p = "**front** (equal: " substr(p, 7) ")"
           else if (p ~ /^dominated:/) p = "dominated by " substr(p, 11)
           else if (p == "subset") p = "other cases (the pair)"
           gsub(/,/, ", ", p)
           printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s / %s | %s |\n",
                  $1, $2, $3, $4, $13, $6, $7, $9, $10, $14, $11, $12, p }' "$work/table.txt"
    echo
    echo "Cases: $(awk 'NR == 1 { print $5 " typical, " $8 " stiff" }' "$work/table.txt"); the Fresnel pair:"
    echo "$(awk '$1 ~ /fresnel-table/ { print $5 " typical, " $8 " stiff" }' "$work/table.txt") (1 <= n < 2, highlight on)."
    cat <<'LEGEND'

Rows (tools/bench/shade_error_cost.c):
- **F12, F16, F20**: the face shader of the mesh path (`stp_shade_fast_face`) as shipped, the core
  built with `STP_FIX_FRAC_BITS` 12, 16 (default), 20: the fast route where it keeps the 2e-3
  bound, the exact route elsewhere.
- **-fast**: the fast route on every face (16-bit scaled directions, table-seeded approximate
  reciprocal square roots and reciprocals, the 49-node Fresnel table, Q30 D, Q16 F).
  **-exact**: the exact route on every face (exact roots and quotients, Fresnel by its formula,
  32-bit mantissas).  **-point**: `stp_shade_point`, the per-point shader (smooth and colour shading, the ray tracer).
- **-sqrtfast**: `STP_SQRT_FAST=1`.  **-lambert**: `STP_WITH_SPECULAR=0` (ambient and
  diffuse only), judged against the full equation: its error is the highlight it leaves out.
- **-16levels, -256levels**: the F16 shade through INTENSITY (`stp_intensity_index`): the error
  of the displayed intensity (index - 1)/(levels - 1).
- **-fresnel-table, -fresnel-formula**: F16 on the cases with 1 <= n < 2 and a highlight, Fresnel's
  F from the prepared table or from its formula at each face (the formula in the fast route's
  32-bit formats needs n^2 < 4; the face shader has no switch for it, the bench clears the
  table's flag).  The host's 64-bit route has neither the fast-everywhere nor the formula
  variant: on the host -fast and -fresnel-formula run the 32-bit route (their host column).
- **-q14normal**: F16 judged against the reference for a 15-bit normal of which the shader's
  Q1.14 normal is the rounding (each component off by 0 or half a step); **-n15normal**:
  `stp_shade_point` given that 15-bit normal (an `stp_fix` normal, as the polygon path has).
  The face shader takes Q1.14 normals only: there is no switch.

Columns: typical = the non-extreme cases, stiff = the extreme ones (grazing, near mirror, tiny
gloss, BRIGHT up to 10 000, small C, near lights), worst = the larger; "level ≠ reference": the
INTENSITY index differs from the reference shade's.  Pareto: on M0+ instructions against the
worst error; costs within 1 % and errors within 10 % count as equal.  Each precision takes the
cases as its `stp_fix` holds them (the reference judges those inputs): F12 rounds a gloss k or
a C below 2^-12 up to 2^-12 and F20 cuts coordinates to +-2048, so F12's stiff cases are
milder: F12-exact's smaller worst error is that, not better arithmetic.
LEGEND
} >"$out/error-cost.md"

if [ "$fast" = 0 ]; then
    # one label per group of equal configurations (the margins above), at its first one's point;
    # a label runs rightwards from its point, level with it beyond 10 000 instructions, else
    # below it (a front label above), then further down while it would overlap one placed
    # before (taken from the top down)
    awk '$15 != "subset" { for (h = 1; h <= n; h++)
               if ($3 <= 1.01 * m0[h] && m0[h] <= 1.01 * $3 && $14 <= 1.1 * e[h] && e[h] <= 1.1 * $14) break
           if (h > n) { n++; m0[n] = $3; e[n] = $14; lab[n] = $1; front[n] = ($15 ~ /^front/) }
           else lab[h] = lab[h] " = " $1 }
         function lg(v) { return log(v) / log(10) }
         END { for (h = 1; h <= n; h++) order[h] = h
               for (h = 2; h <= n; h++) for (k = h; k > 1 && e[order[k]] > e[order[k - 1]]; k--) {
                   t = order[k]; order[k] = order[k - 1]; order[k - 1] = t }
               for (o = 1; o <= n; o++) {
                   h = order[o]
                   ly[h] = m0[h] >= 10000 ? e[h] : front[h] ? e[h] * 1.5 : e[h] / 1.5
                   for (moved = 1; moved;) {
                       moved = 0
                       for (q = 1; q < o; q++) {
                           k = order[q]
                           if ((lg(m0[h] / m0[k]) ^ 2) < 0.25 && (lg(ly[h] / ly[k]) ^ 2) < 0.0169) {
                               ly[h] = ly[k] / 1.4; moved = 1 } } } }
               for (h = 1; h <= n; h++) print m0[h], e[h], "\"" lab[h] "\"", front[h], ly[h] }' \
        "$work/table.txt" >"$work/labels.txt"
    sort -k3,3n "$work/table.txt" | awk '$15 ~ /^front/' >"$work/front.txt"
    awk '$15 ~ /^dominated/' "$work/table.txt" >"$work/dominated.txt"
    gnuplot <<GP
set terminal svg size 960,600 dynamic font "sans,12"
set output "$out/error-cost.svg"
set logscale xy
set format y "10^{%L}"
set xlabel "Cortex-M0+ instructions per shade (QEMU -icount)"
set ylabel "worst error against the double reference, $cases cases"
set title "Shading: error against run time (tools/bench/shade_error_cost.sh)" noenhanced
set key top right
set grid
set xrange [500:300000]
set yrange [3e-5:5]
plot "$work/front.txt" using 3:14 with linespoints lw 2 pt 7 ps 1.2 lc rgb "#1060c0" title "Pareto front", \
     "$work/dominated.txt" using 3:14 with points pt 6 ps 1.2 lc rgb "#c03020" title "dominated", \
     "$work/labels.txt" using 1:(\$4 > 0.5 ? \$5 : 1/0):3 with labels left offset 0.8,0 font "sans,10" notitle, \
     "$work/labels.txt" using 1:(\$4 > 0.5 ? 1/0 : \$5):3 with labels left offset 0.8,0 font "sans,10" tc rgb "#c03020" notitle
GP
fi
cat "$out/error-cost.md"
