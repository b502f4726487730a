#!/bin/sh
# SPDX-License-Identifier: MIT
# Direct drawing on a Cortex-M (issue 15 item 3): build the mps2-an385
# spinning-torus firmware (ports/mps2/main_direct.c), run it under QEMU
# -icount shift=0, print its instruction counts per frame, and check the
# frame it drew against the host's (tools/bench/direct_spin_host, the same
# integers) pixel for pixel.
#
# usage: mps2_direct.sh SOURCE_DIR WORK_DIR DIRECT_SPIN_HOST
# Environment: STP_FW_CPU (cortex-m0plus), STP_MPS2_OPT (-O2),
# STP_FW_BAND_ROWS (8), STP_FW_SORT (1: the faces sorted far to near,
# stp_direct_frame_sort; then DIRECT_SPIN_HOST is direct_spin_host_sorted),
# STP_FW_DEPTH (1: the Z buffer, stp_direct_frame_depth; then
# DIRECT_SPIN_HOST is direct_spin_host_depth),
# STP_FW_PLACE (1: the torus near the eye, cut by the near plane and the
# picture's edges, STP_SPIN_PLACE; then DIRECT_SPIN_HOST is
# direct_spin_host_near),
# STP_FW_CYCLES (1: also the Cortex-M0+ cycle
# estimate from an instruction trace, tools/bench/m0_cycles.sh),
# STP_QEMU_TIMEOUT (120), STP_BUILD_TIMEOUT (600).
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
set -eu
if [ $# -ne 3 ]; then
    echo "usage: $0 SOURCE_DIR WORK_DIR DIRECT_SPIN_HOST" >&2
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
band_rows=${STP_FW_BAND_ROWS:-8}
sort=${STP_FW_SORT:-0}
place=${STP_FW_PLACE:-0}
depth=${STP_FW_DEPTH:-0}
fw=$work/fw-$cpu$(printf %s "$opt" | tr -c 'A-Za-z0-9_-' _)-$band_rows-$sort-$place-$depth

echo "== building the mps2-an385 direct-drawing firmware ($cpu, $opt, $band_rows-row bands) in $fw"
timeout "${STP_BUILD_TIMEOUT:-600}" cmake -S "$src/ports/mps2" -B "$fw" \
    -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-arm-none-eabi.cmake" -DSTP_CPU="$cpu" \
    -DSTP_MPS2_OPT="$opt" -DSTP_FW_BAND_ROWS="$band_rows" -DSTP_FW_SORT="$sort" -DSTP_FW_PLACE="$place" \
    -DSTP_FW_DEPTH="$depth" \
    >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; exit 1; }
timeout "${STP_BUILD_TIMEOUT:-600}" cmake --build "$fw" --target stipple_mps2_direct >"$work/build.log" 2>&1 ||
    { cat "$work/build.log" >&2; exit 1; }

log=$work/qemu.log
echo "== running it"
timeout -k 5 "${STP_QEMU_TIMEOUT:-120}" qemu-system-arm -M mps2-an385 -kernel "$fw/stipple_mps2_direct.elf" \
    -display none -serial null -monitor none \
    -semihosting-config enable=on,target=native -icount shift=0 >"$log" 2>&1 ||
    { cat "$log" >&2; echo "FAIL: QEMU exited with $? (124: timed out)" >&2; exit 1; }
grep -v "^stipple: row\|^[0-9a-f]*\$" "$log" || true
grep -q "^stipple: instructions per direct frame [0-9]" "$log" ||
    { echo "FAIL: no instruction count reported" >&2; exit 1; }
if [ "${STP_FW_CYCLES:-0}" = 1 ]; then
    echo "== the cycle estimate from an instruction trace"
    sh "$src/tools/bench/m0_cycles.sh" "$fw/stipple_mps2_direct.elf" \
        "$(sed -n 's/^stipple: instructions per direct frame \([0-9]*\).*/\1/p' "$log")"
fi
frame=$(sed -n 's/^stipple: frame \([0-9]*\)$/\1/p' "$log")
{
    printf 'P4\n128 64\n'
    sed -n '/^stipple: row /{n;p}' "$log" | tr -d '\r\n' | sed 's/../\\x&/g' | xargs -0 printf '%b'
} >"$work/firmware.pbm"
"$host" -n "$frame" -b 64 -o "$work/host.pbm"
if cmp -s "$work/firmware.pbm" "$work/host.pbm"; then
    echo "PASS: the firmware's frame $frame equals the host's pixel for pixel"
else
    echo "FAIL: the firmware's frame ($work/firmware.pbm) differs from the host's ($work/host.pbm)" >&2
    exit 1
fi
