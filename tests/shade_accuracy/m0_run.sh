#!/bin/sh
# SPDX-License-Identifier: MIT
# The accuracy cases on the Cortex-M0+ (m0/, QEMU mps2-an385), their shades
# checked on the host against the double reference by test_shade_accuracy.
# usage: m0_run.sh SOURCE_DIR WORK_DIR CHECKER
# Exit status: 0 pass, 1 fail, 77 tools missing.
set -eu
for tool in qemu-system-arm arm-none-eabi-gcc; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
checker=$3
cmake -S "$src/tests/shade_accuracy/m0" -B "$work/build" -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-arm-none-eabi.cmake" \
    -DSTP_CPU=cortex-m0plus >"$work/configure.log" 2>&1 || { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/build" >"$work/build.log" 2>&1 || { cat "$work/build.log" >&2; exit 1; }
log=$work/qemu.log
timeout -k 5 600 qemu-system-arm -M mps2-an385 -kernel "$work/build/shade_accuracy_m0.elf" -display none \
    -serial null -monitor none -semihosting-config enable=on,target=native >"$log" 2>&1 ||
    { tail -5 "$log" >&2; echo "FAIL: QEMU exited with an error (124: timed out)" >&2; exit 1; }
exec "$checker" "$log"
