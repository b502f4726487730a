#!/bin/sh
# SPDX-License-Identifier: MIT
# The core builds for small integer-only targets and needs nothing hosted.
#
#   tests/check_cross.sh [ROOT [WORK_DIR]]     (ROOT: the checkout, default ..)
#
# 1. Every src/*.c compiles for a Cortex-M0 (arm-none-eabi-gcc, Thumb, -Os,
#    freestanding, -Werror); the objects are linked into one relocatable
#    object, and its undefined symbols (printed) must include no float or
#    double helper (__aeabi_f*, __aeabi_d*, __aeabi_[u][il]2[fd], libgcc's
#    __addsf3 and kin), no libm, and no malloc/free/calloc/realloc/stdio.
# 2. The same for RV32IMAC (riscv64-unknown-elf-gcc -march=rv32imac
#    -mabi=ilp32): compiles, and no soft-float or hosted symbol.
# 3. src/ and include/ mention no float, double, malloc & co. or stdio
#    outside comments and strings.
# 4. The shipped configurations (cmake/stipple_configurations.cmake) build
#    for their chips: Cortex-M0+ full and minimal, ATmega2560 (avr-gcc).
# A missing cross compiler is a failure, not a skip.  The symbol filter is
# itself checked first on an object that uses float and malloc, so a broken
# filter cannot pass everything.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
root=${1:-$here/..}
root=$(cd "$root" && pwd)
work=${2:-${TMPDIR:-/tmp}/stp_check_cross.$$}
mkdir -p "$work"
status=0

fail() {
    echo "check_cross: FAIL: $*" >&2
    status=1
}

# Symbols a float-free, heap-free, stdio-free core must not need.
FORBIDDEN='^(__aeabi_[fd][a-z0-9_]*|__aeabi_u?[il]2[fd]|__[a-z]*(sf|df|tf|xf)[a-z0-9]*|__(float|fix|fixuns|extend|trunc)[a-z]*(sf|df|tf|xf)[a-z0-9]*|__(eq|ne|lt|le|gt|ge|unord|cmp)[sdtx]f2|malloc|free|calloc|realloc|aligned_alloc|posix_memalign|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsnprintf|puts|fputs|putchar|fputc|fwrite|fopen|fclose|stdout|stderr|stdin|_impure_ptr|abort|exit|(sqrt|sin|cos|tan|pow|exp|exp2|log|log2|floor|ceil|fabs|round|fmod)[fl]?)$'

# undefined_symbols NM OBJECT: the undefined symbols, one per line
undefined_symbols() {
    "$1" -u "$2" | awk '{ print $NF }' | sort -u
}

