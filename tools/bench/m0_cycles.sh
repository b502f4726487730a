#!/bin/sh
# SPDX-License-Identifier: MIT
# Cortex-M0+ cycle estimate of an mps2-an385 firmware's measured window
# (t0 .. t2: the last three calls of stp_count_now): runs the ELF again in
# QEMU with a one-instruction-per-block execution trace and feeds it to
# m0_cycles.py, which prices each executed instruction by the Cortex-M0+
# TRM's timings (its docstring gives the model).  Prints the window's
# instructions, estimated cycles and frames per second at 48 MHz; checks
# the trace's instruction count against the firmware's own SysTick count
# (EXPECTED, optional) within 256 (the firmware counts in SysTick ticks of
# 40 instructions, and each count's own call sits at an edge of the
# window), so a wrong window cannot pass silently.
#
# usage: [STP_M0_PROFILE=N] m0_cycles.sh ELF [EXPECTED_INSTRUCTIONS]
#   STP_M0_PROFILE=N  also print the N functions with the most cycles
#                     in the window (self cost)
# Takes ~30 s and no disk: the trace (~11 M lines) is streamed.
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
set -eu
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: $0 ELF [EXPECTED_INSTRUCTIONS]" >&2; exit 2; }
for tool in qemu-system-arm arm-none-eabi-objdump python3; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp)
trap 'rm -f "$out"' EXIT
timeout -k 5 "${STP_QEMU_TIMEOUT:-300}" qemu-system-arm -M mps2-an385 -kernel "$1" \
    -display none -serial null -monitor none -semihosting-config enable=on,target=native \
    -icount shift=0 -singlestep -d exec,nochain -D /dev/stdout 2>/dev/null |
    python3 "$here/m0_cycles.py" ${STP_M0_PROFILE:+--profile "$STP_M0_PROFILE"} "$1" >"$out"
cat "$out"
if [ $# -eq 2 ]; then
    got=$(sed -n 's/^m0_cycles: instructions in the window \([0-9]*\)$/\1/p' "$out")
    [ -n "$got" ] || { echo "FAIL: no instruction count from the trace" >&2; exit 1; }
    diff=$((got - $2))
    [ "$diff" -lt 0 ] && diff=$((-diff))
    if [ "$diff" -gt 256 ]; then
        echo "FAIL: the trace counts $got instructions in the window, the firmware $2" >&2
        exit 1
    fi
    echo "PASS: the trace's window agrees with the firmware's count ($got against $2)"
fi
