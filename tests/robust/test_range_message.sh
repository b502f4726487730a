#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The core's refusal of a coordinate beyond its range (STP_ERR_RANGE) as the
# command reports it: with --no-rescale the scene's coordinates reach the
# core as they are, and a polygon 40 000 units from the eye gives exactly
# "stipple: FILE:LINE: coordinate ... beyond ...", exit status 1, no output
# file written and an existing one left as it was (nor a temporary file
# beside it); a coordinate beyond stp_fix is refused by the host the same
# way; without --no-rescale the same scene renders.
# usage: test_range_message.sh STIPPLE WORK_DIR
set -u
stipple=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

printf 'v\nfrom 0 0 -20000\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\nl 0 5 -10\n%s\n' \
    'f 1 1 1 1 0 0 0 1' > far.nff
printf 'p 3\n-10000 -10000 20000\n10000 -10000 20000\n0 10000 20000\n' >> far.nff
printf 'v 0 0 0\nv 40000 0 0\nv 0 40000 0\nf 1 2 3\n' > big.obj

# expect STATUS STDERR -- ARGS...: the exit status and the whole of stderr
expect() {
    local want_rc=$1 want_err=$2 rc
    shift 3
    "$stipple" "$@" 2> err.txt
    rc=$?
    [ "$rc" = "$want_rc" ] || fail "$*: exit $rc, want $want_rc"
    [ "$(cat err.txt)" = "$want_err" ] || fail "$*: stderr '$(cat err.txt)', want '$want_err'"
}

range="beyond the core's range (+-32767 units from the eye along each view axis); without --no-rescale the scene is scaled into it"

# no output before: none after
expect 1 "stipple: far.nff:10: coordinate (-10000, -10000, 20000) of polygon 1 $range" -- \
    render far.nff --no-rescale -o new.pgm
[ ! -e new.pgm ] || fail "new.pgm written"
# an old output stays as it was
printf 'old picture\n' > old.pgm
expect 1 "stipple: far.nff:10: coordinate (-10000, -10000, 20000) of polygon 1 $range" -- \
    render far.nff --no-rescale -o old.pgm
[ "$(cat old.pgm)" = "old picture" ] || fail "old.pgm changed"
# every mode of the polygon renderer takes the same path
expect 1 "stipple: far.nff:10: coordinate (-10000, -10000, 20000) of polygon 1 $range" -- \
    render far.nff --no-rescale --smooth --shadows 64 --color -o old.ppm
[ ! -e old.ppm ] || fail "old.ppm written"
# "polygon N" is the file's N: a sphere's tessellation and split pieces
# before it are not counted (the far polygon is the file's second)
{ printf 'v\nfrom 0 0 -20000\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\nl 0 5 -10\n%s\n' \
    'f 1 1 1 1 0 0 0 1'
  printf 's 0 0 0 100\np 3\n-100 -100 0\n100 -100 0\n0 100 0\n'
  printf 'p 3\n-10000 -10000 20000\n10000 -10000 20000\n0 10000 20000\n'; } > counted.nff
expect 1 "stipple: counted.nff:15: coordinate (-10000, -10000, 20000) of polygon 2 $range" -- \
    render counted.nff --no-rescale -o counted.pgm
[ ! -e counted.pgm ] || fail "counted.pgm written"
rm -f counted.nff
# beyond stp_fix: the host refuses it before the core would get it moved
expect 1 "stipple: big.obj:4: coordinate (40000, 0, 0) of polygon 1 beyond the core's range (+-32767 units); without --no-rescale the scene is scaled into it" -- \
    render big.obj --no-rescale -o old.pgm
[ "$(cat old.pgm)" = "old picture" ] || fail "old.pgm changed"
# exactly +-32767 units is within the range (render.h): a vertex there renders
printf 'v\nfrom 0 0 0\nat 0 0 1\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\nl 0 5 -10\n%s\n' \
    'f 1 1 1 1 0 0 0 1' > edge.nff
printf 'p 3\n32767 0 32767\n-100 100 32767\n-100 -32767 32767\n' >> edge.nff
expect 0 "" -- render edge.nff --no-rescale -o edge.pgm
rm -f edge.nff edge.pgm
# the ray tracer always rescales
expect 2 "stipple render: --no-rescale is for the polygon renderer (the ray tracer takes the scene scaled into its range)
Try 'stipple render --help'" -- render far.nff --no-rescale --raytrace -o x.pgm
# nothing else left in the directory (no temporary files)
left=$(ls -A | grep -v -x -e far.nff -e big.obj -e old.pgm -e err.txt)
[ -z "$left" ] || fail "files left: $left"

# rescaled (the default) the same files render: a lit triangle
for scene in far.nff big.obj; do
    expect 0 "" -- render "$scene" --size 64x48 -o ok.pgm
    lit=$(tail -c $((64 * 48)) ok.pgm | od -An -v -tu1 | tr -s ' ' '\n' | awk '$1 > 0' | wc -l)
    [ "$lit" -gt 100 ] || fail "$scene rescaled: only $lit lit pixels"
done

[ "$failures" = 0 ] && echo "all range messages right"
exit $((failures > 0))
