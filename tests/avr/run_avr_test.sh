#!/bin/sh
# SPDX-License-Identifier: MIT
# The core on an 8-bit AVR (16-bit int): build the ATmega2560 firmware for
# SCENE with avr-gcc (-Werror; the scene's minimal configuration and the full
# core library), run it under simavr with an SSD1306 on its SPI
# (avr_ssd1306_sim), and compare the panel pixel for pixel with
# `stipple render SCENE -s 128x64`.
#
# run_avr_test.sh SOURCE_DIR WORK_DIR STIPPLE SIM SCENE
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
# Environment: STP_FW_BAND_ROWS (4; the firmware rounds it up to whole 8-row
# pages), STP_BUILD_TIMEOUT (600 s).
set -eu
if [ $# -ne 5 ]; then
    echo "usage: $0 SOURCE_DIR WORK_DIR STIPPLE SIM SCENE" >&2
    exit 2
fi
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
stipple=$3
sim=$4
scene=$5
for tool in avr-gcc avr-size cmake; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "skipped: $tool not installed (Debian: gcc-avr avr-libc binutils-avr)"
        exit 77
    fi
done
if [ ! -x "$sim" ]; then
    echo "skipped: $sim not built (Debian: simavr libsimavr-dev)"
    exit 77
fi
name=$(basename "$scene" .nff)
build="$work/build-$name"
timeout "${STP_BUILD_TIMEOUT:-600}" cmake -S "$src/firmware" -B "$build" \
    -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-avr.cmake" -DSTP_FW_BOARD=atmega2560 \
    -DSTP_FW_COMPILE_TOOL="$stipple" -DSTP_FW_SCENE="$scene" \
    -DSTP_FW_BAND_ROWS="${STP_FW_BAND_ROWS:-4}" >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log"; echo "FAIL: configure"; exit 1; }
timeout "${STP_BUILD_TIMEOUT:-600}" cmake --build "$build" -j2 >"$work/build.log" 2>&1 ||
    { cat "$work/build.log"; echo "FAIL: avr-gcc build"; exit 1; }
avr-size "$build/stipple_fw_atmega2560.elf"
"$stipple" render "$scene" -s 128x64 -d bayer4 -l 16 --exposure off -o "$work/host.pbm"
"$sim" "$build/stipple_fw_atmega2560.elf" "$work/avr.pbm" "$work/host.pbm"
echo "PASS: $name on the ATmega2560 equals the host render"
