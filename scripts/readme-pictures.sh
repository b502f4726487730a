#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's pictures, from the real renderer, as a 128x64 OLED shows them
# (lit pixels light on a dark panel): the Utah teapot, a torus and a
# Sierpinski tetrahedron from 'stipple scene', their floors left out (a
# mid-grey floor swallows a model at 128x64), each at 1:1 and 4x enlarged.
# The animation (docs/spin-128x64.gif) comes from scripts/pictures.sh.
# Needs the stipple command and ImageMagick's convert (Debian: imagemagick).
# Usage: scripts/readme-pictures.sh [STIPPLE]   (default build/tools/stipple)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
stipple=${1:-$here/build/tools/stipple}
out=$here/docs/readme
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v convert >/dev/null || { echo "readme-pictures.sh: needs convert (imagemagick)" >&2; exit 1; }
mkdir -p "$out"

# NAME SIZE FLOOR_BLOCKS [from at angle]: the scene without its first
# FLOOR_BLOCKS materials (the floor), optionally seen from elsewhere
scene() {
    "$stipple" scene "$1" --size "$2" -o "$work/$1-full.nff"
    awk -v k="$3" -v from="${4:-}" -v at="${5:-}" -v angle="${6:-}" '
        /^f / { n++ }
        n >= 1 && n <= k { next }
        from != "" && /^from / { print "from " from; next }
        at != "" && /^at / { print "at " at; next }
        angle != "" && /^angle / { print "angle " angle; next }
        { print }' "$work/$1-full.nff" >"$work/$1.nff"
}
scene teapot 2 2 "3 9 3.5" "0.3 0 1.4" 26
scene torus 2 1
scene tetra 3 0

panel() { # IN OUT SCALE BORDER: enlarged SCALE, in a dark bezel BORDER pixels wide
    convert "$1" -scale "$3" -bordercolor '#303030' -border "$4" "$2"
}
for name in teapot torus tetra; do
    # the still default (error diffusion after automatic exposure), 1-bit,
    # on a black background: PNG's white is a lit pixel
    "$stipple" render "$work/$name.nff" -s 128x64 --background 0 --format png1 -o "$out/$name-128x64.png"
    panel "$out/$name-128x64.png" "$out/$name-128x64-x4.png" 400% 8
done

echo "wrote docs/readme/{teapot,torus,tetra}-128x64{,-x4}.png"
