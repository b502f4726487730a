#!/bin/sh
# SPDX-License-Identifier: MIT
# Code size of direct drawing (issue 15 item 3: a spinning model, flat, one
# light, ambient + diffuse, <= 6 KiB of core code) on a Cortex-M0+
# (arm-none-eabi-gcc -Os, section garbage collection):
#  1. the core alone: the spinning torus (ports/direct/direct_spin.c) and a
#     band loop linked without link-time optimisation, so each kept input
#     section is named in the link map: the kept .text/.rodata of each core
#     object (src/), of libgcc, and of the application;
#  2. the whole shipping image for the lm3s6965evb (ports/stellaris/
#     main_direct.c: the OLED driver, startup, the model built on the chip),
#     with link-time optimisation as the firmware build makes it:
#     arm-none-eabi-size, and the RAM of the band and the scratch.
#  3. with avr-gcc, the direct-drawing files on an ATmega328P per function
#     (the Arduino library's configuration, no LTO).
# The lean configuration: STP_WITH_SPECULAR=0 (the highlight's code out of
# shade_fast.c), STP_MAX_LIGHTS=1, STP_WITH_PAGES=0 (its SSD0323 panel takes
# rows: the page layout left out), STP_SMALL_DIVISION=1 (the edges' slopes
# by div64.c's loop: no C library division, no slope table).
#
# usage: firmware_lean_sizes.sh SOURCE_DIR WORK_DIR
set -eu
[ $# -eq 2 ] || { echo "usage: $0 SOURCE_DIR WORK_DIR" >&2; exit 2; }
command -v arm-none-eabi-gcc >/dev/null 2>&1 || { echo "$0: arm-none-eabi-gcc not found: skipped" >&2; exit 77; }
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
cpu="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft"
defs="-DSTP_WITH_SPECULAR=0 -DSTP_MAX_LIGHTS=1 -DSTP_WITH_PAGES=0 -DSTP_SMALL_DIVISION=1 -DSTP_DIRECT_COMPACT=1"
cflags="-std=c99 $cpu -Os -ffreestanding -ffunction-sections -fdata-sections -Wall -Wextra -Werror"
inc="-I $src/include -I $src/src -I $src/ports/direct -I $src/ports/stellaris -I $src/ports/controllers"
core="direct direct_band direct_view shade_fast shade view recip mesh fix div64"
rm -rf "$work/obj" && mkdir -p "$work/obj"

# ---- 1. the core alone, per object
for f in $core; do
    # shellcheck disable=SC2086 # word lists
    arm-none-eabi-gcc $cflags $defs $inc -c "$src/src/$f.c" -o "$work/obj/$f.o"
done
arm-none-eabi-ar rcs "$work/obj/core.a" "$work"/obj/*.o
cat >"$work/obj/min_main.c" <<'C'
/* SPDX-License-Identifier: MIT */
/* the spinning torus, every band handed to a sink the compiler cannot drop */
#include "direct_spin.h"
static direct_spin spin;
static uint8_t band[SPIN_STRIDE * 8u];
volatile uint8_t sink;
int main(void);
int main(void)
{
    stp_direct_frame f;
    uint16_t n, y;
    if (direct_spin_init(&spin) != STP_OK)
        return 1;
    for (n = 0;; n++) {
        if (direct_spin_frame(&spin, n, &f) != STP_OK)
            return 1;
        for (y = 0; y < SPIN_HEIGHT; y = (uint16_t)(y + 8u)) {
            if (stp_direct_draw_band(&f, band, SPIN_STRIDE, y, 8) != STP_OK)
                return 1;
            sink = band[y];
        }
    }
}
C
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $defs $inc -c "$work/obj/min_main.c" -o "$work/obj/min_main.x"
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $defs $inc -c "$src/ports/direct/direct_spin.c" -o "$work/obj/direct_spin.x"
# shellcheck disable=SC2086
arm-none-eabi-gcc $cpu -Os -nostdlib -nostartfiles -Wl,--gc-sections -Wl,-e,main \
    "$work/obj/min_main.x" "$work/obj/direct_spin.x" "$work/obj/core.a" -lgcc \
    -Wl,-Map="$work/min.map" -o "$work/min.elf"
echo "== core alone (no LTO; kept .text/.rodata per object, bytes)"
python3 - "$work/min.map" <<'PY'
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
print('core (src/) code and constants: %d bytes; libgcc: %d bytes; core + libgcc: %d of 6144' % (core, gcc, core + gcc))
PY

# ---- 2. the whole lm3s6965evb image, with LTO
st=$src/ports/stellaris
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $defs -fno-builtin -fno-tree-loop-distribute-patterns -c \
    "$src/ports/compiled/libc_min.c" -o "$work/obj/libc_min.x"
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $defs $inc -flto -nostdlib -Wl,--gc-sections -T "$st/lm3s6965.ld" -L "$st" \
    "$st/main_direct.c" "$src/ports/direct/direct_spin.c" "$st/startup.c" "$st/semihost.c" \
    "$st/lm3s6965_oled.c" "$st/board_lm3s6965.c" "$src/ports/controllers/panel.c" \
    "$src/ports/controllers/ssd0323.c" "$src/src/direct.c" "$src/src/direct_band.c" \
    "$src/src/direct_view.c" "$src/src/direct_clip.c" "$src/src/clip.c" "$src/src/shade_fast.c" "$src/src/shade.c" "$src/src/view.c" "$src/src/recip.c" "$src/src/mesh.c" "$src/src/fix.c" "$src/src/div64.c" "$work/obj/libc_min.x" -lgcc \
    -Wl,-Map="$work/lm3s6965.map" -o "$work/stipple_fw_lm3s6965evb_direct.elf"
echo "== whole lm3s6965evb image (LTO, --gc-sections)"
arm-none-eabi-size "$work/stipple_fw_lm3s6965evb_direct.elf"
echo "== RAM of the spinning torus (500 vertices, 1000 triangles), bytes"
arm-none-eabi-nm -S --size-sort --radix=d "$work/stipple_fw_lm3s6965evb_direct.elf" | awk '
    $3 ~ /^[bBdD]$/ { printf "%7d %s\n", $2, $4 }'

# ---- 3. the direct-drawing files on an ATmega328P, per function
# avr-gcc -Os without LTO in the Arduino library's configuration
# (ports/arduino/src/stipple_config.h, included for ARDUINO), as
# docs/avr.md gives them: each function's bytes as avr-nm reports them.
if command -v avr-gcc >/dev/null 2>&1; then
    echo "== direct drawing on an ATmega328P (avr-gcc -Os, no LTO, Arduino configuration), bytes per function"
    for f in direct direct_band direct_view shade_fast; do
        # shellcheck disable=SC2086
        avr-gcc -std=gnu11 -mmcu=atmega328p -Os -ffunction-sections -fdata-sections -DARDUINO=10819 \
            -Wall -Wextra -Werror -I "$src/include" -I "$src/src" -I "$src/ports/arduino/src" \
            -c "$src/src/$f.c" -o "$work/obj/$f.avr.o"
    done
    for f in direct direct_band direct_view shade_fast; do
        avr-nm --size-sort -S -t d "$work/obj/$f.avr.o" |
            awk -v f="$f.c" 'NF == 4 && $3 ~ /[tTrR]/ { printf "%7d %s %s\n", $2, f, $4 }'
    done
else
    echo "== avr-gcc not found: no ATmega328P sizes"
fi
