#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerate tests/golden/*-128x64.pbm from the current renderer: run after an
# intended change of the pictures, look at them, and say why in the commit.
# Usage: tools/update_golden.sh BUILD_DIR [SCENES_DIR]
set -eu
build=${1:?usage: tools/update_golden.sh BUILD_DIR [SCENES_DIR]}
here=$(cd "$(dirname "$0")/.." && pwd)
scenes=${2:-$here/tests/data/spd}

# The goldens hold the library's defaults (stp_tool_options_default: Bayer
# 4x4, 16 levels, no automatic exposure), which the golden tests render;
# `stipple render` to a PBM file defaults to Floyd-Steinberg at 256 levels
# with automatic exposure (stp_tool_still_defaults).
lib_defaults="-d bayer4 -l 16 --exposure off"
for nff in "$scenes"/*.nff; do
    name=$(basename "$nff" .nff)
    "$build/tools/stipple" render $lib_defaults "$nff" -o "$here/tests/golden/$name-128x64.pbm"
    echo "wrote tests/golden/$name-128x64.pbm"
    "$build/tools/stipple" render $lib_defaults "$nff" --raytrace -o "$here/tests/golden/$name-raytrace-128x64.pbm"
    echo "wrote tests/golden/$name-raytrace-128x64.pbm"
done
"$build/tools/stipple" render $lib_defaults "$scenes/teapot-s2.nff" --smooth -o "$here/tests/golden/teapot-s2-smooth-128x64.pbm"
echo "wrote tests/golden/teapot-s2-smooth-128x64.pbm"
"$build/tools/stipple" render $lib_defaults "$scenes/teapot-s1.nff" --edge-aa -o "$here/tests/golden/teapot-s1-edge-aa-128x64.pbm"
echo "wrote tests/golden/teapot-s1-edge-aa-128x64.pbm"
for name in balls-s1 mount-s2 tetra-s1; do
    "$build/tools/stipple" render $lib_defaults "$scenes/$name.nff" --color -o "$here/tests/golden/$name-colour-128x64.ppm"
    echo "wrote tests/golden/$name-colour-128x64.ppm"
done
for name in balls-s1 mount-s2; do
    "$build/tools/stipple" render $lib_defaults "$scenes/$name.nff" --shadows 256 -o "$here/tests/golden/$name-shadows-128x64.pbm"
    echo "wrote tests/golden/$name-shadows-128x64.pbm"
done
"$build/tools/stipple" render $lib_defaults "$scenes/mount-s2.nff" --color --transparent --hidden painter \
    -o "$here/tests/golden/mount-s2-transparent-colour-128x64.ppm"
echo "wrote tests/golden/mount-s2-transparent-colour-128x64.ppm"
"$build/tools/stipple" render $lib_defaults "$scenes/teapot-s1.nff" --outlines both \
    -o "$here/tests/golden/teapot-s1-outlines-128x64.pbm"
echo "wrote tests/golden/teapot-s1-outlines-128x64.pbm"
