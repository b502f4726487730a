#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The stipple command's panel-side outputs and image preparation (run by CTest):
#  1. XBM equals ImageMagick's XBM of the negated PBM (XBM's 1 is lit here);
#     the C array of rows is the PBM raster complemented; SSD1306 pages are
#     the pixels regrouped (checked with awk from the plain PBM);
#  2. render --invert is netpbm's pnminvert of the picture; text prints a
#     dark background as blanks, --invert the other way;
#  3. dither --rotate/--flip equal ImageMagick's -rotate/-flop before the
#     halftone; --size fit/fill/stretch exact pixels; --invert; JPEG input
#     equals the same picture decoded to PGM by ImageMagick;
#  4. NFF's resolution line: a note on a terminal when --size is not given;
#  5. progress: the bar moves (percentages below 100 %, time left);
#  6. errors list the choices; bad values exit 2.
# Usage: test_cli_outputs.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
scene=$scenes/tetra-s1.nff
hexbytes() { grep -o '0x[0-9a-fA-F][0-9a-fA-F]' "$1" | tr 'A-F' 'a-f'; }

# --- 1. XBM, C rows, SSD1306 pages
"$stipple" render "$scene" -s 21x11 -o "$work/p.pbm"
"$stipple" render "$scene" -s 21x11 -o "$work/p.xbm"
"$stipple" render "$scene" -s 21x11 -o "$work/p.h"
"$stipple" render "$scene" -s 21x11 --format c-pages -o "$work/pages.h"
convert "$work/p.pbm" -negate "xbm:$work/im.xbm"
if [ -s "$work/p.xbm" ] && diff <(hexbytes "$work/p.xbm") <(hexbytes "$work/im.xbm") >/dev/null &&
        grep -q '#define p_width 21' "$work/p.xbm"; then ok
else bad "XBM differs from ImageMagick's XBM of the negated PBM"; fi
# the P4 raster: after the header's three lines; complemented = lit bits
# (the padding bits of each row's last byte are unlit in the array)
i=0
tail -c $((3 * 11)) "$work/p.pbm" | od -An -v -tx1 | tr ' ' '\n' | grep . |
    while read -r b; do
        i=$((i + 1))
        printf '0x%02x\n' $(((0xff ^ 0x$b) & (i % 3 == 0 ? 0xf8 : 0xff)))
    done >"$work/rows.masked"
if diff <(hexbytes "$work/p.h") "$work/rows.masked" >/dev/null && grep -q 'p\[33\]' "$work/p.h"; then ok
else bad "C array of rows differs from the PBM raster complemented"; fi
pnmtoplainpnm "$work/p.pbm" 2>/dev/null | tail -n +3 | tr -d ' \n' | fold -w 21 >"$work/plain"
awk -v w=21 -v h=11 '{ row[NR - 1] = $0 }
    END { for (p = 0; p < (h + 7) / 8 - ((h + 7) % 8) / 8; p++) for (x = 0; x < w; x++) {
            v = 0
            for (k = 0; k < 8; k++) { y = 8 * p + k
                if (y < h && substr(row[y], x + 1, 1) == "0") v += 2 ^ k }
            printf "0x%02x\n", v } }' "$work/plain" >"$work/pages.want"
if diff <(hexbytes "$work/pages.h") "$work/pages.want" >/dev/null && grep -q 'pages\[42\]' "$work/pages.h"; then ok
else bad "SSD1306 pages differ from the pixels regrouped"; fi

# --- 2. render --invert, text
"$stipple" render "$scene" -s 40x20 --invert -o "$work/inv.pbm"
"$stipple" render "$scene" -s 40x20 -o "$work/fwd.pbm"
pnminvert "$work/fwd.pbm" >"$work/inv.want"
cmp -s "$work/inv.pbm" "$work/inv.want" && ok || bad "render --invert is not pnminvert of the picture"
"$stipple" render "$scene" -s 40x20 --background 0 -o "$work/dark.txt"
"$stipple" render "$scene" -s 40x20 --background 0 --invert -o "$work/darkinv.txt"
[ "$(head -n 1 "$work/dark.txt" | cut -c1-5)" = "     " ] && ok || bad "text: a black background is not blank: $(head -n 1 "$work/dark.txt")"
[ "$(head -n 1 "$work/darkinv.txt" | cut -c1-5)" = "@@@@@" ] && ok || bad "text --invert: a black background is not @"
"$stipple" render "$scene" -s 40x20 --background 1 -o "$work/light.txt"
[ "$(head -n 1 "$work/light.txt" | cut -c1-5)" = "     " ] && ok || bad "text: a white background is not blank"

