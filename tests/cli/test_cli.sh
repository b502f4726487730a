#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# End-to-end checks of the stipple command (run by CTest):
#  1. every shared scene renders at 128x64 and 512x512 to PBM (raw and plain),
#     PGM, PPM and text; every PNM passes netpbm's pamvalidate and has the
#     size asked for; the text has one line per row, one character per pixel;
#  2. malformed scenes (NFF, OBJ, OFF: truncated, wrong counts, bad numbers,
#     indices out of range, empty) exit non-zero with "file:line: ..." on
#     stderr, write no output file and leave an existing one untouched;
#  3. `stipple dither` gives ImageMagick's -ordered-dither pixels on a ramp;
#  4. every shared scene ray-traces at 512x512 to PPM (colour) and PBM, valid
#     and of the size asked for, the PPM with at least 3 colours;
#     bad --depth / --min-weight are refused; a progress bar appears only on
#     a terminal (stderr here is a file: nothing but the stats line).
# Usage: test_cli.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

command -v pamvalidate >/dev/null || { echo "FAIL: pamvalidate (netpbm) is not installed" >&2; exit 1; }

# --- 0. --version prints the version written in include/stipple/version.h
header=$(dirname "$0")/../../include/stipple/version.h
want=$(awk '/^#define STP_VERSION_(MAJOR|MINOR|PATCH) /{v = v (v == "" ? "" : ".") $3} END{print v}' "$header")
got=$("$stipple" --version)
if [ "$got" = "stipple $want" ]; then ok; else bad "--version printed '$got', want 'stipple $want'"; fi

