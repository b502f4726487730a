#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every build switch of include/stipple/config.h must change the core's object
# code when flipped (a switch spelled differently in two places would
# silently do nothing), and the core must build warning-free in each position.
# Usage: check_switches.sh SOURCE_DIR [CC]
set -u
src=$1
cc=${2:-cc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build() { # OUT_DIR DEFINES...
    local out=$1
    shift
    mkdir -p "$out"
    # shellcheck disable=SC2086 # files: a list of paths without spaces
    for f in ${files:-"$src"/src/*.c}; do
        "$cc" -std=c99 -Os -ffreestanding -Wall -Wextra -Wpedantic -Werror -Wshadow -Wconversion \
            -Wno-sign-conversion "$@" -I "$src/include" -I "$src/src" -c "$f" \
            -o "$out/$(basename "$f" .c).o" || return 1
    done
    # code and constant data only: the object files' other sections carry names
    for o in "$out"/*.o; do objcopy -O binary -j .text -j '.text.*' -j .rodata -j '.rodata.*' "$o" "$o.bin"; done
    cat "$out"/*.o.bin | sha256sum | cut -d' ' -f1
}
switches=$(grep -oE '^#define (STP_[A-Z0-9_]+) ' "$src/include/stipple/config.h" | awk '{print $2}')
base=$(build "$work/base") || { echo "FAIL: default build"; exit 1; }
passes=0 failures=0
for s in $switches; do
    default=$(sed -n "s/^#define $s \([0-9]*\).*/\1/p" "$src/include/stipple/config.h")
    case "$s" in
        STP_FIX_FRAC_BITS) flipped=12 ;;
        STP_MAX_POLYGON_VERTICES) flipped=8 ;;
        STP_MAX_LIGHTS | STP_MAX_SEGMENTS) flipped=1 ;;
        STP_RT_MAX_DEPTH) flipped=2 ;;
        STP_VERTEX_CACHE) flipped=0 ;;
        STP_PATTERN_CACHE) flipped=0 ;;
        *) flipped=$((1 - default)) ;;
    esac
    files='' extra=''
    if [ "$s" = STP_PLAYBACK_ONLY ]; then
        # only the playback sources build with it (config.h), shadows off:
        # compared with the same sources and shadows off without it
        files=$(for f in playback raster dither output shade status frame_memory div64 recip fix edge_aa; do echo "$src/src/$f.c"; done)
        extra=-DSTP_WITH_SHADOWS=0
        base_s=$(build "$work/$s-base" "$extra") || base_s=none
    else
        base_s=$base
    fi
    # shellcheck disable=SC2086 # extra: empty or one option
    if ! sum=$(build "$work/$s" "-D$s=$flipped" $extra); then
        echo "FAIL: $s=$flipped does not build cleanly"
        failures=$((failures + 1))
    elif [ "$sum" = "$base_s" ]; then
        echo "FAIL: $s=$flipped leaves the object code unchanged"
        failures=$((failures + 1))
    else
        echo "ok: $s=$flipped changes the object code"
        passes=$((passes + 1))
    fi
done
# At most twelve user-facing switches (config.h's first part), each saying
# what it removes and what that saves, with a figure in bytes.
user=$(awk '/==== The user-facing switches/ { on = 1; next } /==== Internal switches/ { on = 0 }
    on && /^\/\*/ { doc = "" } on { line = $0; sub(/^ *\*+ */, "", line); doc = doc " " line }
    on && /^#ifndef STP_/ { print $2, (doc ~ /[0-9] bytes/ && doc ~ /(Saves|saves|Size)/) ? "documented" : "undocumented" }' \
    "$src/include/stipple/config.h")
count=$(printf '%s\n' "$user" | grep -c documented || true)
if [ "$count" -lt 1 ] || [ "$count" -gt 12 ]; then
    echo "FAIL: $count user-facing switches in config.h (1..12 allowed)"
    failures=$((failures + 1))
else
    echo "ok: $count user-facing switches"
    passes=$((passes + 1))
fi
for s in $(printf '%s\n' "$user" | awk '$2 == "undocumented" { print $1 }'); do
    echo "FAIL: the user-facing switch $s does not give its size effect in bytes"
    failures=$((failures + 1))
done
echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ] && [ "$passes" -gt 0 ]
