#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs tools/bench/shade_error_cost.sh --fast over the first 3000 accuracy
# cases and checks its table (OUT_DIR/error-cost.md): every configuration's
# row is there and well formed, and the errors behave as the arithmetic
# says they must.
# usage: check_error_cost.sh SOURCE_DIR OUT_DIR     exit 0 pass, 1 fail, 77 skipped
set -eu
src=$1
out=$2
status=0
"$src/tools/bench/shade_error_cost.sh" --fast --cases 3000 "$out" >"$out.log" 2>&1 || status=$?
[ "$status" = 77 ] && { cat "$out.log" >&2; exit 77; }
[ "$status" = 0 ] || { cat "$out.log" >&2; echo "FAIL: the script exited with $status" >&2; exit 1; }
awk -F'|' '
function fail(msg) { print "FAIL: " msg; bad = 1 }
function num(v) { return v ~ /^ *-?[0-9]+(\.[0-9]+)?(e[-+][0-9]+)? *$/ }
# one figure of the table: field f (2 name, 7 typical max, 8 mean, 9 stiff max, 10 stiff mean, 11 worst)
function at(name, f) { if (!(name in row)) { fail("no row " name); return -1 } split(row[name], c, "|"); return c[f] + 0 }
/^\| F[0-9]/ {
    n = split($0, c, "|")
    name = c[2]; gsub(/ /, "", name)
    if (n != 14) fail(name ": " n - 2 " cells, not 12")
    for (f = 7; f <= 11; f++)
        if (!num(c[f]) || c[f] + 0 < 0 || c[f] + 0 > 1.0001) fail(name ": error \"" c[f] "\" is not a number in [0, 1]")
    split(c[12], d, "/")
    if (!(name ~ /levels/) && (!num(d[1]) || !num(d[2]) || d[1] + 0 > 100 || d[2] + 0 > 100))
        fail(name ": level percentages \"" c[12] "\"")
    row[name] = $0
    rows++
}
/^Cases: / { cases = $0 }
END {
    if (rows != 20) fail(rows " configurations, not 20")
    if (cases !~ /^Cases: [0-9]+ typical, [0-9]+ stiff/) fail("no case counts")
    # the exact route: its error on ordinary faces is the final rounding to F bits, half a step
    for (F = 12; F <= 20; F += 4) {
        half = 2 ^ -(F + 1); e = at("F" F "-exact", 7)
        if (e < 0.5 * half || e > 1.05 * half) fail("F" F "-exact: typical max " e " is not about half a step, " half)
        if (at("F" F, 11) > 2e-3) fail("F" F ": worst " at("F" F, 11) " above the 2e-3 bound")
    }
    if (!(at("F12-exact", 7) > at("F16-exact", 7) && at("F16-exact", 7) > at("F20-exact", 7)))
        fail("the exact route error does not fall from F12 to F16 to F20")
    if (!(at("F12-exact", 8) > at("F16-exact", 8) && at("F16-exact", 8) > at("F20-exact", 8)))
        fail("the exact route mean error does not fall from F12 to F16 to F20")
    if (!(at("F16-exact", 9) > at("F20-exact", 9))) fail("the exact route stiff error does not fall from F16 to F20")
    # the same arithmetic gives the same figures
    for (f = 7; f <= 10; f++) {
        for (F = 12; F <= 20; F += 4)
            if (at("F" F "-point", f) != at("F" F "-exact", f)) fail("F" F "-point and F" F "-exact differ (field " f ")")
        if (at("F16-sqrtfast", f) != at("F16", f)) fail("STP_SQRT_FAST changed the face shader (field " f ")")
        if (at("F16-q14normal", f) < at("F16", f) && f == 9) fail("a coarser normal came out more exact")
    }
    # Lambert leaves the highlight out; the fast route alone fails the extremes
    if (at("F16-lambert", 7) < 0.1 || at("F16-lambert", 8) < 100 * at("F16", 8)) fail("Lambert-only is too close to the full equation")
    if (at("F16-fast", 9) < 0.1) fail("the forced fast route keeps the extremes: the default route guards nothing")
    if (at("F16-fast", 7) > 2e-3) fail("the fast route is off by " at("F16-fast", 7) " on ordinary faces")
    # levels: the displayed intensity is INTENSITY truncation, up to one level step
    if (at("F16-16levels", 7) < 1 / 15 - 2e-3 || at("F16-16levels", 7) > 1 / 15 + 2e-3) fail("16 levels: " at("F16-16levels", 7))
    if (at("F16-256levels", 7) < 1 / 255 - 2e-3 || at("F16-256levels", 7) > 1 / 255 + 2e-3) fail("256 levels: " at("F16-256levels", 7))
    if (at("F16-fresnel-formula", 7) > at("F16-fresnel-table", 7)) fail("the Fresnel formula errs more than its table")
    if (at("F16-n15normal", 7) > 2 * 2 ^ -17) fail("the per-point shader with the finer normal: " at("F16-n15normal", 7))
    if (bad) exit 1
    print "error_cost: " rows " configurations well formed; exact route " at("F12-exact", 7) " / " at("F16-exact", 7) \
          " / " at("F20-exact", 7) " at F 12 / 16 / 20"
}' "$out/error-cost.md"
