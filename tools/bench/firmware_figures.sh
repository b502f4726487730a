#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instruction counts of the lm3s6965evb firmware (issue 7 item 5), for the
# Cortex-M columns of the benchmark (issue 3).
#
# Builds and runs the firmware for each scene and CPU through
# tests/firmware/run_qemu_test.sh (so every figure comes from a run whose
# picture matched the host render), under QEMU -icount shift=0: emulated
# instructions, the same on every run.  Collects each run's figures.csv into
# one CSV:
#   board,cpu,scene,config,instr_per_shade,instr_enter,instr_frame,
#   instr_frame_with_transfer,options
# config: "minimal" (the scene's compiled configuration) or "full" (the
# library's defaults), two images of the same firmware.  Cortex-M0+ images
# run on QEMU's Cortex-M3 (ARMv6-M code is ARMv7-M code).
#
# usage: firmware_figures.sh [--build DIR] [--work DIR] [--out FILE] [--scenes DIR]
#                            [--stipple EXE] [--compare EXE]
#   --build DIR    the host build (default ./build): EXE defaults below
#   --work DIR     where the firmware is built and run (default BUILD/firmware-figures)
#   --out FILE     the CSV (default WORK/firmware.csv)
#   --scenes DIR   the shared NFF scenes (default $STP_SCENES_DIR, else
#                  tests/data/spd)
#   --stipple EXE  host stipple (default BUILD/tools/stipple)
#   --compare EXE  compare_screendump (default BUILD/tests/firmware/compare_screendump)
# Environment: STP_FW_FIGURE_SCENES (default "teapot-s1 tetra-s1"),
# STP_FW_FIGURE_CPUS (default "cortex-m0plus cortex-m3"), and
# run_qemu_test.sh's STP_QEMU_TIMEOUT, STP_BUILD_TIMEOUT, STP_FW_BAND_ROWS.
# Exit status: 0 when every run passed, 1 otherwise (a run whose tools are
# missing counts as failed here: there is no figure to report).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
build=build
work=""
out=""
scenes=${STP_SCENES_DIR:-$src/tests/data/spd}
stipple=""
compare=""
while [ $# -gt 0 ]; do
    case $1 in
    --build) build=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    --stipple) stipple=$2; shift 2 ;;
    --compare) compare=$2; shift 2 ;;
    -h|--help) sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "firmware_figures.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
work=${work:-$build/firmware-figures}
out=${out:-$work/firmware.csv}
stipple=${stipple:-$build/tools/stipple}
compare=${compare:-$build/tests/firmware/compare_screendump}
for exe in "$stipple" "$compare"; do
    [ -x "$exe" ] || { echo "firmware_figures.sh: $exe not found (build the host first:" \
                            "cmake --build $build)" >&2; exit 1; }
done
# run_qemu_test.sh runs from its own work folders: give it absolute paths
abs() { (cd "$(dirname "$1")" && echo "$(pwd)/$(basename "$1")"); }
stipple=$(abs "$stipple")
compare=$(abs "$compare")
scenes=$(cd "$scenes" && pwd)
mkdir -p "$work" "$(dirname "$out")"
work=$(cd "$work" && pwd)

tmp=$out.tmp
echo "board,cpu,scene,config,instr_per_shade,instr_enter,instr_frame,instr_frame_with_transfer,options" \
    >"$tmp"
status=0
for scene in ${STP_FW_FIGURE_SCENES:-teapot-s1 tetra-s1}; do
    for cpu in ${STP_FW_FIGURE_CPUS:-cortex-m0plus cortex-m3}; do
        dir=$work/$scene-$cpu
        echo "== $scene on $cpu (log: $dir.log)" >&2
        rm -f "$dir/figures.csv"
        rc=0
        STP_FW_CPU=$cpu "$src/tests/firmware/run_qemu_test.sh" --board lm3s6965evb "$src" "$dir" \
            "$stipple" "$stipple" "$compare" "$scenes/$scene.nff" >"$dir.log" 2>&1 || rc=$?
        if [ "$rc" -ne 0 ]; then
            echo "firmware_figures.sh: $scene on $cpu failed ($rc; 77: tools missing), see $dir.log" >&2
            status=1
        fi
        # the rows of the images that passed
        if [ -f "$dir/figures.csv" ]; then
            tail -n +2 "$dir/figures.csv" >>"$tmp"
        fi
    done
done
mv "$tmp" "$out"
echo "wrote $out" >&2
exit $status
