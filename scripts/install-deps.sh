#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install what stipple's build, tests and demo need, from Debian's packages.
# Idempotent; uses sudo when not root.
set -eu
packages=(
    cmake make gcc g++ libc6-dev       # the build (g++: the C++ consumer tests)
    libcmocka-dev                      # the test framework
    libpng-dev help2man                # PNG in and out; the man page from --help
    man-db groff-base bsdextrautils    # the man page's checks (man, groff, col)
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
# The package lists are refreshed every time: the tests fetch packages
# (python3-skimage for its photo, Debian's kernel) with apt-get download too.
as_root apt-get update -q >/dev/null
if [ "${#missing[@]}" -gt 0 ]; then
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
# libgpiod 2 (the GPIO control lines of SPI panels) only when the machine's
# own apt sources offer it (Debian 13, or Debian 12 with bookworm-backports
# already enabled by its owner): this script never edits apt sources.
# Without it the GPIO lines are not built and test_linux_fb says it skipped
# their checks; everything else builds and runs.
gpiod_candidate() { apt-cache policy "$1" 2>/dev/null | sed -n 's/^ *Candidate: *//p'; }
gpiod_backports() { apt-cache policy libgpiod-dev 2>/dev/null | grep -q -- '-backports'; }
if ! dpkg-query -W -f='${Version}' libgpiod-dev 2>/dev/null | grep -q '^2'; then
    case $(gpiod_candidate libgpiod-dev) in
    2*) as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends libgpiod-dev ;;
    *)
        if gpiod_backports; then
            as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
                -t "$(. /etc/os-release && echo "$VERSION_CODENAME")-backports" libgpiod-dev
        else
            echo "install-deps.sh: libgpiod 2 is not in this machine's apt sources: the GPIO" \
                "control lines are left out (their tests say so)" >&2
        fi
        ;;
    esac
fi
