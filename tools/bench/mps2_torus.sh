#!/bin/sh
# SPDX-License-Identifier: MIT
# Cortex-M bench of issue 11: build the mps2-an385 torus firmware
# (ports/mps2), run it under QEMU -icount shift=0, print its instruction
# counts per 128x64 torus frame, and check the frame it rendered against the
# host's render of the same torus (tools/bench/torus_frame_host) pixel for
# pixel; the frames per second at 48 MHz the count gives.
#
# usage: mps2_torus.sh SOURCE_DIR WORK_DIR TORUS_FRAME_HOST
# Environment: STP_FW_CPU (cortex-m0plus: ARMv6-M code, which runs on the
# board's Cortex-M3 model), STP_MPS2_OPT (-O2), STP_FW_BAND_ROWS (64: the
# whole frame), STP_FW_KEEP_SETUP (1/0: lend the per-polygon setup array;
# default: with several bands), STP_FW_MESH (1: the torus entered as one
# mesh by stp_renderer_mesh, checked against torus_frame_host --mesh),
# STP_FW_CYCLES (1: also the Cortex-M0+ cycle estimate from an instruction
# trace, tools/bench/m0_cycles.sh, ~30 s more), STP_QEMU_TIMEOUT (seconds, 120), STP_BUILD_TIMEOUT (600).
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
set -eu
if [ $# -ne 3 ]; then
    echo "usage: $0 SOURCE_DIR WORK_DIR TORUS_FRAME_HOST" >&2
    exit 2
fi
for tool in qemu-system-arm arm-none-eabi-gcc; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
host=$3
cpu=${STP_FW_CPU:-cortex-m0plus}
opt=${STP_MPS2_OPT:--O2}
band_rows=${STP_FW_BAND_ROWS:-64}
keep=${STP_FW_KEEP_SETUP:-}
mesh=${STP_FW_MESH:-0}
# the options in the folder name without their separators (";" would end
# a CMake list there)
fw=$work/fw-$cpu$(printf %s "$opt" | tr -c 'A-Za-z0-9_-' _)-$band_rows${keep:+-keep$keep}-mesh$mesh

echo "== building the mps2-an385 torus firmware ($cpu, $opt, $band_rows-row bands) in $fw"
timeout "${STP_BUILD_TIMEOUT:-600}" cmake -S "$src/ports/mps2" -B "$fw" \
    -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-arm-none-eabi.cmake" -DSTP_CPU="$cpu" \
    -DSTP_MPS2_OPT="$opt" -DSTP_FW_BAND_ROWS="$band_rows" -DSTP_FW_KEEP_SETUP="$keep" -DSTP_FW_MESH="$mesh" \
    >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; exit 1; }
timeout "${STP_BUILD_TIMEOUT:-600}" cmake --build "$fw" >"$work/build.log" 2>&1 ||
    { cat "$work/build.log" >&2; exit 1; }

log=$work/qemu.log
echo "== running it"
timeout -k 5 "${STP_QEMU_TIMEOUT:-120}" qemu-system-arm -M mps2-an385 -kernel "$fw/stipple_mps2_torus.elf" \
    -display none -serial null -monitor none \
    -semihosting-config enable=on,target=native -icount shift=0 >"$log" 2>&1 ||
    { cat "$log" >&2; echo "FAIL: QEMU exited with $? (124: timed out)" >&2; exit 1; }
grep -v "^stipple: row\|^[0-9a-f]*\$" "$log" || true
grep -q "^stipple: instructions per torus frame [0-9]" "$log" ||
    { echo "FAIL: no instruction count reported" >&2; exit 1; }
# frames per second at 48 MHz, one instruction per cycle (an upper bound:
# a Cortex-M0+ takes 2 cycles for loads, stores and taken branches)
awk '/^stipple: instructions per torus frame [0-9]/ {
    printf "stipple: %d instructions per torus frame: %.1f frames/s at 48 MHz (1 instruction/cycle)\n", $6, 48e6 / $6 }' "$log"

if [ "${STP_FW_CYCLES:-0}" = 1 ]; then
    echo "== the cycle estimate from an instruction trace"
    sh "$src/tools/bench/m0_cycles.sh" "$fw/stipple_mps2_torus.elf" \
        "$(sed -n 's/^stipple: instructions per torus frame \([0-9]*\).*/\1/p' "$log")"
fi
# the frame: the hex line after each "stipple: row Y", as a binary PBM
{
    printf 'P4\n128 64\n'
    sed -n '/^stipple: row /{n;p}' "$log" | tr -d '\r\n' | sed 's/../\\x&/g' | xargs -0 printf '%b'
} >"$work/firmware.pbm"
if [ "$mesh" = 1 ]; then
    "$host" -s 128x64 --mesh -o "$work/host.pbm"
else
    "$host" -s 128x64 -o "$work/host.pbm"
fi
if cmp -s "$work/firmware.pbm" "$work/host.pbm"; then
    echo "PASS: the firmware's frame equals the host's pixel for pixel"
else
    echo "FAIL: the firmware's frame ($work/firmware.pbm) differs from the host's ($work/host.pbm)" >&2
    exit 1
fi
