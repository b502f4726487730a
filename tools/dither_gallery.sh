#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's 128x64 pictures (docs/dither.md): for every shared scene, the
# ideal (a 512x256 render at 256 levels with automatic exposure,
# box-filtered to 128x64), the old default 1-bit picture (Bayer 4x4, 16
# levels) and the default for a still 1-bit picture (Floyd-Steinberg, 256
# levels, automatic exposure), each enlarged 4x, side by side, as
# docs/dither/<scene>.png.  Needs ImageMagick (convert).
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
done