# check_target NAME CC NM CFLAGS...
check_target() {
    name=$1 cc=$2 nm=$3
    shift 3
    if ! command -v "$cc" >/dev/null 2>&1; then
        fail "$cc not found (install it: the check must not be skipped)"
        return
    fi
    dir=$work/$name
    rm -rf "$dir"
    mkdir -p "$dir"
    objs=
    for src in "$root"/src/*.c; do
        obj=$dir/$(basename "$src" .c).o
        if ! "$cc" "$@" -I "$root/include" -I "$root/src" -c "$src" -o "$obj"; then
            fail "$name: $src does not compile"
            continue
        fi
        objs="$objs $obj"
    done
    [ -n "$objs" ] || { fail "$name: no objects"; return; }
    # shellcheck disable=SC2086
    if ! "$cc" "$@" -nostdlib -r -o "$dir/core.o" $objs; then
        fail "$name: partial link failed"
        return
    fi
    # the filter must catch a float- and malloc-using object
    cat >"$dir/probe.c" <<'PROBE'
#include <stddef.h>
void *malloc(size_t n);
float probe_f(float a, float b) { return a / b + (float)(long)a; }
double probe_d(double a, double b) { return a * b - (double)(unsigned long long)b; }
void *probe_m(size_t n) { return malloc(n); }
PROBE
    if ! "$cc" "$@" -c "$dir/probe.c" -o "$dir/probe.o"; then
        fail "$name: the probe does not compile"
    elif [ "$(undefined_symbols "$nm" "$dir/probe.o" | grep -cE "$FORBIDDEN")" -lt 3 ]; then
        fail "$name: the symbol filter misses the probe's float/double/malloc symbols:"
        undefined_symbols "$nm" "$dir/probe.o" >&2
    fi
    echo "== $name: undefined symbols of the core:"
    undefined_symbols "$nm" "$dir/core.o" | sed 's/^/   /'
    bad=$(undefined_symbols "$nm" "$dir/core.o" | grep -E "$FORBIDDEN" || true)
    if [ -n "$bad" ]; then
        fail "$name: forbidden symbols needed by the core:"
        echo "$bad" | sed 's/^/   /' >&2
    else
        echo "== $name: ok, no float/double helper, heap or stdio symbol"
    fi
    "${nm%nm}size" "$dir/core.o" 2>/dev/null || true
}

check_target cortex-m0 arm-none-eabi-gcc arm-none-eabi-nm \
    -mcpu=cortex-m0 -mthumb -Os -ffreestanding -std=c99 -Wall -Wextra -Werror
check_target rv32imac riscv64-unknown-elf-gcc riscv64-unknown-elf-nm \
    -march=rv32imac -mabi=ilp32 -Os -ffreestanding -std=c99 -Wall -Wextra -Werror

# 4. the configurations the project ships (cmake/stipple_configurations.cmake,
# read from there): Cortex-M0+ with every switch at its default and with
# the least core, and the ATmega2560 (16-bit int, avr-gcc) with a compiled
# scene's switches.  Their host libraries run the test suite on the 32-bit
# arithmetic; here the core must build for the chip, warning-free, and need
# no float, heap or stdio symbol.
shipped_defines() { # NAME: the -D flags of STP_CONFIG_NAME
    awk -v want="set(STP_CONFIG_$1" '
        index($0, want " ") == 1 || $0 == want { on = 1 }
        on { line = $0; sub(/^set\(STP_CONFIG_[a-z0-9_]+/, "", line); sub(/\).*/, "", line)
             n = split(line, w, " "); for (i = 1; i <= n; i++) if (w[i] ~ /^STP_/) printf "-D%s ", w[i] }
        on && /\)/ { exit }' "$root/cmake/stipple_configurations.cmake"
}
for config in m0plus_full m0plus_minimal; do
    defs=$(shipped_defines $config)
    [ -n "$defs" ] || fail "no STP_CONFIG_$config in cmake/stipple_configurations.cmake"
    # shellcheck disable=SC2086 # defs: a list of -D flags
    check_target "cortex-m0plus-$config" arm-none-eabi-gcc arm-none-eabi-nm \
        -mcpu=cortex-m0plus -mthumb -Os -ffreestanding -std=c99 -Wall -Wextra -Werror $defs
done
defs=$(shipped_defines avr)
[ -n "$defs" ] || fail "no STP_CONFIG_avr in cmake/stipple_configurations.cmake"
# shellcheck disable=SC2086
check_target atmega2560-avr avr-gcc avr-nm -mmcu=atmega2560 -Os -ffreestanding -std=c99 -Wall -Wextra -Werror $defs

# 3. source text: strip comments and string/char literals with the
# preprocessor's comment removal (no includes expanded), then look for words
echo "== source scan of src/ and include/"
scan_words='\b(float|double|long double|malloc|calloc|realloc|free|alloca|printf|fprintf|sprintf|snprintf|puts|FILE|stdio|stdlib|math\.h|stdio\.h|stdlib\.h)\b'
for f in "$root"/src/*.c "$root"/src/*.h "$root"/include/stipple/*.h; do
    stripped=$(gcc -fpreprocessed -dD -E -P -x c "$f" 2>/dev/null) || { fail "cannot read $f"; continue; }
    # drop string and character literals
    hits=$(printf '%s\n' "$stripped" | sed -e 's/"\([^"\\]\|\\.\)*"/""/g' -e "s/'\\([^'\\\\]\\|\\\\.\\)*'/''/g" |
        grep -nE "$scan_words" || true)
    if [ -n "$hits" ]; then
        fail "$f uses a forbidden word outside comments:"
        printf '%s\n' "$hits" | sed 's/^/   /' >&2
    fi
done
# the scan itself must see a float in code and not one in a comment
probe_hits=$(printf 'int a; /* float in a comment */\nfloat b;\nconst char *s = "double";\n' |
    gcc -fpreprocessed -dD -E -P -x c - | sed -e 's/"\([^"\\]\|\\.\)*"/""/g' | grep -cE "$scan_words" || true)
[ "$probe_hits" = "1" ] || fail "the source scan is broken (found $probe_hits, want 1 in the probe)"

if [ "$status" -eq 0 ]; then
    echo "check_cross: ok"
fi
exit "$status"
