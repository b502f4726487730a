#!/bin/sh
# SPDX-License-Identifier: MIT
# The Arduino examples' generated files are what `stipple compile` writes
# today from the models in ports/arduino/models and the SPD teapot: the
# release script (scripts/arduino_library.sh) copies them as they are, so a
# change of the compiler or of a model must come with them regenerated
# (the command lines are below, and in each file's first lines).
#
# check_arduino_generated.sh SOURCE_DIR WORK_DIR STIPPLE SCENES_DIR
set -eu
src=$1 work=$2 stipple=$3 scenes=$4
ex="$src/ports/arduino/examples"
mkdir -p "$work"
status=0
check() { # FILE, then the compile arguments
    file=$1
    shift
    "$stipple" compile "$@" -o "$work/out" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
    if ! cmp -s "$work/out" "$file"; then
        echo "FAIL: $file is not what 'stipple compile $*' writes:"
        diff "$file" "$work/out" | head -20
        status=1
    fi
}
for d in SpinningCube SpinningCubeSPI U8g2Cube; do
    check "$ex/$d/cube_mesh.h" "$src/ports/arduino/models/cube.obj" --mesh --name cube
done
check "$ex/SpinningTeapot/teapot_mesh.h" "$src/ports/arduino/models/teapot.nff" --mesh --name teapot
check "$ex/StaticScene/scene_spans.c" "$scenes/teapot-s1.nff" -s 128x64 -d bayer4 -l 16 \
    --exposure off --spans --header "$work/spans_config.h"
# refusals: a name that is not a C identifier, --mesh with --spans, a
# model of degenerate polygons only
refuse() { # WANT_STATUS, then the compile arguments
    want=$1
    shift
    got=0
    "$stipple" compile "$@" >"$work/log" 2>&1 || got=$?
    if [ "$got" -ne "$want" ] || [ ! -s "$work/log" ] || [ -e "$work/refused.h" ]; then
        echo "FAIL: 'stipple compile $*' exited $got (want $want, a message, no output):"
        cat "$work/log"
        status=1
    fi
}
rm -f "$work/refused.h"
refuse 1 "$src/ports/arduino/models/cube.obj" --mesh --name 9cube -o "$work/refused.h"
refuse 2 "$src/ports/arduino/models/cube.obj" --mesh --spans -o "$work/refused.h"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' >"$work/flat.obj"
refuse 1 "$work/flat.obj" --mesh -o "$work/refused.h"
[ $status -eq 0 ] && echo "PASS: the examples' meshes and spans are up to date"
exit $status
