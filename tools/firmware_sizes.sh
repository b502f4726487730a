#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Code and RAM of the lm3s6965evb firmware for every shared scene, minimal
# configuration (the scene's generated config header) and full library, on
# Cortex-M0+ and M4: prints a Markdown table of arm-none-eabi-size figures.
# Usage: tools/firmware_sizes.sh STIPPLE_BINARY [SCENES_DIR] [WORK_DIR]
set -u
stipple=$(realpath "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
scenes=${2:-$here/tests/data/spd}
work=${3:-$(mktemp -d)}
mkdir -p "$work"
echo "| scene | CPU | minimal .text | minimal .bss | full .text | full .bss |"
echo "|---|---|---|---|---|---|"
for nff in "$scenes"/*.nff; do
    name=$(basename "$nff" .nff)
    for cpu in cortex-m0plus cortex-m4; do
        b="$work/$name-$cpu"
        if cmake -S "$here/firmware" -B "$b" -DCMAKE_TOOLCHAIN_FILE="$here/cmake/toolchain-arm-none-eabi.cmake" \
            -DSTP_CPU="$cpu" -DSTP_FW_COMPILE_TOOL="$stipple" -DSTP_FW_SCENE="$nff" >"$b.log" 2>&1 &&
            cmake --build "$b" >>"$b.log" 2>&1; then
            read -r mt md mb _ < <(arm-none-eabi-size "$b/stipple_fw_lm3s6965evb.elf" | tail -1)
            read -r ft fd fb _ < <(arm-none-eabi-size "$b/stipple_fw_lm3s6965evb_full.elf" | tail -1)
            echo "| $name | ${cpu#cortex-} | $mt | $((md + mb)) | $ft | $((fd + fb)) |"
        else
            reason=$(grep -m1 -oE "region .RAM. overflowed by [0-9]+ bytes|error: .*" "$b.log" | head -c 80)
            echo "| $name | ${cpu#cortex-} | does not build: ${reason:-see $b.log} | | | |"
        fi
    done
done
