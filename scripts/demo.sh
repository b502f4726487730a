#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The first picture on a fresh Debian 12 machine, from a bare clone with
# nothing beside it: install only what building and rendering need (cmake,
# make, gcc, libc6-dev, libpng-dev for PNG and libgif-dev for animated GIFs),
# build the stipple command, write the Utah teapot
# with 'stipple scene', render it to out/teapot.pbm (128x64) and
# out/teapot-512.pbm, and print it on the terminal as text.
# Usage: scripts/demo.sh [SCENE.nff|.obj|.off]   (another scene instead)
# Environment: STP_DEMO_SKIP_INSTALL=1 installs nothing; STP_DEMO_STIPPLE=PATH
# renders with that stipple command instead of building one;
# STP_DEMO_OUT=DIR writes there instead of out/.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
out=${STP_DEMO_OUT:-$here/out}
as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

if [ "${STP_DEMO_SKIP_INSTALL:-0}" != 1 ]; then
    missing=()
    for p in cmake make gcc libc6-dev libpng-dev libgif-dev; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    if [ "${#missing[@]}" -gt 0 ]; then
        as_root apt-get update -q >/dev/null
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
    fi
fi

stipple=${STP_DEMO_STIPPLE:-}
if [ -z "$stipple" ]; then
    # the command alone: no tests (cmocka), no Linux device ports (libusb, libgpiod)
    cmake -S "$here" -B "$here/build-demo" -DCMAKE_BUILD_TYPE=Release -DSTP_BUILD_TESTS=OFF \
        -DSTP_WITH_LINUX=OFF >/dev/null
    cmake --build "$here/build-demo" -j"$(nproc)" --target stipple >/dev/null
    stipple=$here/build-demo/tools/stipple
fi

mkdir -p "$out"
if [ $# -ge 1 ]; then
    scene=$1
    name=$(basename "${scene%.*}")
else
    scene=$out/teapot.nff
    name=teapot
    "$stipple" scene teapot --size 4 -o "$scene"
fi
"$stipple" render "$scene" -s 128x64 -o "$out/$name.pbm"
"$stipple" render "$scene" -s 512x512 -o "$out/$name-512.pbm"
# as wide as the terminal allows (at most 128 columns), half as many rows:
# a character is about twice as tall as it is wide
columns=$( (stty size </dev/tty) 2>/dev/null | cut -d' ' -f2 || true)
case "$columns" in '' | *[!0-9]*) columns=80 ;; esac
[ "$columns" -gt 128 ] && columns=128
echo "wrote ${out#"$here"/}/$name.pbm (128x64) and ${out#"$here"/}/$name-512.pbm (512x512); as text:"
"$stipple" render "$scene" -s "${columns}x$((columns / 2))" -o -
