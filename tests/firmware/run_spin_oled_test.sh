#!/bin/sh
# SPDX-License-Identifier: MIT
# The spinning teapot on the lm3s6965evb OLED (issue 11 item 4): the image
# of ports/stellaris/main_spin.c (Cortex-M0+ code as the shipping images,
# STP_SPIN_OPT, default -Os; section GC) with the teapot-s1 meshes written
# by spin_mesh_gen, stopped after frames 0..STP_SPIN_FRAMES-1 (default 8)
# and run in QEMU under -icount shift=0; prints the instructions of every
# frame and the frames per second at 48 MHz they give, and compares the
# panel's screendump (QMP) with the host's picture after the same last
# frame (tools/bench/spin_host, the same spin_frame.c) pixel for pixel.
#
# usage: run_spin_oled_test.sh SOURCE_DIR WORK_DIR SPIN_HOST SPIN_DATA_C COMPARE_SCREENDUMP
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
set -eu
[ $# -eq 5 ] || { echo "usage: $0 SOURCE_DIR WORK_DIR SPIN_HOST SPIN_DATA_C COMPARE_SCREENDUMP" >&2; exit 2; }
for tool in qemu-system-arm arm-none-eabi-gcc /usr/bin/python3; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
host=$3
data=$4
compare=$5
frames=${STP_SPIN_FRAMES:-8}
opt=${STP_SPIN_OPT:--Os}
st=$src/ports/stellaris
cflags="-std=c99 -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft $opt -ffreestanding -ffunction-sections
 -fdata-sections -Wall -Wextra -Werror"
inc="-I $src/include -I $src/src -I $src/ports/spin -I $st -I $src/ports/controllers"
elf=$work/stipple_fw_lm3s6965evb_spin.elf
# shellcheck disable=SC2086 # word lists
arm-none-eabi-gcc $cflags -fno-builtin -fno-tree-loop-distribute-patterns -c \
    "$src/ports/compiled/libc_min.c" -o "$work/libc_min.o"
# shellcheck disable=SC2086
arm-none-eabi-gcc $cflags $inc -DSTP_SPIN_FRAMES="$frames" -nostdlib -Wl,--gc-sections \
    -T "$st/lm3s6965.ld" -L "$st" \
    "$st/main_spin.c" "$src/ports/spin/spin_frame.c" "$data" "$st/startup.c" "$st/semihost.c" \
    "$st/lm3s6965_oled.c" "$st/board_lm3s6965.c" "$src/ports/controllers/panel.c" \
    "$src/ports/controllers/ssd0323.c" "$src"/src/*.c "$work/libc_min.o" -lgcc -o "$elf"
arm-none-eabi-size "$elf"
"$host" -n $((frames - 1)) -o "$work/host.pbm"

sockdir=$(mktemp -d /tmp/stps.XXXXXX)
trap 'rm -rf "$sockdir"' EXIT
sock=$sockdir/qmp
log=$work/qemu.log
dump=$work/panel.ppm
rm -f "$dump"
timeout -k 5 300 qemu-system-arm -M lm3s6965evb -kernel "$elf" -display none -serial null -monitor none \
    -icount shift=0 -qmp "unix:$sock,server=on,wait=off" \
    -semihosting-config enable=on,target=native >"$log" 2>&1 &
qemu=$!
client=0
/usr/bin/python3 "$src/tests/firmware/qmp_screendump.py" "$sock" "$log" "$dump" 300 "$qemu" || client=$?
qemu_status=0
wait "$qemu" || qemu_status=$?
cat "$log"
[ "$client" -eq 0 ] || { echo "FAIL: QMP client failed ($client)" >&2; exit 1; }
[ "$qemu_status" -eq 0 ] || { echo "FAIL: QEMU exited with $qemu_status" >&2; exit 1; }
grep -q "^stipple: frame $((frames - 1)): enter [0-9]" "$log" ||
    { echo "FAIL: no instruction count for frame $((frames - 1))" >&2; exit 1; }
if "$compare" "$dump" "$work/host.pbm" 4; then
    echo "PASS: the panel shows the host's frame $((frames - 1)) pixel for pixel"
else
    echo "FAIL: the panel ($dump) differs from the host's frame ($work/host.pbm)" >&2
    exit 1
fi
