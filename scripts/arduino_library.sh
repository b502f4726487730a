#!/bin/sh
# SPDX-License-Identifier: MIT
# Make the Arduino library's release archive from the tree, with nothing
# built first: OUT_DIR/Stipple (the folder, in the Arduino library layout
# of specification 1.5: library.properties, library.json for PlatformIO,
# src/, examples/) and OUT_DIR/Stipple-VERSION.zip (Sketch > Include
# Library > Add .ZIP Library in the IDE; unzip into ~/Arduino/libraries;
# or a PlatformIO lib_deps entry).  The examples' meshes and span picture
# are generated files kept in the tree (tests/avr/check_arduino_generated.sh
# checks they are what `stipple compile` writes today).
#
# arduino_library.sh OUT_DIR     prints the archive's path
set -eu
if [ $# -ne 1 ]; then
    echo "usage: $0 OUT_DIR" >&2
    exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$1"
out=$(cd "$1" && pwd)
lib="$out/Stipple"
v=$(sed -n 's/^#define STP_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$/\2/p' "$root/include/stipple/version.h" |
    tr '\n' . | sed 's/\.$//')
case $v in
    *.*.*) ;;
    *) echo "$0: no version in include/stipple/version.h" >&2; exit 1 ;;
esac
rm -rf "$lib" "$out/Stipple-$v.zip"
mkdir -p "$lib/src/stipple" "$lib/src/core" "$lib/examples"
sed "s/@VERSION@/$v/" "$root/ports/arduino/library.properties" >"$lib/library.properties"
sed "s/@VERSION@/$v/" "$root/ports/arduino/library.json" >"$lib/library.json"
cp "$root/LICENSE" "$lib/"
cp "$root/docs/arduino.md" "$lib/README.md"
cp "$root"/ports/arduino/src/* "$lib/src/"
cp "$root"/include/stipple/*.h "$lib/src/stipple/"
cp "$root"/src/*.c "$root"/src/*.h "$lib/src/core/"
# the examples' spin reads the core's private stp_direct_lit: beside it
mv "$lib/src/stipple_spin.c" "$lib/src/core/"
cp "$root/ports/controllers/stp_panel.h" "$root/ports/controllers/panel.c" \
   "$root/ports/controllers/ssd1306.c" "$lib/src/"
cp -r "$root"/ports/arduino/examples/* "$lib/examples/"
# a fixed order and date, so one tree gives one archive
find "$lib" -exec touch -d "2000-01-01 00:00:00 UTC" {} +
(cd "$out" && find Stipple | LC_ALL=C sort | zip -q -X -@ "Stipple-$v.zip")
echo "$out/Stipple-$v.zip"
