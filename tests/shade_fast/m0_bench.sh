#!/bin/sh
# SPDX-License-Identifier: MIT
# Cortex-M0+ instruction counts of the flat-face shading against the
# accurate path (tests/shade_fast/m0) under QEMU -icount shift=0, and a
# check that on ARMv6-M code the two paths' shades of its 64 faces stay
# within the host tests' tolerance (5e-4: 32 LSB at F = 16).
# usage: m0_bench.sh SOURCE_DIR WORK_DIR [-O2|-Os]
# Exit status: 0 done, 1 fail, 77 tools missing.
set -eu
for tool in qemu-system-arm arm-none-eabi-gcc; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
opt=${3:--O2}
cmake -S "$src/tests/shade_fast/m0" -B "$work/m0$opt" -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-arm-none-eabi.cmake" \
    -DSTP_CPU=cortex-m0plus -DSTP_M0_OPT="$opt" >"$work/configure.log" 2>&1 || { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/m0$opt" >"$work/build.log" 2>&1 || { cat "$work/build.log" >&2; exit 1; }
log=$work/qemu$opt.log
timeout -k 5 120 qemu-system-arm -M mps2-an385 -kernel "$work/m0$opt/shade_fast_m0.elf" -display none \
    -serial null -monitor none -semihosting-config enable=on,target=native -icount shift=0 >"$log" 2>&1 ||
    { cat "$log" >&2; echo "FAIL: QEMU exited with an error (124: timed out)" >&2; exit 1; }
cat "$log"
worst=$(sed -n 's/^stipple: worst |fast - accurate| in LSB \([0-9]*\).*/\1/p' "$log")
[ -n "$worst" ] || { echo "FAIL: no comparison reported" >&2; exit 1; }
if [ "$worst" -gt 32 ]; then
    echo "FAIL: the fast shade differs from stp_shade_unit by $worst LSB (> 32)" >&2
    exit 1
fi
echo "PASS: fast and accurate shades within $worst LSB on ARMv6-M"
