#!/bin/sh
# SPDX-License-Identifier: MIT
# Code size of a minimal moving configuration (issue 15 item 3): a spinning
# mesh entered by stp_renderer_mesh, flat, one light, ambient + diffuse, no
# fallback, 1-bit output (tools/bench/mesh_min_size.c), linked for a
# Cortex-M0+ (arm-none-eabi-gcc -Os, section garbage collection); prints
# the linked code and constant data per core object and the core's total.
#
# usage: mesh_min_size.sh SOURCE_DIR WORK_DIR
set -eu
[ $# -eq 2 ] || { echo "usage: $0 SOURCE_DIR WORK_DIR" >&2; exit 2; }
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
defs="-DSTP_WITH_MESH_FALLBACK=0 -DSTP_WITH_SPECULAR=0 -DSTP_WITH_GOURAUD=0 -DSTP_WITH_COLOUR=0
 -DSTP_WITH_TRANSPARENCY=0 -DSTP_WITH_SHADOWS=0 -DSTP_WITH_LINES=0 -DSTP_WITH_RAYTRACE=0
 -DSTP_WITH_EDGE_AA=0 -DSTP_WITH_DIFFUSION=0 -DSTP_WITH_DEFAULT_CELL=0 -DSTP_WITH_PAINTER=0
 -DSTP_WITH_TRIANGLE_PATH=0 -DSTP_SMALL_DIVISION=1 -DSTP_VERTEX_CACHE=0 -DSTP_MAX_LIGHTS=1
 -DSTP_MAX_SEGMENTS=1 -DSTP_MAX_POLYGON_VERTICES=8"
cflags="-std=c99 -mcpu=cortex-m0plus -mthumb -Os -ffunction-sections -fdata-sections"
rm -f "$work"/*.o "$work/core.a"
for f in "$src"/src/*.c; do
    # shellcheck disable=SC2086 # word lists
    arm-none-eabi-gcc $cflags $defs -I "$src/include" -I "$src/src" -c "$f" \
        -o "$work/$(basename "$f" .c).o"
done
arm-none-eabi-ar rcs "$work/core.a" "$work"/*.o
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $defs -I "$src/include" -c "$src/tools/bench/mesh_min_size.c" -o "$work/main.o.x"
arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -Os -Wl,--gc-sections -specs=nosys.specs -nostartfiles \
    -Wl,-e,main "$work/main.o.x" "$work/core.a" -lgcc -Wl,-Map="$work/out.map" -o "$work/out.elf"
# the kept .text/.rodata input sections of each archive member (a long
# section name puts its address and size on the next line)
python3 - "$work/out.map" <<'PY'
import collections, re, sys
text = open(sys.argv[1]).read()
text = text[text.index('Linker script and memory map'):]
sizes = collections.Counter()
for m in re.finditer(r'^ \.(?:text|rodata)\S*\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+)$', text, re.M):
    sizes[m.group(2).rsplit('/', 1)[-1]] += int(m.group(1), 16)
for name, size in sorted(sizes.items(), key=lambda kv: -kv[1]):
    if size:
        print('%7d %s' % (size, name))
core = sum(v for k, v in sizes.items() if k.startswith('core.a'))
gcc = sum(v for k, v in sizes.items() if k.startswith('libgcc'))
print('core (src/) code and constants: %d bytes; libgcc: %d bytes' % (core, gcc))
PY
