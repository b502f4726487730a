#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `stipple compile --spans` (run by CTest): it writes stp_compiled_spans for
# shared scenes (it checks the spans against the core's own picture itself
# and fails if they differ), its runs cover every row exactly once, and it
# refuses, with a message and a non-zero status, what the span player cannot
# draw (error diffusion, a mask cell, more than 256 pixels a row) without
# leaving a half-written file.
# Usage: test_compile_spans.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

for scene in tetra-s1 teapot-s1 gears-s1; do
    if ! "$stipple" compile "$scenes/$scene.nff" --spans -s 128x64 -o "$work/$scene.c" 2>"$work/err"; then
        bad "$scene: $(cat "$work/err")"
        continue
    fi
    grep -q "^const stp_spans stp_compiled_spans = {128, 64, 4, " "$work/$scene.c" ||
        bad "$scene: no stp_compiled_spans for 128x64 with 4-row patterns"
    rows=$(grep -c "/\* row [0-9]* \*/" "$work/$scene.c")
    [ "$rows" = 64 ] || bad "$scene: $rows rows of runs, not 64"
    grep -q "#define STP_PLAYBACK_ONLY 1" "$work/${scene}_config.h" || bad "$scene: config header"
done

for refused in "-d fs" "-d blue-noise" "-s 300x20"; do
    # shellcheck disable=SC2086
    if "$stipple" compile "$scenes/tetra-s1.nff" --spans $refused -o "$work/no.c" 2>"$work/err"; then
        bad "--spans $refused was accepted"
    elif ! grep -q "spans" "$work/err"; then
        bad "--spans $refused: no message naming --spans: $(cat "$work/err")"
    fi
    [ ! -e "$work/no.c" ] || bad "--spans $refused left $work/no.c"
done

[ "$failures" -eq 0 ] || exit 1
echo "PASS"
