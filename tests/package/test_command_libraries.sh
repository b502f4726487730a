#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The stipple command runs on a plain Debian 12: every shared library it
# needs (ELF NEEDED) is one that Debian 12's main archive has at the version
# the command was linked against — libc, libm, libpng16, libz, libusb-1.0,
# libgif, libjpeg (libjpeg62-turbo) —
# and never libgpiod (libgpiod 2 is only in bookworm-backports; the GPIO
# control lines load it when a device spec names a line).  When the GPIO
# lines are built, a spec naming a line on a chip that does not exist must
# fail with the chip's name: libgpiod was loaded and asked (the loader works).
# Usage: test_command_libraries.sh STIPPLE [with-gpio]
set -u
stipple=$1 gpio=${2:-}
fail() { echo "FAIL: $*"; exit 1; }
command -v readelf >/dev/null || { echo "readelf not found (binutils)"; exit 77; }
needed=$(readelf -d "$stipple" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
[ -n "$needed" ] || fail "readelf found no NEEDED entries in $stipple"
for lib in $needed; do
    case $lib in
    libc.so.6 | libm.so.6 | libpng16.so.16 | libz.so.1 | libusb-1.0.so.0 | libgif.so.7 | libjpeg.so.62) echo "ok: needs $lib" ;;
    libasan.so.* | libubsan.so.* | libgcc_s.so.1) echo "ok: needs $lib (compiler runtime)" ;;
    *) fail "the stipple command needs $lib, which plain Debian 12 may not have" ;;
    esac
done
if [ "$gpio" = with-gpio ]; then
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    "$stipple" scene tetra -o "$work/t.nff" || fail "stipple scene tetra"
    if "$stipple" render "$work/t.nff" --device spi:/dev/null,controller=ssd1306,dc=gpiochip99:1 \
        2>"$work/err"; then
        fail "a device with a line on a missing GPIO chip was accepted"
    fi
    grep -q "gpiochip99" "$work/err" || { cat "$work/err"; fail "the error does not name the chip"; }
    echo "ok: GPIO lines through the loaded libgpiod: $(cat "$work/err")"
fi
