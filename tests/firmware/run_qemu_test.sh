#!/bin/sh
# SPDX-License-Identifier: MIT
# End-to-end firmware test: build a board's firmware for SCENE with the
# cross toolchain, run it in QEMU, take a screendump of the OLED over QMP and
# compare it pixel for pixel with `stipple render` of the same scene through
# the same core, at the panel's size.  Boards:
#   lm3s6965evb  SSD0323 128x64 (SSI): the 1-bit halftoned picture, ON as grey
#                15; the shipping image and the bench image (the scene's
#                minimal configuration) and the full library's bench image
#   lm3s811evb   SSD0303 96x16 mono (I2C): the 1-bit picture, drawn in the
#                panel's page layout (STP_PIXEL_MONO1_PAGES) and sent page by
#                page as drawn; the shipping and bench images of the minimal
#                configuration only (the full renderer exceeds its 8 KB RAM)
# Either dump shows a panel pixel as a 4x4 block, 255 for ON and 0 for OFF.
# Every image's picture is compared; the bench images' counts are recorded.
#
# run_qemu_test.sh [--board BOARD] SOURCE_DIR WORK_DIR STIPPLE COMPILE_TOOL COMPARE SCENE [OPTION...]
#   BOARD         lm3s6965evb (default) or lm3s811evb
#   STIPPLE       host stipple command (for the reference render)
#   COMPILE_TOOL  host program taking `compile SCENE -o OUT.c` (stipple itself
#                 once it has the subcommand, or stp_compile_scene)
#   COMPARE       compare_screendump
#   OPTION...     render options shared by both sides (e.g. --hidden painter)
# Exit status: 0 pass, 1 fail, 77 tools missing (skipped).
# WORK_DIR/figures.csv receives the instruction counts each image reported
# (QEMU -icount shift=0, emulated instructions), one row per image that
# passed: board,cpu,scene,config,instr_per_shade,instr_enter,instr_frame,
# instr_frame_with_transfer,options; config is "minimal" (the scene's own
# configuration) or "full" (the default one), scene the file's name without
# .nff; a figure the firmware does not report is left empty (the lm3s811evb
# reports no per-shade figure).
# Environment: STP_FW_CPU (cortex-m3; cortex-m0plus also runs on QEMU's M3),
# STP_QEMU_TIMEOUT (seconds per QEMU run, 60), STP_BUILD_TIMEOUT (600),
# STP_FW_BAND_ROWS (4; 8 on the lm3s811evb: whole pages), STP_FW_STATIC (OFF; ON: the scene compiled with
# --static and played back from flash), STP_FW_SPANS (OFF; ON: compiled with
# --spans, drawn by the span player: no renderer, so no renderer bytes).
set -eu

board=lm3s6965evb
if [ "${1:-}" = "--board" ] && [ $# -ge 2 ]; then
    board=$2
    shift 2
fi
if [ $# -lt 6 ]; then
    echo "usage: $0 [--board BOARD] SOURCE_DIR WORK_DIR STIPPLE COMPILE_TOOL COMPARE SCENE [OPTION...]" >&2
    exit 2
fi
# per board: the panel's size, the images to run, and how the firmware is
# told to finish once the screendump is taken (the lm3s6965evb waits for its
# "up" key; QEMU gives the lm3s811evb no keys, so it waits for a UART0 byte)
case $board in
    lm3s6965evb)
        size=128x64
        images="stipple_fw_lm3s6965evb stipple_fw_lm3s6965evb_bench stipple_fw_lm3s6965evb_full"
        default_band_rows=4
        uart=no ;;
    lm3s811evb)
        size=96x16
        images="stipple_fw_lm3s811evb stipple_fw_lm3s811evb_bench"
        default_band_rows=8
        uart=yes ;;
    *)
        echo "$0: unknown board '$board' (lm3s6965evb or lm3s811evb)" >&2
        exit 2 ;;
esac
src=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
stipple=$3 compile_tool=$4 compare=$5 scene=$6
shift 6
cpu=${STP_FW_CPU:-cortex-m3}
qemu_timeout=${STP_QEMU_TIMEOUT:-60}
build_timeout=${STP_BUILD_TIMEOUT:-600}
band_rows=${STP_FW_BAND_ROWS:-$default_band_rows}
here=$(cd "$(dirname "$0")" && pwd)

# 77: CTest's "skipped" (SKIP_RETURN_CODE), so a machine without the tools
# shows the test as not run rather than passed
for tool in qemu-system-arm arm-none-eabi-gcc; do
    command -v "$tool" >/dev/null 2>&1 || { echo "$0: $tool not found: skipped" >&2; exit 77; }
done
[ -x /usr/bin/python3 ] || { echo "$0: /usr/bin/python3 not found: skipped" >&2; exit 77; }

# the render options as one CMake list
options=""
for o in "$@"; do options="${options:+$options;}$o"; done

