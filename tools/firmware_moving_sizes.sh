#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Issue 15 item 3, what the existing switches give a model spinning on the
# chip: the lm3s6965evb shipping image of SCENE entered on the chip with the
# least configuration a convex model needs (--hidden none --backface: flat,
# the scene's lights, no Z buffer or painter's sort), Cortex-M0+, -Os,
# 4-row bands.  Prints the whole image with LTO (.text, RAM = .data + .bss)
# and, from a build without LTO (whose map file names each object's share;
# section GC on), the bytes of code and const data of the core's objects and
# of libgcc.
# Usage: tools/firmware_moving_sizes.sh STIPPLE_BINARY [SCENE] [WORK_DIR]
set -eu
stipple=$(realpath "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
scene=${2:-$here/../shared/scenes/tetra-s1.nff}
work=${3:-$(mktemp -d)}
mkdir -p "$work"
for lto in ON OFF; do
    b="$work/lto-$lto"
    cmake -S "$here/firmware" -B "$b" -DCMAKE_TOOLCHAIN_FILE="$here/cmake/toolchain-arm-none-eabi.cmake" \
        -DSTP_CPU=cortex-m0plus -DSTP_FW_COMPILE_TOOL="$stipple" -DSTP_FW_SCENE="$scene" \
        -DSTP_FW_BAND_ROWS=4 -DSTP_FW_LTO=$lto "-DSTP_FW_COMPILE_OPTIONS=--hidden;none;--backface" \
        >"$b.log" 2>&1
    cmake --build "$b" -j2 --target stipple_fw_lm3s6965evb >>"$b.log" 2>&1
done
arm-none-eabi-size "$work/lto-ON/stipple_fw_lm3s6965evb.elf" | tail -1 |
    awk '{print "whole image, LTO: .text " $1 " B, RAM " $2 + $3 " B"}'
# map lines: " .text.NAME  0xADDR  0xSIZE  FILE" (the section name may sit
# on a line of its own when long)
python3 - "$work/lto-OFF/stipple_fw_lm3s6965evb.elf.map" <<'PY'
import collections, re, sys
lines = open(sys.argv[1]).read().split("\n")
start = next(i for i, l in enumerate(lines) if l.startswith("Linker script and memory map"))
core, libgcc, pending = collections.Counter(), 0, False
for line in lines[start:]:
    if re.match(r"^ \.(text|rodata)\S*$", line):
        pending = True
        continue
    m = re.match(r"^ (\.(?:text|rodata)\S*)?\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+)", line)
    if m and (m.group(1) or pending):
        size, path = int(m.group(2), 16), m.group(3)
        if "libstipple_core_scene" in path:
            core[re.sub(r".*\((.*)\.obj\)", r"\1", path)] += size
        elif "libgcc" in path:
            libgcc += size
    pending = False
parts = ", ".join(f"{k} {v}" for k, v in core.most_common())
print(f"core without LTO: {sum(core.values())} B ({parts}); libgcc: {libgcc} B")
PY
