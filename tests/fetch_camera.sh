#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetch the "camera" test picture and ImageMagick's ordered dithers of it,
# for tests/core/test_dither_camera.c (run by CTest as the setup of the
# fixture "camera").
#
#   tests/fetch_camera.sh [DATA_DIR]      (default: $STP_BINARY_DIR/data)
#
# camera.png comes from Debian's python3-skimage package (apt-get download,
# then dpkg-deb -x); the package is cached as DATA_DIR/camera.png, so the
# download happens once per build tree.  The conversions are redone on every
# run with the real ImageMagick, /usr/bin/convert (not a stand-in earlier on
# PATH):
#   camera.pgm                 8-bit grey, P5
#   oNxN.pbm, oNxN.pgm         convert camera.pgm -ordered-dither oNxN, N = 2, 4, 8
# Any missing tool or failed step is an error (exit 1): the test must not
# pass by skipping.
set -eu

CONVERT=/usr/bin/convert
data=${1:-}
if [ -z "$data" ]; then
    if [ -z "${STP_BINARY_DIR:-}" ]; then
        echo "fetch_camera.sh: give DATA_DIR or set STP_BINARY_DIR" >&2
        exit 1
    fi
    data=$STP_BINARY_DIR/data
fi

fail() {
    echo "fetch_camera.sh: FAIL: $*" >&2
    exit 1
}

for tool in apt-get dpkg-deb; do
    command -v "$tool" >/dev/null 2>&1 || fail "$tool is not available"
done
[ -x "$CONVERT" ] || fail "$CONVERT (ImageMagick) is not installed"
version=$("$CONVERT" -version 2>/dev/null | head -n 1) || fail "$CONVERT -version failed"
case $version in
    *ImageMagick*) echo "fetch_camera.sh: using $version" ;;
    *) fail "$CONVERT is not ImageMagick: '$version'" ;;
esac

mkdir -p "$data"
cd "$data"

if [ ! -s camera.png ]; then
    rm -rf deb.tmp
    mkdir deb.tmp
    (cd deb.tmp && apt-get download python3-skimage) || fail "apt-get download python3-skimage failed"
    set -- deb.tmp/python3-skimage_*.deb
    [ -f "$1" ] || fail "apt-get download left no python3-skimage .deb"
    dpkg-deb -x "$1" deb.tmp/root || fail "dpkg-deb -x $1 failed"
    png=$(find deb.tmp/root -path '*/skimage/data/camera.png' | head -n 1)
    [ -n "$png" ] || fail "no skimage/data/camera.png in $1"
    cp "$png" camera.png.tmp
    mv camera.png.tmp camera.png
    rm -rf deb.tmp
fi

# 8-bit grey PGM (P5, maxval 255)
"$CONVERT" camera.png -depth 8 pgm:camera.pgm.tmp || fail "convert camera.png to PGM failed"
[ "$(head -c 2 camera.pgm.tmp)" = "P5" ] || fail "camera.pgm is not a P5 grey map"
mv camera.pgm.tmp camera.pgm

for n in 2 4 8; do
    map=o${n}x${n}
    "$CONVERT" camera.pgm -ordered-dither "$map" pbm:"$map.pbm.tmp" || fail "convert -ordered-dither $map (PBM) failed"
    "$CONVERT" camera.pgm -ordered-dither "$map" -depth 8 pgm:"$map.pgm.tmp" || fail "convert -ordered-dither $map (PGM) failed"
    [ "$(head -c 2 "$map.pbm.tmp")" = "P4" ] || fail "$map.pbm is not a raw PBM"
    [ "$(head -c 2 "$map.pgm.tmp")" = "P5" ] || fail "$map.pgm is not a raw PGM"
    mv "$map.pbm.tmp" "$map.pbm"
    mv "$map.pgm.tmp" "$map.pgm"
done
ls -l camera.png camera.pgm o2x2.pbm o4x4.pbm o8x8.pbm o2x2.pgm o4x4.pgm o8x8.pgm
echo "fetch_camera.sh: ok ($data)"
