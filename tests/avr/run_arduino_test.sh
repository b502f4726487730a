#!/bin/sh
# SPDX-License-Identifier: MIT
# The Arduino library: assemble it (scripts/arduino_library.sh) with SCENE
# in its example sketch, build the sketch for the Mega 2560 against Debian's
# arduino-core-avr the way arduino-builder would (its platform.txt recipes:
# the same flags, LTO, the core as an archive), run the image under simavr
# with an SSD1306 (avr_ssd1306_sim) and compare the panel pixel for pixel
# with `stipple render SCENE -s 128x64`.
#
# Debian 12's arduino-core-avr does not compile with its gcc-avr 5.4
# (WString.cpp: "size of array 'buf' is not an integral constant-
# expression"), so arduino-builder cannot be used as is: the core is
# compiled here with WString.cpp left out.
#
# run_arduino_test.sh SOURCE_DIR WORK_DIR STIPPLE SIM SCENE
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
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
hw=/usr/share/arduino/hardware/arduino/avr
for tool in avr-gcc avr-g++ avr-gcc-ar avr-size; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "skipped: $tool not installed (Debian: gcc-avr avr-libc binutils-avr)"
        exit 77
    fi
done
if [ ! -f "$hw/platform.txt" ]; then
    echo "skipped: $hw missing (Debian: arduino-core-avr)"
    exit 77
fi
if [ ! -x "$sim" ]; then
    echo "skipped: $sim not built (Debian: simavr libsimavr-dev)"
    exit 77
fi

lib=$("$src/scripts/arduino_library.sh" "$work/libraries" "$stipple" "$scene")
sketch="$lib/examples/StippleScene"
out="$work/out"
rm -rf "$out"
mkdir -p "$out/core" "$out/lib" "$out/sketch"

# platform.txt: compiler.c.flags, compiler.cpp.flags, compiler.S.flags (warnings "default":
# none added), -mmcu={build.mcu} -DF_CPU={build.f_cpu} -DARDUINO=... for
# board mega, cpu atmega2560
defs="-mmcu=atmega2560 -DF_CPU=16000000L -DARDUINO=10819 -DARDUINO_AVR_MEGA2560 -DARDUINO_ARCH_AVR"
cflags="-c -g -Os -std=gnu11 -ffunction-sections -fdata-sections -MMD -flto -fno-fat-lto-objects $defs"
cxxflags="-c -g -Os -std=gnu++11 -fpermissive -fno-exceptions -ffunction-sections -fdata-sections -fno-threadsafe-statics -Wno-error=narrowing -MMD -flto $defs"
includes="-I$hw/cores/arduino -I$hw/variants/mega -I$hw/libraries/SPI/src -I$lib/src"

sflags="-c -g -x assembler-with-cpp -flto -MMD $defs"
cc() { avr-gcc $cflags $includes "$1" -o "$2"; }
as() { avr-gcc $sflags $includes "$1" -o "$2"; }
cxx() { avr-g++ $cxxflags $includes "$1" -o "$2"; }

# the sketch: arduino-builder's preprocessing of a .ino is Arduino.h first
{
    echo '#include <Arduino.h>'
    echo "#line 1 \"$sketch/StippleScene.ino\""
    cat "$sketch/StippleScene.ino"
} >"$out/sketch/StippleScene.ino.cpp"
objects=
cxx "$out/sketch/StippleScene.ino.cpp" "$out/sketch/StippleScene.ino.cpp.o"
cc "$sketch/scene.c" "$out/sketch/scene.c.o"
objects="$out/sketch/StippleScene.ino.cpp.o $out/sketch/scene.c.o"
# the libraries: every source under src/, recursively
for f in $(cd "$lib/src" && find . -name '*.c' -o -name '*.cpp' | sort); do
    o="$out/lib/$(echo "$f" | tr / _).o"
    case $f in
        *.c) cc "$lib/src/$f" "$o" ;;
        *.cpp) cxx "$lib/src/$f" "$o" ;;
    esac
    objects="$objects $o"
done
cxx "$hw/libraries/SPI/src/SPI.cpp" "$out/lib/SPI.cpp.o"
objects="$objects $out/lib/SPI.cpp.o"
# the core, as core.a: every file of it but WString.cpp (which does not
# compile, see above); the linker takes from the archive what is called
for f in $(cd "$hw/cores/arduino" && ls *.c *.cpp *.S); do
    case $f in
        WString.cpp) continue ;;
        *.c) cc "$hw/cores/arduino/$f" "$out/core/$f.o" ;;
        *.S) as "$hw/cores/arduino/$f" "$out/core/$f.o" ;;
        *.cpp) cxx "$hw/cores/arduino/$f" "$out/core/$f.o" ;;
    esac
    avr-gcc-ar rcs "$out/core/core.a" "$out/core/$f.o"
done
# recipe.c.combine.pattern
avr-gcc -Os -g -flto -fuse-linker-plugin -Wl,--gc-sections -mmcu=atmega2560 \
    -o "$out/StippleScene.ino.elf" $objects "$out/core/core.a" "-L$out" -lm
avr-size "$out/StippleScene.ino.elf"
"$stipple" render "$scene" -s 128x64 -d bayer4 -l 16 --exposure off -o "$work/host.pbm"
"$sim" "$out/StippleScene.ino.elf" "$work/arduino.pbm" "$work/host.pbm"
echo "PASS: the Arduino sketch draws $(basename "$scene" .nff) as the host renders it"
