#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's 128x64 pictures (docs/dither.md): for every shared scene, the
# ideal (a 512x256 render at 256 levels with automatic exposure,
# box-filtered to 128x64), the old default 1-bit picture (Bayer 4x4, 16
# levels) and the default for a still 1-bit picture (Floyd-Steinberg, 256
# levels, automatic exposure), each enlarged 4x, side by side, as
# docs/dither/<scene>.png; and docs/dither/all-128x64.png, every scene's
# ideal and still default, for the README.  Needs ImageMagick (convert).
# Usage: tools/dither_gallery.sh BUILD_DIR [SCENES_DIR]
set -eu
build=${1:?usage: tools/dither_gallery.sh BUILD_DIR [SCENES_DIR]}
here=$(cd "$(dirname "$0")/.." && pwd)
scenes=${2:-$here/../shared/scenes}
out=$here/docs/dither
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
for nff in "$scenes"/*.nff; do
    name=$(basename "$nff" .nff)
    "$build/tools/stipple" render "$nff" -s 512x256 -l 256 --exposure auto -o "$work/ideal.pgm"
    "$build/tools/stipple" render "$nff" -d bayer4 -l 16 -o "$work/bayer.pbm"
    "$build/tools/stipple" render "$nff" -o "$work/still.pbm"
    convert "$work/ideal.pgm" -filter box -resize 128x64 -scale 400% "$work/ideal.png"
    convert "$work/ideal.png" \( "$work/bayer.pbm" -scale 400% \) \( "$work/still.pbm" -scale 400% \) \
        -background grey50 -splice 8x0 +append -chop 8x0 -strip -colors 256 "$out/$name.png"
    echo "wrote docs/dither/$name.png"
    convert "$work/ideal.png" \( "$work/still.pbm" -scale 400% \) -background grey50 -splice 8x0 +append \
        -chop 8x0 "$work/pair-$name.png"
done
# the README's overview: ideal and still default of every scene, two a row
set -- $(cd "$scenes" && ls *.nff | sed 's/\.nff$//')
rows="" row=0
while [ $# -gt 0 ]; do
    row=$((row + 1))
    if [ $# -gt 1 ]; then
        convert "$work/pair-$1.png" "$work/pair-$2.png" -background white -splice 24x0 +append -chop 24x0 \
            "$work/row-$row.png"
        shift 2
    else
        cp "$work/pair-$1.png" "$work/row-$row.png"
        shift
    fi
    rows="$rows $work/row-$row.png"
done
convert $rows -background white -splice 0x16 -append -chop 0x16 -strip -colors 256 "$out/all-128x64.png"
echo "wrote docs/dither/all-128x64.png"