fw="$work/fw-$cpu"
echo "== building the $board firmware ($cpu) in $fw"
timeout "$build_timeout" cmake -S "$src/firmware" -B "$fw" \
    -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchain-arm-none-eabi.cmake" -DSTP_CPU="$cpu" \
    -DSTP_FW_BOARD="$board" \
    -DSTP_FW_COMPILE_TOOL="$compile_tool" -DSTP_FW_SCENE="$scene" \
    -DSTP_FW_COMPILE_OPTIONS="$options" -DSTP_FW_BAND_ROWS="$band_rows" \
    -DSTP_FW_STATIC="${STP_FW_STATIC:-OFF}" -DSTP_FW_SPANS="${STP_FW_SPANS:-OFF}" >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; exit 1; }
timeout "$build_timeout" cmake --build "$fw" >"$work/build.log" 2>&1 ||
    { cat "$work/build.log" >&2; exit 1; }

echo "== host render"
# compiled scenes use the library's cell, levels and exposure (Bayer 4x4,
# 16, none), not the command's defaults for a still PBM (Floyd-Steinberg,
# 256 levels, automatic exposure)
"$stipple" render "$scene" -s "$size" -d bayer4 -l 16 --exposure off -o "$work/host.pbm" "$@"

# "stipple: WHAT N" from a firmware log; empty when it is not there
figure() {
    sed -n "s/^stipple: $2 \([0-9][0-9]*\)\r*\$/\1/p" "$1" | head -n 1
}
figures="$work/figures.csv"
scene_name=$(basename "$scene" .nff)
echo "board,cpu,scene,config,instr_per_shade,instr_enter,instr_frame,instr_frame_with_transfer,options" \
    >"$figures"

# Unix socket paths must stay under 108 bytes, which a build tree in a deep
# checkout exceeds: the sockets live in a short folder of their own.
sockdir=$(mktemp -d /tmp/stpq.XXXXXX)
trap 'rm -rf "$sockdir"' EXIT

status=0
for image in $images; do
    elf="$fw/$image.elf"
    sock="$sockdir/$image.qmp"
    log="$work/$image.log"
    dump="$work/$image.ppm"
    serial_sock="$sockdir/$image.uart"
    rm -f "$sock" "$log" "$dump" "$serial_sock"
    # the QMP client releases the firmware through this socket when set
    release=""
    serial=null
    if [ "$uart" = yes ]; then
        serial="unix:$serial_sock,server=on,wait=off"
        release=$serial_sock
    fi
    echo "== $image"
    arm-none-eabi-size "$elf"
    timeout -k 5 "$qemu_timeout" qemu-system-arm -M "$board" -kernel "$elf" \
        -display none -serial "$serial" -monitor none \
        -qmp "unix:$sock,server=on,wait=off" \
        -semihosting-config enable=on,target=native -icount shift=0 >"$log" 2>&1 &
    qemu=$!
    client=0
    /usr/bin/python3 "$here/qmp_screendump.py" "$sock" "$log" "$dump" "$qemu_timeout" "$qemu" \
        ${release:+"$release"} ||
        client=$?
    qemu_status=0
    wait "$qemu" || qemu_status=$?
    cat "$log"
    if [ "$client" -ne 0 ]; then
        echo "FAIL $image: QMP client failed ($client)" >&2
        status=1
        continue
    fi
    if [ "$qemu_status" -ne 0 ]; then
        echo "FAIL $image: QEMU exited with $qemu_status (124: timed out)" >&2
        status=1
        continue
    fi
    # the shipping image reports nothing but the frame; the others counts
    case $image in
        *_full) config=full ;;
        *_bench) config=minimal ;;
        *) config= ;;
    esac
    if [ -n "$config" ] && ! grep -q "instructions per frame" "$log"; then
        echo "FAIL $image: no instruction count reported" >&2
        status=1
        continue
    fi
    # the stack must not have reached the static data (bench images paint
    # the free RAM at reset and report what the stack never touched)
    unused=$(figure "$log" "stack bytes never used:")
    if [ -n "$config" ] && { [ -z "$unused" ] || [ "$unused" -eq 0 ]; }; then
        echo "FAIL $image: the stack ran into the static data (no stack bytes left unused)" >&2
        status=1
        continue
    fi
    # the firmware build measures STP_RENDERER_BYTES: it must be the object's size
    object=$(figure "$log" "renderer bytes:")
    storage=$(figure "$log" "renderer storage bytes:")
    if [ -n "$config" ] && [ "${STP_FW_SPANS:-OFF}" != ON ] &&
        { [ -z "$object" ] || [ "$object" != "$storage" ]; }; then
        echo "FAIL $image: STP_RENDERER_BYTES is not stp_renderer_size()" >&2
        status=1
        continue
    fi
    if "$compare" "$dump" "$work/host.pbm" 4; then
        echo "PASS $image"
        [ -n "$config" ] || continue
        per_shade=$(figure "$log" "instructions per shade:")
        enter=$(figure "$log" "instructions to enter the scene:")
        frame=$(figure "$log" "instructions per frame (core):")
        transfer=$(figure "$log" "instructions per frame (core + panel):")
        echo "$board,$cpu,$scene_name,$config,$per_shade,$enter,$frame,$transfer,$*" >>"$figures"
    else
        echo "FAIL $image: the panel differs from the host render" >&2
        status=1
    fi
done
exit $status
