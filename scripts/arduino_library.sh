#!/bin/sh
# SPDX-License-Identifier: MIT
# Assemble the Arduino library from the tree: OUT_DIR/Stipple in the layout
# the Arduino builder expects (library.properties, src/, examples/), with
# SCENE compiled for the example sketch and its configuration as the
# library's src/stipple_config.h.  Zip OUT_DIR/Stipple and add it in the IDE
# (Sketch > Include Library > Add .ZIP Library).
#
# arduino_library.sh OUT_DIR STIPPLE SCENE
#   STIPPLE  the host stipple command (build/tools/stipple)
set -eu
if [ $# -ne 3 ]; then
    echo "usage: $0 OUT_DIR STIPPLE SCENE" >&2
    exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
lib="$1/Stipple"
stipple=$2
scene=$3
rm -rf "$lib"
mkdir -p "$lib/src/stipple" "$lib/src/core" "$lib/examples"
cp "$root/ports/arduino/library.properties" "$root/LICENSE" "$lib/"
cp "$root"/ports/arduino/src/* "$lib/src/"
cp -r "$root/ports/arduino/examples/StippleScene" "$lib/examples/"
cp "$root"/include/stipple/*.h "$lib/src/stipple/"
cp "$root"/src/*.c "$root"/src/*.h "$lib/src/core/"
cp "$root/ports/controllers/stp_panel.h" "$root/ports/controllers/panel.c" \
   "$root/ports/controllers/panel_pages.c" \
   "$root/ports/controllers/ssd1306.c" "$lib/src/"
cp "$root/ports/compiled/stp_scene_data.h" "$root/ports/compiled/scene_data.c" "$lib/src/"
"$stipple" compile "$scene" -s 128x64 -o "$lib/examples/StippleScene/scene.c" \
    --header "$lib/src/stipple_config.h"
echo "$lib"
