#!/bin/sh
# SPDX-License-Identifier: MIT
# RISC-V check: the core and a compiled scene cross-compiled for rv32imac
# with the firmware project's own checks (no soft float, no C library,
# warnings are errors) and linked into firmware/rv32's image.
#
# build_rv32.sh SOURCE_DIR WORK_DIR COMPILE_TOOL SCENE
# Exit status: 0 pass, 1 fail, 77 riscv64-unknown-elf-gcc missing (skipped).
set -eu
if [ $# -ne 4 ]; then
    echo "usage: $0 SOURCE_DIR WORK_DIR COMPILE_TOOL SCENE" >&2
    exit 2
fi
command -v riscv64-unknown-elf-gcc >/dev/null 2>&1 ||
    { echo "$0: riscv64-unknown-elf-gcc not found: skipped" >&2; exit 77; }
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
timeout=${STP_BUILD_TIMEOUT:-600}
timeout "$timeout" cmake -S "$src/firmware" -B "$work/fw-rv32" \
    -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-riscv32-elf.cmake" \
    -DSTP_FW_COMPILE_TOOL="$3" -DSTP_FW_SCENE="$4" >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; exit 1; }
timeout "$timeout" cmake --build "$work/fw-rv32" >"$work/build.log" 2>&1 ||
    { cat "$work/build.log" >&2; exit 1; }
riscv64-unknown-elf-size "$work/fw-rv32/stipple_fw_rv32.elf" "$work/fw-rv32/stipple_fw_rv32_full.elf"
