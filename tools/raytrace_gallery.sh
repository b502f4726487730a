#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's ray-tracing comparisons: each scene ray-traced at 512x512 in
# colour (256 levels) and halftoned to PBM, beside the Standard Procedural
# Databases' own picture, scaled to 256 pixels a panel, as
# docs/raytrace/<name>.png.  Needs ImageMagick (convert).
# Usage: tools/raytrace_gallery.sh BUILD_DIR [SCENES_DIR]
set -eu
build=${1:?usage: tools/raytrace_gallery.sh BUILD_DIR [SCENES_DIR]}
here=$(cd "$(dirname "$0")/.." && pwd)
scenes=${2:-$here/../shared/scenes}
out=$here/docs/raytrace
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
for pair in balls:balls-s2 mount:mount-s2 teapot:teapot-s2 tetra:tetra-s2 gears:gears-s1; do
    ref=${pair%%:*} scene=${pair#*:}
    "$build/tools/stipple" render "$scenes/$scene.nff" --raytrace --color --levels 256 \
        -s 512x512 -o "$work/$scene.ppm"
    "$build/tools/stipple" render "$scenes/$scene.nff" --raytrace -s 512x512 -o "$work/$scene.pbm"
    convert "$work/$scene.ppm" "$scenes/reference/$ref.png" "$work/$scene.pbm" \
        -resize 256x256 +append -strip "$out/$ref.png"
    echo "wrote docs/raytrace/$ref.png"
done
