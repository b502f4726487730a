#!/bin/sh
# SPDX-License-Identifier: MIT
# An example of the Arduino library, as a user builds it: the release
# archive made by scripts/arduino_library.sh and unzipped, the example built
# by Debian's arduino-builder for the board FQBN, run in simavr (MCU at
# 16 MHz) with an SSD1306 on BUS (spi: CS 10, DC 9, RES 8 as the example
# wires them; i2c: address 0x3C), and the panel compared pixel for pixel
# with the host's picture made by REFERENCE (spin_reference MODEL: the same
# frame drawn by the host core; or a `stipple render ...` command line).
# Prints the builder's flash and RAM figures, the peak RAM with the stack
# and the cycles of each frame with the bus left out (simavr's SPI takes
# ~1600 cycles a byte, a real one 16 at f/2: add the real transfer time).
#
# Debian 12's arduino-core-avr does not build with its gcc-avr 5.4
# (WString.cpp: DECIMAL_DIG undeclared); the one preference
# compiler.cpp.extra_flags=-DDECIMAL_DIG=17 makes arduino-builder build the
# core as it is.  STIPPLE_SIM_FRAMES (ports/arduino/src/stipple_sim.h)
# stops the sketch after its frames, for the simulator.
#
# run_arduino_test.sh SOURCE_DIR WORK_DIR SIM EXAMPLE FQBN MCU BUS REFERENCE...
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
set -eu
if [ $# -lt 8 ]; then
    echo "usage: $0 SOURCE_DIR WORK_DIR SIM EXAMPLE FQBN MCU BUS REFERENCE..." >&2
    exit 2
fi
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
sim=$3 example=$4 fqbn=$5 mcu=$6 bus=$7
shift 7
for tool in arduino-builder avr-nm unzip; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "skipped: $tool not installed (Debian: arduino-builder gcc-avr binutils-avr unzip)"
        exit 77
    fi
done
hw=/usr/share/arduino/hardware
if [ ! -f "$hw/arduino/avr/platform.txt" ]; then
    echo "skipped: $hw/arduino/avr missing (Debian: arduino-core-avr)"
    exit 77
fi
if [ ! -x "$sim" ]; then
    echo "skipped: $sim not built (Debian: simavr libsimavr-dev)"
    exit 77
fi

# the release archive, unzipped where the IDE would put it
rm -rf "$work/dist" "$work/libraries" "$work/out"
zip=$("$src/scripts/arduino_library.sh" "$work/dist")
mkdir -p "$work/libraries" "$work/out"
unzip -q "$zip" -d "$work/libraries"

case $example in
    StaticScene) frames=1 ;;
    *) frames=8 ;;
esac
arduino-builder -compile -hardware "$hw" -hardware /usr/share/arduino-builder \
    -tools /usr/share/arduino-builder -libraries "$work/libraries" -fqbn "$fqbn" \
    -build-path "$work/out" \
    "-prefs=compiler.cpp.extra_flags=-DDECIMAL_DIG=17 -DSTIPPLE_SIM_FRAMES=$frames" \
    "$work/libraries/Stipple/examples/$example/$example.ino" >"$work/build.log" 2>&1 ||
    { cat "$work/build.log"; echo "FAIL: arduino-builder $fqbn $example"; exit 1; }
grep -E "^(Sketch uses|Global variables)" "$work/build.log"
elf="$work/out/$example.ino.elf"
avr-size "$elf"
heap=$(avr-nm "$elf" | sed -n 's/^\([0-9a-f]*\) . __bss_end$/0x\1/p')

case $mcu in
    atmega328p) pins=B2,B1,B0 ;;  # Uno, Nano: 10, 9, 8
    atmega2560) pins=B4,H6,H5 ;;  # Mega: 10, 9, 8
    *) echo "$0: no pins for $mcu" >&2; exit 2 ;;
esac
case $(basename "$1") in
    spin_reference) "$@" "$((frames - 1))" "$work/host.pbm" ;;
    *) "$@" -o "$work/host.pbm" ;;
esac
"$sim" -m "$mcu" -b "$bus" -p "$pins" -s "$heap" "$elf" "$work/panel.pbm" "$work/host.pbm"
echo "PASS: $example ($fqbn, $bus) draws on the simulated panel what the host draws"
