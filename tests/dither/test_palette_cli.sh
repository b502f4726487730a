#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# stipple dither/render --palette end to end (netpbm reads the outputs):
#  1. --palette bw with an ordered cell is the 1-bit picture, pixel for pixel;
#  2. pictures hold only the palette's colours (bwr, grey4, rgb8, a file);
#  3. --planes writes the SSD1680's two planes: the red plane's ON bits are
#     the picture's red pixels, the bw plane's OFF bits its black ones;
#  4. bad palettes, --planes without bwr and 1-bit outputs are refused.
# Usage: test_palette_cli.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
# colours FILE: "R G B" lines of the colours a PPM/PGM holds, sorted
colours() { pnmtoplainpnm "$1" 2>/dev/null | ppmhist -noheader 2>/dev/null | awk '{print $1, $2, $3}' | sort -u; }
# ones FILE: how many bits are 1
ones() { od -An -v -tu1 "$1" | tr -s ' ' '\n' | awk 'NF{for(i=0;i<8;i++)if(int($1/2^i)%2)n++} END{print n+0}'; }
subset() { # subset "have" "allowed": every line of have is in allowed
    local line
    while read -r line; do
        [ -z "$line" ] && continue
        printf '%s\n' "$2" | grep -qxF "$line" || return 1
    done <<<"$1"
}

"$stipple" render "$scenes/teapot-s1.nff" -o "$work/g.pgm" || bad "render grey"
"$stipple" render "$scenes/balls-s1.nff" --color -o "$work/c.ppm" || bad "render colour"

# 1. bw + bayer4 = the PBM
"$stipple" dither "$work/g.pgm" -d bayer4 -o "$work/a.pbm" || bad "dither pbm"
"$stipple" dither "$work/g.pgm" -d bayer4 --palette bw -o "$work/b.pgm" || bad "dither --palette bw"
pgmtopbm -threshold "$work/b.pgm" | cmp -s - "$work/a.pbm" || bad "--palette bw -d bayer4 differs from the 1-bit picture"
"$stipple" dither "$work/g.pgm" -d bayer4 --linear -o "$work/al.pbm" || bad "dither --linear"
"$stipple" dither "$work/g.pgm" -d bayer4 --linear --palette bw -o "$work/bl.pgm" || bad "dither --linear --palette bw"
pgmtopbm -threshold "$work/bl.pgm" | cmp -s - "$work/al.pbm" || bad "--linear --palette bw differs from --linear"

# 2. only the palette's colours
"$stipple" dither "$work/g.pgm" --palette grey4 -d fs -o "$work/g4.pgm" || bad "grey4"
have=$(colours "$work/g4.pgm")
subset "$have" "$(printf '0 0 0\n85 85 85\n170 170 170\n255 255 255')" || bad "grey4 colours: $have"
[ "$(printf '%s\n' "$have" | wc -l)" -ge 3 ] || bad "grey4 uses fewer than 3 levels: $have"
"$stipple" dither "$work/c.ppm" --palette rgb8 -d blue-noise -o "$work/r8.png" || bad "rgb8"
pngtopnm "$work/r8.png" >"$work/r8.ppm" || bad "rgb8 png"
have=$(colours "$work/r8.ppm")
subset "$have" "$(for r in 0 255; do for g in 0 255; do for b in 0 255; do echo "$r $g $b"; done; done; done)" ||
    bad "rgb8 colours: $have"
[ "$(printf '%s\n' "$have" | wc -l)" -ge 4 ] || bad "rgb8 of balls-s1 uses fewer than 4 colours: $have"
printf '# two inks\n0 0 64 navy\n255 255 200 cream\n' >"$work/inks.txt"
"$stipple" dither "$work/c.ppm" --palette "$work/inks.txt" -o "$work/inks.ppm" || bad "palette file"
have=$(colours "$work/inks.ppm")
[ "$have" = "$(printf '0 0 64\n255 255 200')" ] || bad "palette file colours: $have"

# 3. bwr and its planes (tetra-s1: red faces on blue)
"$stipple" render "$scenes/tetra-s1.nff" --palette bwr --planes "$work/t" -o "$work/t.ppm" || bad "render bwr"
have=$(colours "$work/t.ppm")
subset "$have" "$(printf '0 0 0\n255 255 255\n255 0 0')" || bad "bwr colours: $have"
red=$(ppmhist -noheader "$work/t.ppm" | awk '$1 == 255 && $2 == 0 {print $5}')
black=$(ppmhist -noheader "$work/t.ppm" | awk '$1 == 0 && $2 == 0 && $3 == 0 {print $5}')
[ "${red:-0}" -gt 100 ] || bad "bwr tetra-s1 has ${red:-0} red pixels"
[ "$(stat -c %s "$work/t.red")" = 1024 ] && [ "$(stat -c %s "$work/t.bw")" = 1024 ] ||
    bad "planes of 128x64 are not 1024 bytes each"
[ "$(ones "$work/t.red")" = "${red:-0}" ] || bad "red plane has $(ones "$work/t.red") ON bits, picture $red red pixels"
[ "$((8192 - $(ones "$work/t.bw")))" = "${black:-0}" ] || bad "bw plane's OFF bits are not the $black black pixels"

# 4. refusals (usage errors: exit 2)
expect2() { "$stipple" "$@" >/dev/null 2>"$work/err"; [ $? = 2 ] || bad "'$*' not refused"; }
expect2 dither "$work/g.pgm" --palette grey4 --planes "$work/p" -o "$work/x.png"
expect2 dither "$work/g.pgm" --palette bwr -o "$work/x.pbm"
expect2 dither "$work/c.ppm" --palette rgb8 -o "$work/x.pgm"
expect2 render "$scenes/tetra-s1.nff" --palette nosuch -o "$work/x.png"
printf '0 0 0\n255 255\n' >"$work/broken.txt"
expect2 dither "$work/g.pgm" --palette "$work/broken.txt" -o "$work/x.png"
grep -qF "broken.txt:2:" "$work/err" || bad "palette file error does not name file:line: $(cat "$work/err")"
[ ! -e "$work/x.png" ] && [ ! -e "$work/x.pbm" ] && [ ! -e "$work/p.bw" ] || bad "a refused command wrote a file"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)" >&2
    exit 1
fi
echo "palette CLI: all checks passed"
