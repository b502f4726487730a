#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Code and RAM of the shipping lm3s6965evb image for every shared scene as a
# static scene (stipple compile --static: the display file in flash, the
# playback-only core), Cortex-M0+, -Os, LTO, 1-row bands, beside the same
# scene entered on the chip (4-row bands) and as visible spans (stipple
# compile --spans: the picture's rows as runs of one shade, the span player
# only, 1-row bands): a Markdown table of arm-none-eabi-size figures
# (RAM = .data + .bss).
# Usage: tools/firmware_static_sizes.sh STIPPLE_BINARY [SCENES_DIR] [WORK_DIR]
set -u
stipple=$(realpath "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
scenes=${2:-$here/../shared/scenes}
work=${3:-$(mktemp -d)}
mkdir -p "$work"
size_of() { # build dir -> "text ram", or the reason it does not build
    if [ -f "$1/stipple_fw_lm3s6965evb.elf" ]; then
        arm-none-eabi-size "$1/stipple_fw_lm3s6965evb.elf" | tail -1 | awk '{print $1 " | " $2 + $3}'
    else
        echo "does not build: $(grep -m1 -oE "region .(SRAM|FLASH). overflowed by [0-9]+ bytes" "$1.log" ||
            echo "see $1.log") |"
    fi
}
echo "| scene | on the chip: .text | RAM | static: .text | RAM | spans: .text | RAM |"
echo "|---|---|---|---|---|---|---|"
for nff in "$scenes"/*.nff; do
    name=$(basename "$nff" .nff)
    for mode in chip static spans; do
        b="$work/$name-$mode"
        case $mode in
            static) opts="-DSTP_FW_STATIC=ON -DSTP_FW_BAND_ROWS=1" ;;
            spans) opts="-DSTP_FW_SPANS=ON -DSTP_FW_BAND_ROWS=1" ;;
            *) opts="-DSTP_FW_BAND_ROWS=4" ;;
        esac
        # shellcheck disable=SC2086
        cmake -S "$here/firmware" -B "$b" -DCMAKE_TOOLCHAIN_FILE="$here/cmake/toolchain-arm-none-eabi.cmake" \
            -DSTP_CPU=cortex-m0plus -DSTP_FW_COMPILE_TOOL="$stipple" -DSTP_FW_SCENE="$nff" $opts >"$b.log" 2>&1 &&
            cmake --build "$b" -j2 --target stipple_fw_lm3s6965evb >>"$b.log" 2>&1
    done
    echo "| $name | $(size_of "$work/$name-chip") | $(size_of "$work/$name-static") | $(size_of "$work/$name-spans") |"
done
