#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# stipple render --outlines end to end: the lines change the picture and
# take the asked shade (white lines add white pixels to a grey picture);
# --crease-angle moves the crease set; misuse is refused (exit 2, nothing
# written).
# Usage: test_outlines_cli.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
white() { ppmhist -noheader "$1" | awk '$1 == 255 {n += $5} END {print n + 0}'; }
scene=$scenes/teapot-s1.nff

"$stipple" render "$scene" -o "$work/plain.pbm" || bad "render"
"$stipple" render "$scene" --outlines both -o "$work/lines.pbm" || bad "render --outlines both"
cmp -s "$work/plain.pbm" "$work/lines.pbm" && bad "--outlines both left the picture as it was"
"$stipple" render "$scene" --exposure off -o "$work/plain.pgm" || bad "render grey"
"$stipple" render "$scene" --exposure off --outlines silhouette --outline-level 1 -o "$work/sil.pgm" ||
    bad "render --outline-level 1"
"$stipple" render "$scene" --exposure off --outlines both --outline-level 1 -o "$work/both.pgm" ||
    bad "render --outlines both --outline-level 1"
"$stipple" render "$scene" --exposure off --outlines crease --crease-angle 180 --outline-level 1 \
    -o "$work/none.pgm" || bad "render --crease-angle 180"
p=$(white "$work/plain.pgm") s=$(white "$work/sil.pgm") b=$(white "$work/both.pgm") n=$(white "$work/none.pgm")
[ "$s" -gt $((p + 50)) ] || bad "silhouettes added $((s - p)) white pixels"
[ "$b" -gt "$s" ] || bad "both ($b white) not more than silhouettes ($s)"
[ "$n" = "$p" ] || bad "no crease at 180 degrees, yet $((n - p)) white pixels more"

# a still 1-bit picture without -d or --outlines draws silhouettes where
# its objects would not stand out (tools/readable.h): balls-s1 at 128x64
# (a mid-grey object on a mid-grey floor, black lines on the lit floor),
# not tetra-s1; --outlines none and a dither named with -d keep no lines
scenes_dir=$(dirname "$scene")
balls="$scenes_dir/balls-s1.nff"
"$stipple" render "$balls" -o "$work/auto.pbm" && "$stipple" render "$balls" --outlines none -o "$work/off.pbm" &&
    "$stipple" render "$balls" --outlines silhouette -o "$work/sil.pbm" &&
    "$stipple" render "$balls" -d fs:blue -o "$work/named.pbm" || bad "balls renders"
cmp -s "$work/auto.pbm" "$work/sil.pbm" || bad "balls-s1: the default is not the picture with silhouettes"
cmp -s "$work/off.pbm" "$work/named.pbm" || bad "balls-s1: -d fs:blue drew lines by itself"
! cmp -s "$work/auto.pbm" "$work/off.pbm" || bad "balls-s1: --outlines none drew lines"
"$stipple" render "$scenes_dir/tetra-s1.nff" -o "$work/t1.pbm" &&
    "$stipple" render "$scenes_dir/tetra-s1.nff" --outlines none -o "$work/t2.pbm" || bad "tetra renders"
cmp -s "$work/t1.pbm" "$work/t2.pbm" || bad "tetra-s1: lines drawn though it reads without them"

expect2() { "$stipple" "$@" >/dev/null 2>&1; [ $? = 2 ] || bad "'$*' not refused"; }
expect2 render "$scene" --outlines all -o "$work/x.pbm"
expect2 render "$scene" --outlines both --crease-angle 200 -o "$work/x.pbm"
expect2 render "$scene" --crease-angle 30 -o "$work/x.pbm"
expect2 render "$scene" --outline-level 0.5 -o "$work/x.pbm"
expect2 render "$scene" --outlines both --outline-level 2 -o "$work/x.pbm"
expect2 render "$scene" --outlines both --raytrace -o "$work/x.pbm"
[ ! -e "$work/x.pbm" ] || bad "a refused command wrote a file"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)" >&2
    exit 1
fi
echo "outlines CLI: all checks passed"
