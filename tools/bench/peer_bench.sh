#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The side-by-side torus bench of issue 21: stipple's mesh route against
# small3dlib in one program (tools/bench/peer_bench.c), instructions per
# frame counted by callgrind inside the frame function only
# (--toggle-collect=torus_frame / peer_s3l_frame: set-up, pose and exit not
# counted), at 128x64, 400x240 and 640x480, still and spinning, and a
# 100 000-triangle torus at 400x240; a table with the ratio
# stipple / small3dlib.  gcc -O2, the same workload as torus_bench.sh
# --mesh (see tools/bench/torus.h and peer_s3l.h), stipple with pixel
# culling on (stp_renderer_set_pixel_cull: the same frames, no edge
# anti-aliasing; peer_bench --keep-slivers turns it off).
#
# usage: peer_bench.sh [--peer-small3dlib DIR] [--peer-zbuffer 1|2] [--frames N] [--quick] BUILD_DIR
#   BUILD_DIR   a build folder of its own (created if missing), configured
#               here as docs/realtime.md measures: -DCMAKE_BUILD_TYPE=
#               -DCMAKE_C_FLAGS=-O2 (tests and Linux ports off); only the
#               peer_bench target is built
#   --peer-small3dlib DIR  a folder holding small3dlib.h (drummyfish's
#               small3dlib, never copied into this repository), e.g.
#                 git clone https://codeberg.org/drummyfish/small3dlib DIR
#               (or a GitHub mirror of it); without it only stipple's
#               figures are printed and the comparison is reported skipped
#   --peer-zbuffer 2 (default): small3dlib's reduced Z buffer of bytes, its
#               cheaper (and on this torus the same picture); 1: its full
#               32-bit Z buffer
#   --frames N  frames counted per 1000-triangle case (default 20; the
#               100 000-triangle case counts max(N / 10, 1))
#   --quick     2 frames, 128x64 still only (a smoke run for CI)
# Example (from the repository's top):
#   tools/bench/peer_bench.sh --peer-small3dlib /tmp/small3dlib build-peer
set -euo pipefail

frames=20
peer=""
zbuf=2
quick=0
while [ $# -gt 1 ]; do
    case $1 in
    --peer-small3dlib) peer=$2; shift 2 ;;
    --peer-zbuffer) zbuf=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    *) echo "peer_bench.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
[ $# -eq 1 ] || { sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
build=$1
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
command -v valgrind >/dev/null || { echo "peer_bench.sh: valgrind not found" >&2; exit 1; }
case $zbuf in 1 | 2) ;; *) echo "peer_bench.sh: --peer-zbuffer takes 1 or 2" >&2; exit 2 ;; esac
case $frames in '' | *[!0-9]* | 0) echo "peer_bench.sh: --frames takes a positive count" >&2; exit 2 ;; esac
if [ -n "$peer" ]; then
    [ -f "$peer/small3dlib.h" ] || { echo "peer_bench.sh: no small3dlib.h in $peer" >&2; exit 1; }
    peer=$(cd "$peer" && pwd)
fi

mkdir -p "$build"
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE= -DCMAKE_C_FLAGS=-O2 -DSTP_BUILD_TESTS=OFF \
    -DSTP_WITH_LINUX=OFF -DSTP_PEER_SMALL3DLIB_DIR="$peer" -DSTP_PEER_SMALL3DLIB_ZBUFFER="$zbuf" >"$build/peer_configure.log" 2>&1 ||
    { cat "$build/peer_configure.log" >&2; exit 1; }
cmake --build "$build" --target peer_bench -j2 >/dev/null ||
    { echo "peer_bench.sh: building peer_bench failed" >&2; exit 1; }
exe=$build/tools/bench/peer_bench

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# instr RENDERER FRAMES ARGS...: million instructions per frame
instr() {
    local who=$1 n=$2 fn=torus_frame out total
    shift 2
    [ "$who" = small3dlib ] && fn=peer_s3l_frame
    out=$dir/callgrind.out
    valgrind --tool=callgrind --toggle-collect=$fn --callgrind-out-file="$out" \
        "$exe" --renderer "$who" --frames "$n" "$@" >/dev/null 2>"$dir/valgrind.log" ||
        { cat "$dir/valgrind.log" >&2; echo "peer_bench.sh: $who $* failed" >&2; exit 1; }
    total=$(sed -n 's/^summary: \([0-9]*\).*/\1/p' "$out")
    [ -n "$total" ] || total=$(sed -n 's/^totals: \([0-9]*\).*/\1/p' "$out")
    [ -n "$total" ] || { echo "peer_bench.sh: no total in $out" >&2; exit 1; }
    awk -v t="$total" -v f="$n" 'BEGIN { printf "%.3f", t / f / 1e6 }'
}

fine_frames=$((frames / 10 > 0 ? frames / 10 : 1))
cases=("1000 still 128x64" "1000 still 400x240" "1000 still 640x480"
       "1000 spin 128x64" "1000 spin 400x240" "1000 spin 640x480"
       "100000 still 400x240" "100000 spin 400x240")
if [ "$quick" = 1 ]; then
    frames=2
    cases=("1000 still 128x64")
fi

cc=$(sed -n 's/^CMAKE_C_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
rev=$(git -C "$top" rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ "$rev" != unknown ] && ! git -C "$top" diff --quiet HEAD -- src include tools/bench 2>/dev/null; then
    rev="$rev+changes"
fi
echo "stipple $rev, $(date -u +%Y-%m-%d), $("$cc" --version | head -n 1), -O2, callgrind instructions per frame"
if [ -n "$peer" ]; then
    pv=$(sed -n 's/^ *version: *\(.*\)/\1/p' "$peer/small3dlib.h" | head -n 1)
    pc=$(git -C "$peer" rev-parse --short HEAD 2>/dev/null || echo "not a git checkout")
    echo "small3dlib ${pv:-version unknown} ($pc) from $peer, S3L_Z_BUFFER $zbuf"
fi
printf "%-10s %-6s %-9s %14s %14s %16s\n" triangles pose size "stipple M" "small3dlib M" "stipple/s3l"
for c in "${cases[@]}"; do
    read -r tri pose size <<<"$c"
    args=(--size "$size")
    n=$frames
    [ "$pose" = spin ] && args+=(--spin)
    [ "$tri" = 100000 ] && { args+=(--fine 250x200); n=$fine_frames; }
    s=$(instr stipple "$n" "${args[@]}")
    if [ -n "$peer" ]; then
        p=$(instr small3dlib "$n" "${args[@]}")
        ratio=$(awk -v s="$s" -v p="$p" 'BEGIN { printf "%.2f", s / p }')
    else
        p=-
        ratio=skipped
    fi
    printf "%-10s %-6s %-9s %14s %14s %16s\n" "$tri" "$pose" "$size" "$s" "$p" "$ratio"
done
[ -n "$peer" ] || echo "comparison skipped: no --peer-small3dlib DIR (see the usage above)"