# --- 1. every scene, both sizes, every output kind
for nff in "$scenes"/*.nff; do
    name=$(basename "$nff" .nff)
    for size in 128x64 512x512; do
        w=${size%x*}
        h=${size#*x}
        for ext in pbm pgm ppm txt; do
            out="$work/$name-$size.$ext"
            if ! "$stipple" render "$nff" -s "$size" -o "$out" 2>"$work/err"; then
                bad "$name $size .$ext: exit status $? ($(cat "$work/err"))"
                continue
            fi
            if [ "$ext" = txt ]; then
                lines=$(wc -l <"$out")
                widths=$(awk '{print length($0)}' "$out" | sort -u)
                if [ "$lines" != "$h" ] || [ "$widths" != "$w" ]; then
                    bad "$name $size .txt: $lines lines of widths '$widths'"
                else ok; fi
            else
                if ! pamvalidate <"$out" >/dev/null 2>&1; then
                    bad "$name $size .$ext: pamvalidate rejects it"
                elif [ "$(pamfile "$out" | grep -o "$w by $h")" != "$w by $h" ]; then
                    bad "$name $size .$ext: wrong size: $(pamfile "$out")"
                else ok; fi
            fi
        done
        out="$work/$name-$size-plain.pbm"
        if "$stipple" render "$nff" -s "$size" --format plain-pbm -o "$out" 2>/dev/null &&
            pamvalidate <"$out" >/dev/null 2>&1 && [ "$(head -c 2 "$out")" = P1 ]; then ok
        else bad "$name $size plain PBM"; fi
    done
done

# --- 4. ray tracing every scene at 512x512
for nff in "$scenes"/*.nff; do
    name=$(basename "$nff" .nff)
    for ext in ppm pbm; do
        out="$work/$name-rt.$ext"
        colour=""
        [ "$ext" = ppm ] && colour=--color
        if ! "$stipple" render "$nff" --raytrace $colour -s 512x512 -o "$out" 2>"$work/err"; then
            bad "$name --raytrace .$ext: exit status ($(cat "$work/err"))"
        elif [ -s "$work/err" ]; then
            bad "$name --raytrace .$ext: unexpected stderr: $(head -c 200 "$work/err")"
        elif ! pamvalidate <"$out" >/dev/null 2>&1; then
            bad "$name --raytrace .$ext: pamvalidate rejects it"
        elif [ "$(pamfile "$out" | grep -o "512 by 512")" != "512 by 512" ]; then
            bad "$name --raytrace .$ext: wrong size: $(pamfile "$out")"
        elif [ "$ext" = ppm ] && [ "$(ppmhist -noheader "$out" | wc -l)" -lt 3 ]; then
            bad "$name --raytrace .ppm: fewer than 3 colours"
        else ok; fi
    done
done
for bad_opt in "--depth 99" "--depth -1" "--min-weight 2" "--min-weight x"; do
    # shellcheck disable=SC2086
    if "$stipple" render "$scenes/tetra-s1.nff" --raytrace $bad_opt -o "$work/x.pbm" 2>"$work/err"; then
        bad "--raytrace $bad_opt accepted"
    elif ! grep -q "bad --" "$work/err"; then
        bad "--raytrace $bad_opt: message: $(cat "$work/err")"
    else ok; fi
done

# --- 2. malformed scenes
expect_error() { # FILE EXPECTED_LINE
    local file=$1 line=$2 out="$work/out.pbm"
    printf 'keep me' >"$out"
    if "$stipple" render "$file" -o "$out" 2>"$work/err"; then
        bad "$(basename "$file"): accepted"
        return
    fi
    if ! grep -q "$(basename "$file"):$line:" "$work/err"; then
        bad "$(basename "$file"): message does not name line $line: $(cat "$work/err")"
    elif [ "$(cat "$out")" != "keep me" ]; then
        bad "$(basename "$file"): existing output changed"
    elif ls -a "$work" | grep -q '^\.out\.pbm\.'; then
        bad "$(basename "$file"): temporary file left behind"
    else ok; fi
    rm -f "$out"
    if "$stipple" render "$file" -o "$out" 2>/dev/null || [ -e "$out" ]; then
        bad "$(basename "$file"): output file written"
    else ok; fi
}
printf 'v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\np 3\n0 0 0\n1 0 0\n' >"$work/truncated.nff"
expect_error "$work/truncated.nff" 8
printf 'p 4\n0 0 0\n1 0 0\n1 1 0\nfoo\n' >"$work/wrongcount.nff"
expect_error "$work/wrongcount.nff" 5
printf 'p 3\n0 0 0\n1 0 0\n1 1.2.3 0\n' >"$work/badnumber.nff"
expect_error "$work/badnumber.nff" 4
printf 's 0 0 0 nan\n' >"$work/nan.nff"
expect_error "$work/nan.nff" 1
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n' >"$work/range.obj"
expect_error "$work/range.obj" 4
printf 'v 0 0 0\nv 1 0 0\nf 1 2 -3\n' >"$work/negrange.obj"
expect_error "$work/negrange.obj" 3
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 3\n' >"$work/range.off"
expect_error "$work/range.off" 6
printf 'OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n' >"$work/short.off"
expect_error "$work/short.off" 2
: >"$work/empty.nff"
if "$stipple" render "$work/empty.nff" -o "$work/e.pbm" 2>"$work/err" || [ -e "$work/e.pbm" ] ||
    ! grep -q 'empty.nff' "$work/err"; then bad "empty scene accepted or unnamed"; else ok; fi
if "$stipple" render "$work/missing.nff" -o "$work/m.pbm" 2>/dev/null; then bad "missing scene accepted"; else ok; fi
if "$stipple" render "$scenes/tetra-s1.nff" -o "$work/x.jpeg" 2>/dev/null; then bad "unknown extension accepted"; else ok; fi
if "$stipple" render "$scenes/tetra-s1.nff" -o "$work/x.pbm" --levels 1 2>/dev/null; then bad "--levels 1 accepted"; else ok; fi

# --- indexed frame buffer through a colour table: the grey table gives the
# grey picture itself (at the palette's 16 levels); pseudocolour maps each grey to one colour and back
"$stipple" render "$scenes/teapot-s1.nff" -s 64x32 -l 16 -o "$work/plain.ppm" &&
    "$stipple" render "$scenes/teapot-s1.nff" -s 64x32 --palette grey -o "$work/grey.ppm" &&
    "$stipple" render "$scenes/teapot-s1.nff" -s 64x32 --palette pseudo -o "$work/pseudo.ppm" ||
    bad "--palette renders"
if cmp -s "$work/plain.ppm" "$work/grey.ppm"; then ok; else bad "--palette grey differs from the grey picture"; fi
pairs=$(paste -d' ' <(pnmtoplainpnm "$work/grey.ppm" | tail -n +4 | tr -s ' \n' '\n' | grep . | paste -d, - - -) \
                    <(pnmtoplainpnm "$work/pseudo.ppm" | tail -n +4 | tr -s ' \n' '\n' | grep . | paste -d, - - -) | sort -u)
greys=$(echo "$pairs" | cut -d' ' -f1 | sort -u | wc -l)
colours=$(echo "$pairs" | cut -d' ' -f2 | sort -u | wc -l)
if [ "$(echo "$pairs" | wc -l)" = "$greys" ] && [ "$greys" = "$colours" ] && [ "$greys" -gt 2 ]; then ok
else bad "--palette pseudo is not one colour per grey ($greys greys, $colours colours)"; fi
if "$stipple" render "$scenes/teapot-s1.nff" --palette pseudo -o "$work/x.pbm" 2>/dev/null; then
    bad "--palette accepted for PBM"; else ok; fi

# --- 3. dither against ImageMagick on a 256x16 ramp with a vertical gradient
{
    printf 'P2\n256 16\n255\n'
    for y in $(seq 0 15); do
        for x in $(seq 0 255); do printf '%d ' $(((x + y * 7) % 256)); done
        printf '\n'
    done
} >"$work/ramp.pgm"
if [ -x /usr/bin/convert ]; then
    for n in 2 4 8; do
        "$stipple" dither "$work/ramp.pgm" -d "bayer$n" -o "$work/s$n.pbm" &&
            /usr/bin/convert "$work/ramp.pgm" -ordered-dither "o${n}x$n" "$work/i$n.pbm" || { bad "dither $n ran"; continue; }
        if cmp -s <(pnmtoplainpnm "$work/s$n.pbm" | tail -n +3 | tr -d ' \n') \
                  <(pnmtoplainpnm "$work/i$n.pbm" | tail -n +3 | tr -d ' \n'); then ok
        else bad "dither bayer$n differs from ImageMagick o${n}x$n"; fi
    done
else
    bad "/usr/bin/convert (ImageMagick) is not installed"
fi

# --- 4. error diffusion: a still PBM defaults to Floyd-Steinberg at 256
# levels with blue-noise thresholds on mid-greys (fs:blue; teapot-s1's floor
# is mid-grey, so plain fs:raster differs); `stipple dither -d KERNEL` keeps
# the ramp's mean (FS loses no error but the shares past the edges: ON
# pixels = sum of grey / 255 within 32)
"$stipple" render "$scenes/teapot-s1.nff" -o "$work/still.pbm" &&
    "$stipple" render "$scenes/teapot-s1.nff" -d fs:blue -l 256 -o "$work/fs.pbm" &&
    "$stipple" render "$scenes/teapot-s1.nff" -d fs:raster -l 256 -o "$work/fsr.pbm" &&
    "$stipple" render "$scenes/teapot-s1.nff" -d bayer4 -l 16 -o "$work/bayer.pbm" || bad "diffusion renders ran"
if cmp -s "$work/still.pbm" "$work/fs.pbm" && ! cmp -s "$work/still.pbm" "$work/bayer.pbm" &&
    ! cmp -s "$work/still.pbm" "$work/fsr.pbm"; then ok
else bad "the default still PBM is not -d fs:blue -l 256"; fi
"$stipple" render "$scenes/tetra-s1.nff" -o "$work/still.pgm" -l 256 &&
    "$stipple" render "$scenes/tetra-s1.nff" -o "$work/still2.pgm" && cmp -s "$work/still.pgm" "$work/still2.pgm" &&
    ok || bad "grey pictures changed defaults"
expected_on=$(pnmtoplainpnm "$work/ramp.pgm" | tail -n +4 | tr -s ' \n' '\n' | grep . |
    awk '{s += $1} END {printf "%d", s / 255 + 0.5}')
for kernel in fs fs:raster fs:blue sierra-lite jjn stucki burkes; do
    if "$stipple" dither "$work/ramp.pgm" -d "$kernel" -o "$work/d.pbm"; then
        on=$(pnmtoplainpnm "$work/d.pbm" | tail -n +3 | tr -d ' \n' | tr -d 1 | wc -c)
        if [ $((on - expected_on)) -le 32 ] && [ $((expected_on - on)) -le 32 ]; then ok
        else bad "dither -d $kernel: $on lit pixels, the ramp holds $expected_on"; fi
    else bad "dither -d $kernel ran"; fi
done
# --linear: sRGB 128 is 21.6 % linear light, so about 884 of 4096 pixels lit
{ printf 'P2\n64 64\n255\n'; for i in $(seq 1 4096); do printf '128 '; done; } >"$work/grey128.pgm"
for mode in "" --linear; do
    want=2048
    [ -n "$mode" ] && want=884
    if "$stipple" dither "$work/grey128.pgm" -d fs $mode -o "$work/d.pbm"; then
        on=$(pnmtoplainpnm "$work/d.pbm" | tail -n +3 | tr -d ' \n' | tr -d 1 | wc -c)
        if [ $((on - want)) -le 32 ] && [ $((want - on)) -le 32 ]; then ok
        else bad "dither $mode: $on lit pixels, want about $want"; fi
    else bad "dither $mode ran"; fi
done
if "$stipple" dither "$work/grey128.pgm" --linear -g 2 -o "$work/d.pbm" 2>/dev/null; then
    bad "dither --linear with --gamma accepted"; else ok; fi
if "$stipple" dither "$work/ramp.pgm" -d fs:serpentine -o "$work/d.pbm" 2>/dev/null; then
    bad "dither -d fs:serpentine accepted"; else ok; fi

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
