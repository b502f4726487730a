#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job on a fresh machine: install, build, render the Utah teapot from
# the Standard Procedural Databases to a PBM and print it as a line-printer dump.
# Usage: scripts/demo.sh [SCENE.nff]
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
scene=${1:-$here/../shared/scenes/teapot-s2.nff}
"$here/scripts/install-deps.sh"
cmake -S "$here" -B "$here/build-demo" -DCMAKE_BUILD_TYPE=Release -DSTP_BUILD_TESTS=OFF >/dev/null
cmake --build "$here/build-demo" -j"$(nproc)" --target stipple >/dev/null
mkdir -p "$here/out"
"$here/build-demo/tools/stipple" render "$scene" -s 128x64 -o "$here/out/teapot.pbm"
"$here/build-demo/tools/stipple" render "$scene" -s 512x512 -o "$here/out/teapot-512.pbm"
echo "wrote out/teapot.pbm (128x64) and out/teapot-512.pbm (512x512); the 128x64 picture as text:"
"$here/build-demo/tools/stipple" render "$scene" -s 128x64 -o -
