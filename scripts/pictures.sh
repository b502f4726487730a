#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the animated pictures in docs/ from the stipple command:
#   docs/spin-128x64.gif     Newell's teapot turning once at 128x64, lit pixels
#                            white on black as an SSD1306 OLED shows them,
#                            72 frames 5 degrees apart at 20 frames a second
#   docs/spin-128x64-x4.gif  the same enlarged 4 times (each pixel a 4x4 block,
#                            ImageMagick's -scale), for pages that shrink GIFs
# Usage: scripts/pictures.sh [STIPPLE_BINARY]   (default build/tools/stipple)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
stipple=${1:-$here/build/tools/stipple}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the teapot of 'stipple scene teapot' without its checkered floor (the
# lines before the teapot's material: the floor's materials and squares),
# on a black background
"$stipple" scene teapot --size 3 |
    awk 'NR == 1 || /^(b|v|from|at|up|angle|hither|resolution|l) / || /^v$/ { print; next }
         /^f 1 0.5 0.1/ { teapot = 1 } teapot' |
    sed 's/^b .*/b 0 0 0/' >"$work/teapot.nff"
"$stipple" animate "$work/teapot.nff" --eye 5.5,0,3 --at 0,0,1.2 --frames 72 --fps 20 --stats \
    -o "$here/docs/spin-128x64.gif"
convert "$here/docs/spin-128x64.gif" -coalesce -scale 400% -layers Optimize "$here/docs/spin-128x64-x4.gif"
ls -l "$here/docs/spin-128x64.gif" "$here/docs/spin-128x64-x4.gif"
