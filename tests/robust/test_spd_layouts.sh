#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every SPD-like database (spd_like.py: the SPD programs' layouts, one-line
# cones) at size factors 1-3, the SPD files of tests/data/spd and the scenes
# of 'stipple scene' at size factors 1-3 render in every mode with exit 0
# and a valid file; CRLF and byte-order-mark variants too; a 66 430-sphere sphereflake
# ray-traces; -o through a symbolic link to /dev/null, to /proc/self/fd/1
# (redirected to a file), a FIFO.
# usage: test_spd_layouts.sh STIPPLE SPD_LIKE_PY WORK_DIR
set -u
stipple=$1 gen=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0 runs=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
validate() { # file
    if command -v pamvalidate >/dev/null; then
        pamvalidate < "$1" >/dev/null 2>&1 || fail "$1 is not a valid Netpbm file"
    fi
}
# render NFF in every mode with exit 0 and a valid file
every_mode() { # nff
    local nff=$1 mode args ext out
    for mode in flat smooth colour shadows transparent raytrace; do
        runs=$((runs + 1))
        case $mode in
        flat) args=() ext=pbm ;;
        smooth) args=(--smooth) ext=pbm ;;
        colour) args=(--color) ext=ppm ;;
        shadows) args=(--shadows 128) ext=pbm ;;
        transparent) args=(--color --transparent) ext=ppm ;;
        raytrace) args=(--raytrace) ext=pgm ;;
        esac
        out=${nff%.nff}-$mode.$ext
        if ! "$stipple" render "$nff" "${args[@]}" --size 64x48 -o "$out" 2> "$work/err"; then
            fail "$(basename "$nff") $mode: $(cat "$work/err")"
            continue
        fi
        validate "$out"
    done
}
for db in rings tree jacks lattice shells sombrero balls; do
    for size in 1 2 3; do
        nff=$work/$db-s$size.nff
        python3 "$gen" "$db" "$size" > "$nff" || { fail "generate $db $size"; continue; }
        every_mode "$nff"
    done
done
# the SPD's own files in the repository (balls, gears, mount, teapot,
# tetra) and the SPD-like scenes stipple writes, at size factors 1-3
for nff in "$(dirname "$0")"/../data/spd/*.nff; do
    cp "$nff" "$work/spd-$(basename "$nff")" && every_mode "$work/spd-$(basename "$nff")"
done
for name in teapot tetra sphereflake torus rings mountain; do
    for size in 1 2 3; do
        nff=$work/scene-$name-s$size.nff
        "$stipple" scene "$name" --size "$size" -o "$nff" || { fail "stipple scene $name $size"; continue; }
        every_mode "$nff"
    done
done
# the same layouts with CRLF line ends and a byte-order mark
python3 "$gen" rings 1 --crlf --bom > "$work/rings-crlf.nff"
"$stipple" render "$work/rings-crlf.nff" --size 64x48 -o "$work/crlf.pbm" || fail "CRLF + BOM"
"$stipple" render "$work/rings-s1.nff" --size 64x48 -o "$work/lf.pbm" || fail "LF"
cmp -s "$work/crlf.pbm" "$work/lf.pbm" || fail "CRLF + BOM picture differs from LF"
# balls at size 5: 66 430 spheres, traced without tessellation
python3 "$gen" balls 5 > "$work/balls-s5.nff"
"$stipple" render "$work/balls-s5.nff" --raytrace --size 32x24 -o "$work/balls-s5.pbm" 2> "$work/err" ||
    fail "balls-s5 --raytrace: $(cat "$work/err")"
# output targets: a link to /dev/null stays a link, a FIFO stays a FIFO
ln -s /dev/null "$work/null.pbm"
"$stipple" render "$work/rings-s1.nff" --size 64x48 -o "$work/null.pbm" || fail "-o link to /dev/null"
[ -L "$work/null.pbm" ] || fail "the link to /dev/null was replaced"
[ -c /dev/null ] || fail "/dev/null is no longer a character device"
mkfifo "$work/fifo.pbm"
cat "$work/fifo.pbm" > "$work/from-fifo.pbm" &
reader=$!
"$stipple" render "$work/rings-s1.nff" --size 64x48 -o "$work/fifo.pbm" || fail "-o FIFO"
wait "$reader"
[ -p "$work/fifo.pbm" ] || fail "the FIFO was replaced"
cmp -s "$work/from-fifo.pbm" "$work/lf.pbm" || fail "what came through the FIFO differs"
# a link to /proc/self/fd/1 (what /dev/stdout is) with stdout redirected
# to a file: the bytes go to that file, the link stays
ln -s /proc/self/fd/1 "$work/stdout.pbm"
"$stipple" render "$work/rings-s1.nff" --size 64x48 -o "$work/stdout.pbm" > "$work/captured.pbm" ||
    fail "-o link to /proc/self/fd/1"
[ -L "$work/stdout.pbm" ] || fail "the link to /proc/self/fd/1 was replaced"
cmp -s "$work/captured.pbm" "$work/lf.pbm" || fail "what went to the redirected stdout differs"
if [ "$(find "$work" -name '.*' -type f | wc -l)" -ne 0 ]; then fail "temporary files left"; fi
[ "$failures" -eq 0 ] && echo "all SPD layouts rendered in every mode ($runs renders)"
exit $((failures > 0))
