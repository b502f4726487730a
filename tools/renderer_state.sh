#!/bin/sh
# SPDX-License-Identifier: MIT
# The renderer object's size (sizeof(stp_renderer): every byte of renderer
# state, entry and frame; the display file, bands and meshes are the
# caller's) per configuration, on a Cortex-M0+ (arm-none-eabi-gcc) and an
# ATmega328P (avr-gcc): firmware/renderer_probe.c compiled with the
# configuration's switches, its one object's size read back with nm -S, as
# the firmware build reads STP_RENDERER_BYTES.
#
# usage: renderer_state.sh [--budget BYTES] SOURCE_DIR
#   --budget BYTES  fail (exit 1) when the Cortex-M0+ triangle build's
#                   object (STP_MAX_POLYGON_VERTICES=3, the other switches
#                   at their defaults) is larger than BYTES
# Prints a table: configuration, Cortex-M0+ bytes, ATmega328P bytes ("-"
# where that compiler is missing).  Exit 77 when arm-none-eabi-gcc is not
# installed (skipped).
set -eu
budget=""
if [ "${1:-}" = "--budget" ]; then
    [ $# -ge 2 ] || { echo "usage: $0 [--budget BYTES] SOURCE_DIR" >&2; exit 2; }
    budget=$2
    shift 2
fi
[ $# -eq 1 ] || { echo "usage: $0 [--budget BYTES] SOURCE_DIR" >&2; exit 2; }
src=$(cd "$1" && pwd)
command -v arm-none-eabi-gcc >/dev/null 2>&1 || { echo "$0: arm-none-eabi-gcc not found: skipped" >&2; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# sizeof(stp_renderer) for compiler $1 (arm or avr) with definitions $2
state_bytes() {
    case $1 in
    arm) cc="arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb"; nm=arm-none-eabi-nm ;;
    avr) cc="avr-gcc -mmcu=atmega328p"; nm=avr-nm ;;
    esac
    command -v "$nm" >/dev/null 2>&1 || { echo "-"; return 0; }
    # shellcheck disable=SC2086 # word lists
    $cc -Os -std=c99 -I "$src/include" -I "$src/src" $2 -c "$src/firmware/renderer_probe.c" -o "$work/probe.o"
    "$nm" -S -t d "$work/probe.o" | awk '$4 == "stp_renderer_probe" { print $2 + 0 }'
}

triangles="-DSTP_MAX_POLYGON_VERTICES=3"
printf '%-58s %8s %8s\n' "configuration" "M0+" "AVR"
while IFS='|' read -r name defs; do
    printf '%-58s %8s %8s\n' "$name" "$(state_bytes arm "$defs")" "$(state_bytes avr "$defs")"
done <<EOF
default|
triangles (STP_MAX_POLYGON_VERTICES=3)|$triangles
triangles, 1 light, no specular, 1 segment|$triangles -DSTP_MAX_LIGHTS=1 -DSTP_WITH_SPECULAR=0 -DSTP_MAX_SEGMENTS=1
quadrilaterals (STP_MAX_POLYGON_VERTICES=4)|-DSTP_MAX_POLYGON_VERTICES=4
EOF

if [ -n "$budget" ]; then
    bytes=$(state_bytes arm "$triangles")
    [ -n "$bytes" ] || { echo "FAIL: no size read back for the triangle build" >&2; exit 1; }
    if [ "$bytes" -gt "$budget" ]; then
        echo "FAIL: the Cortex-M0+ triangle build's renderer object is $bytes B, over $budget B" >&2
        exit 1
    fi
    echo "the Cortex-M0+ triangle build's renderer object: $bytes B, within $budget B"
fi
