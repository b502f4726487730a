#!/bin/sh
# SPDX-License-Identifier: MIT
# Direct drawing on the lm3s6965evb OLED (issue 15 item 3): the shipping
# image of ports/stellaris/main_direct.c, built as tools/firmware_lean_sizes.sh
# builds it (Cortex-M0+ code, -Os, LTO, section GC) but in direct drawing's
# default form (the renderer's stages: the host's frame is that form's;
# the script measures the compact form) and stopping after
# frames 0..10 of the spinning torus, run in QEMU; the panel's screendump
# (QMP) against the host's frame 10 (tools/bench/direct_spin_host) pixel
# for pixel.
#
# usage: run_direct_oled_test.sh SOURCE_DIR WORK_DIR DIRECT_SPIN_HOST COMPARE_SCREENDUMP
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
set -eu
[ $# -eq 4 ] || { echo "usage: $0 SOURCE_DIR WORK_DIR DIRECT_SPIN_HOST COMPARE_SCREENDUMP" >&2; exit 2; }
for tool in qemu-system-arm arm-none-eabi-gcc /usr/bin/python3; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
host=$3
compare=$4
st=$src/ports/stellaris
cflags="-std=c99 -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -Os -ffreestanding -ffunction-sections
 -fdata-sections -Wall -Wextra -Werror -DSTP_WITH_SPECULAR=0 -DSTP_MAX_LIGHTS=1 -DSTP_SMALL_DIVISION=1"
inc="-I $src/include -I $src/src -I $src/ports/direct -I $st -I $src/ports/controllers"
elf=$work/stipple_fw_lm3s6965evb_direct_test.elf
# shellcheck disable=SC2086 # word lists
arm-none-eabi-gcc $cflags -fno-builtin -fno-tree-loop-distribute-patterns -c \
    "$src/ports/compiled/libc_min.c" -o "$work/libc_min.o"
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $inc -DSTP_DIRECT_FRAMES=11 -flto -nostdlib -Wl,--gc-sections \
    -T "$st/lm3s6965.ld" -L "$st" \
    "$st/main_direct.c" "$src/ports/direct/direct_spin.c" "$st/startup.c" "$st/semihost.c" \
    "$st/lm3s6965_oled.c" "$st/board_lm3s6965.c" "$src/ports/controllers/panel.c" \
    "$src/ports/controllers/ssd0323.c" "$src/src/direct.c" "$src/src/direct_band.c" \
    "$src/src/direct_view.c" "$src/src/direct_clip.c" "$src/src/clip.c" "$src/src/shade_fast.c" "$src/src/shade.c" "$src/src/view.c" "$src/src/recip.c" "$src/src/mesh.c" "$src/src/fix.c" "$src/src/div64.c" "$work/libc_min.o" -lgcc -o "$elf"
arm-none-eabi-size "$elf"
"$host" -n 10 -b 64 -i 1 -o "$work/host.pbm"

sockdir=$(mktemp -d /tmp/stpd.XXXXXX)
trap 'rm -rf "$sockdir"' EXIT
sock=$sockdir/qmp
log=$work/qemu.log
dump=$work/panel.ppm
rm -f "$dump"
timeout -k 5 120 qemu-system-arm -M lm3s6965evb -kernel "$elf" -display none -serial null -monitor none \
    -qmp "unix:$sock,server=on,wait=off" -semihosting-config enable=on,target=native >"$log" 2>&1 &
qemu=$!
client=0
/usr/bin/python3 "$src/tests/firmware/qmp_screendump.py" "$sock" "$log" "$dump" 120 "$qemu" || client=$?
qemu_status=0
wait "$qemu" || qemu_status=$?
cat "$log"
[ "$client" -eq 0 ] || { echo "FAIL: QMP client failed ($client)" >&2; exit 1; }
[ "$qemu_status" -eq 0 ] || { echo "FAIL: QEMU exited with $qemu_status" >&2; exit 1; }
if "$compare" "$dump" "$work/host.pbm" 4; then
    echo "PASS: the panel shows the host's frame 10 pixel for pixel"
else
    echo "FAIL: the panel ($dump) differs from the host's frame ($work/host.pbm)" >&2
    exit 1
fi