# --- 3. dither: rotate, flip, size, invert, JPEG
convert -size 37x23 gradient:black-white -swirl 90 "$work/g.pgm"
for t in "--rotate 90:-rotate 90" "--rotate 270:-rotate 270" "--rotate 180:-rotate 180" "--flip:-flop"; do
    ours=${t%%:*} theirs=${t#*:}
    # shellcheck disable=SC2086
    "$stipple" dither "$work/g.pgm" $ours -d bayer4 -o "$work/a.pbm"
    # shellcheck disable=SC2086
    convert "$work/g.pgm" $theirs "$work/r.pgm"
    "$stipple" dither "$work/r.pgm" -d bayer4 -o "$work/b.pbm"
    cmp -s "$work/a.pbm" "$work/b.pbm" && ok || bad "dither $ours differs from ImageMagick $theirs"
done
printf 'P2\n4 2\n255\n255 0 0 0\n255 0 0 0\n' >"$work/s.pgm"
size_case() { # MODE WANT (plain PBM rows, 1 = black = unlit)
    "$stipple" dither "$work/s.pgm" --size 2x2 --resize "$1" -d user:1:1:127 --plain -o "$work/s.pbm"
    got=$(tail -n +3 "$work/s.pbm" | tr -d ' \n')
    [ "$got" = "$2" ] && ok || bad "dither --size 2x2 --resize $1: $got, want $2"
}
size_case fit 0111      # 2x1 on top: mean(255, 0) = 128 lit, 0; a black bar below
size_case fill 1111     # the middle columns, 0 and 0
size_case stretch 0101
"$stipple" dither "$work/s.pgm" --invert -d user:1:1:127 --plain -o "$work/i.pbm"
[ "$(tail -n +3 "$work/i.pbm" | tr -d ' \n')" = 10001000 ] && ok || bad "dither --invert"
convert "$work/g.pgm" -quality 80 "$work/g.jpg"
convert "$work/g.jpg" "$work/fromjpg.pgm"
if "$stipple" dither "$work/g.jpg" -o "$work/j.pbm" 2>"$work/err" &&
        "$stipple" dither "$work/fromjpg.pgm" -o "$work/jp.pbm" && cmp -s "$work/j.pbm" "$work/jp.pbm"; then ok
else bad "dither of a JPEG differs from its PGM: $(cat "$work/err")"; fi
"$stipple" dither "$work/g.jpg" --size 16x8 -o "$work/j.xbm" && grep -q "j_height 8" "$work/j.xbm" && ok ||
    bad "dither JPEG --size to XBM"
head -c 200 "$work/g.jpg" >"$work/cut.jpg"
"$stipple" dither "$work/cut.jpg" -o "$work/cut.pbm" 2>"$work/err"
rc=$?
[ $rc = 1 ] && grep -q "cut.jpg: not a readable JPEG" "$work/err" && [ ! -e "$work/cut.pbm" ] && ok ||
    bad "a truncated JPEG: exit $rc, '$(cat "$work/err")'"

# --- 4. NFF resolution: a note on a terminal (script(1) gives it one)
script -qec "'$stipple' render '$scene' -o '$work/r.pbm'" /dev/null >"$work/tty" </dev/null
grep -q "asks for 512x512 (its resolution line); drawing 128x64" "$work/tty" && ok || bad "no note of the resolution line: $(cat "$work/tty")"
script -qec "'$stipple' render '$scene' -s 64x32 -o '$work/r.pbm'" /dev/null >"$work/tty" </dev/null
[ ! -s "$work/tty" ] && ok || bad "a note although --size was given: $(cat "$work/tty")"
"$stipple" render "$scene" -o "$work/r.pbm" 2>"$work/err"
[ ! -s "$work/err" ] && ok || bad "a note on stderr that is not a terminal"

# --- 5. progress
STIPPLE_PROGRESS=always "$stipple" render "$scene" -s 64x64 -o "$work/pr.pbm" 2>"$work/err"
tr '\r' '\n' <"$work/err" >"$work/bar"
if grep -q ' 50%.* s left' "$work/bar" && grep -q '100%' "$work/bar" && cmp -s "$work/pr.pbm" <("$stipple" render "$scene" -s 64x64 -o - --format pbm 2>/dev/null); then ok
else bad "progress: no bar moving through 50% with the time left, or another picture: $(head -c 300 "$work/bar")"; fi

# --- 6. choices in errors
choices() { # WANT ARGS...
    local want=$1
    shift
    "$stipple" "$@" 2>"$work/err" >/dev/null
    local rc=$?
    [ $rc = 2 ] && grep -qF -- "$want" "$work/err" && ok || bad "'$*': exit $rc, '$(cat "$work/err")' lacks '$want'"
}
choices "bayer2, bayer4, bayer8, bayer16, blue-noise" render "$scene" -d floyd -o "$work/x.pbm"
choices "bayer2, bayer4, bayer8, bayer16, blue-noise" dither "$work/g.pgm" -d floyd -o "$work/x.pbm"
choices "(fit, fill, stretch)" dither "$work/g.pgm" --resize crop -o "$work/x.pbm"
choices "(0, 90, 180, 270" dither "$work/g.pgm" --rotate 45 -o "$work/x.pbm"
choices "(pbm, plain-pbm, png1, xbm, c, c-pages)" dither "$work/g.pgm" --format pgm -o "$work/x.pbm"
choices "xbm, c, c-pages)" render "$scene" --format gif -o "$work/x.pbm"
choices "(auto, off)" render "$scene" --exposure on -o "$work/x.pbm"
choices "(zbuffer, painter, none)" render "$scene" --hidden x -o "$work/x.pbm"
choices "give a .pbm, .png, .xbm or .h name" dither "$work/g.pgm" -o "$work/x.gif"

echo "$passes passed, $failures failed"
[ "$failures" = 0 ]
