#!/bin/sh
# SPDX-License-Identifier: MIT
# An example of the Arduino library, as a user builds it: the release
# archive made by scripts/arduino_library.sh and unzipped, the example built
# by Debian's arduino-builder for the board FQBN, run in simavr (MCU at
# 16 MHz) with an SSD1306 on BUS (spi: CS 10, DC 9, RES 8 as the example
# wires them; i2c: address 0x3C), and the panel compared pixel for pixel
# with the host's picture made by REFERENCE (spin_reference MODEL: the same
# frame drawn by the host core; or a `stipple render ...` command line).
# Prints the builder's flash and RAM figures (and fails over the flash
# budget STP_FLASH_BUDGET, bytes of the test's build, or
# STP_FLASH_NET_BUDGET, bytes as the IDE builds the sketch net of an
# empty sketch, when the environment sets them), the peak
# RAM with the stack and the cycles of each frame with the bus left out (simavr's SPI takes
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
# where a budget is set: the flash as the IDE builds the sketch (no
# simulator markers), and an empty sketch's (setup and loop only: the
# Arduino core's start-up and timer) built the same way, for the figure
# net of it (two more builds: only for the budgeted tests, for CI's time)
build_flash() { # SKETCH OUT_DIR: prints the builder's flash figure
    arduino-builder -compile -hardware "$hw" -hardware /usr/share/arduino-builder \
        -tools /usr/share/arduino-builder -libraries "$work/libraries" -fqbn "$fqbn" \
        -build-path "$2" "-prefs=compiler.cpp.extra_flags=-DDECIMAL_DIG=17" "$1" >"$2.log" 2>&1 ||
        { cat "$2.log"; echo "FAIL: arduino-builder $fqbn $1" >&2; return 1; }
    sed -n 's/^Sketch uses \([0-9]*\) bytes.*/\1/p' "$2.log"
}
rm -rf "$work/ide" "$work/empty"
net=
if [ -n "${STP_FLASH_BUDGET:-}${STP_FLASH_NET_BUDGET:-}" ]; then
    mkdir -p "$work/ide" "$work/empty/Empty" "$work/empty/out"
    printf 'void setup() {}\nvoid loop() {}\n' >"$work/empty/Empty/Empty.ino"
    ide_flash=$(build_flash "$work/libraries/Stipple/examples/$example/$example.ino" "$work/ide")
    empty_flash=$(build_flash "$work/empty/Empty/Empty.ino" "$work/empty/out")
    net=" ($ide_flash B as the IDE builds it, $((ide_flash - empty_flash)) B net of an empty sketch's $empty_flash B)"
fi
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
"$sim" -m "$mcu" -b "$bus" -p "$pins" -s "$heap" "$elf" "$work/panel.pbm" "$work/host.pbm" \
    >"$work/sim.log" 2>&1 || { cat "$work/sim.log"; echo "FAIL: $example ($fqbn, $bus) in simavr"; exit 1; }
cat "$work/sim.log"
# one line for CI's log (scripts/test.sh prints these)
flash=$(sed -n 's/^Sketch uses \([0-9]*\) bytes.*/\1/p' "$work/build.log")
peak=$(sed -n 's/^RAM: \([0-9]*\) static.*, \([0-9]*\) at the peak.*/\1 B static, \2 B peak/p' "$work/sim.log")
cycles=$(sed -n 's/^compute cycles per frame (bus left out): \(.*\)/, compute cycles a frame without the bus: \1/p' "$work/sim.log")
# frames a second at 16 MHz: the worst frame's cycles without the bus plus
# the transfer computed for a real part (SPI at f/2: 16 cycles a byte, 8
# pages of 128 data and 3 command bytes; I2C at 400 kHz: per page one
# transmission of 3 commands and 5 of up to 31 data bytes, 9 bits a byte
# and 2 for START and STOP: 1 299 bits, 8 pages, 40 cycles a bit)
worst=$(sed -n 's/^compute cycles per frame (bus left out): mean [0-9]*, max \([0-9]*\)/\1/p' "$work/sim.log")
fps=
if [ -n "$worst" ] && [ "$example" != StaticScene ]; then
    case $bus in
        spi) transfer=$((8 * (128 + 3) * 16)) ;;
        i2c) transfer=$((8 * 1299 * 40)) ;;
    esac
    fps=$(awk -v w="$worst" -v t="$transfer" 'BEGIN { printf "; %.1f frames/s at 16 MHz (worst frame + %d transfer cycles)", 16e6 / (w + t), t }')
fi
echo "FIGURES $example $fqbn $bus: flash $flash B$net, RAM $peak$cycles$fps; panel equals the host's picture"
# a flash budget (STP_FLASH_BUDGET, bytes: the test's environment) is a
# figure the project has promised (docs/arduino.md), not a timing
if [ -n "${STP_FLASH_BUDGET:-}" ] && [ "$flash" -gt "$STP_FLASH_BUDGET" ]; then
    echo "FAIL: $example ($fqbn) takes $flash B of flash, over its budget of $STP_FLASH_BUDGET B"
    exit 1
fi
# the same net of an empty sketch, as the IDE builds it (STP_FLASH_NET_BUDGET)
if [ -n "${STP_FLASH_NET_BUDGET:-}" ] && [ "$((ide_flash - empty_flash))" -gt "$STP_FLASH_NET_BUDGET" ]; then
    echo "FAIL: $example ($fqbn) takes $((ide_flash - empty_flash)) B of flash net of an empty sketch, over its budget of $STP_FLASH_NET_BUDGET B"
    exit 1
fi
echo "PASS: $example ($fqbn, $bus) draws on the simulated panel what the host draws"
