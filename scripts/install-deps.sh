#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install what stipple's build, tests and demo need, from Debian's packages.
# Idempotent; uses sudo when not root.
set -eu
packages=(
    cmake make gcc g++ libc6-dev       # the build (g++: the C++ consumer tests)
    libcmocka-dev                      # the test framework
    libpng-dev help2man                # PNG in and out; the man page from --help
    libgif-dev                         # animated GIF output (stipple animate; optional)
    libjpeg62-turbo-dev                # JPEG input (stipple dither; optional)
    netpbm                             # pamvalidate and friends, for the outputs
    imagemagick                        # the reference for the Bayer cells
    gcc-arm-none-eabi binutils-arm-none-eabi  # the Cortex-M0 check of the core
    gcc-riscv64-unknown-elf            # the RISC-V check of the core
    gcc-avr avr-libc binutils-avr simavr libsimavr-dev arduino-core-avr arduino-builder zip  # AVR (16-bit int), the Arduino library and its sketches in simavr
    qemu-system-arm python3            # the firmware in an emulated Stellaris board (QMP client)
    dpkg-dev                           # dpkg-deb, to unpack the test photo's package
    gnuplot-nox                        # the error-against-run-time plot
    valgrind                           # callgrind instruction counts of the torus bench
    pmccabe                            # function length and complexity (scripts/check_shape.sh)
    clang libclang-rt-14-dev           # libFuzzer targets of the readers and the display file
    qemu-system-x86 busybox-static xz-utils gcc-12  # fbdev tests on Debian's kernel
    libusb-1.0-0-dev umockdev libumockdev-dev pkg-config  # the USB printer and its emulation
)
as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# libgpiod v2 is in bookworm-backports on Debian 12: add that suite to the
# machine's existing Debian source entry (no new URL).
sources=/etc/apt/sources.list.d/debian.sources
if [ -f "$sources" ] && grep -q '^Suites:.*\bbookworm\b' "$sources" && ! grep -q 'bookworm-backports' "$sources"; then
    as_root sed -i '0,/^Suites:.*\bbookworm\b.*/s//& bookworm-backports/' "$sources"
fi
# The package lists are refreshed every time: the tests fetch packages
# (python3-skimage for its photo, Debian's kernel) with apt-get download too.
as_root apt-get update -q >/dev/null
if [ "${#missing[@]}" -gt 0 ]; then
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
if apt-cache policy libgpiod-dev 2>/dev/null | grep -q 'bookworm-backports' &&
    ! dpkg-query -W -f='${Version}' libgpiod-dev 2>/dev/null | grep -q '^2'; then
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends -t bookworm-backports libgpiod-dev
fi
