#!/bin/sh
# SPDX-License-Identifier: MIT
# The compatibility tag (include/stipple/config_guard.h) refuses a library
# built with other layout switches than the application:
#
#   check_config_tag.sh CC ROOT WORK LIB_A DEFS_A LIB_B DEFS_B [FLAGS]
#
# LIB_A and LIB_B are the core built in two configurations whose layouts
# differ (DEFS_*: their switches NAME=VALUE, separated by commas), FLAGS extra
# compiler and linker flags (the sanitizers').  tag_caller.c, which links
# every constructor, must build and run against the library of its own
# configuration (both ways), and must fail to link against the other one
# with an error naming each of the five constructors under its tagged name.
set -eu
[ $# -ge 7 ] || { echo "usage: $0 CC ROOT WORK LIB_A DEFS_A LIB_B DEFS_B [FLAGS]" >&2; exit 2; }
cc=$1 root=$2 work=$3 lib_a=$4 defs_a=$5 lib_b=$6 defs_b=$7 flags=${8:-}
mkdir -p "$work"
status=0
fail() {
    echo "check_config_tag: FAIL: $*" >&2
    status=1
}
dflags() { # a ;-list of NAME=VALUE as -D flags
    printf '%s' "$1" | tr ',;' '\n\n' | sed -n 's/^\(STP_[A-Z0-9_]*=[0-9]*\)$/-D\1/p' | tr '\n' ' '
}
# link NAME DEFS LIB: compile tag_caller.c with DEFS and link it with LIB
link() {
    # shellcheck disable=SC2046,SC2086 # word lists
    "$cc" -std=c99 $flags $(dflags "$2") -I "$root/include" -o "$work/$1" "$root/tests/config/tag_caller.c" "$3" \
        >"$work/$1.log" 2>&1
}
for side in a b; do
    if [ $side = a ]; then defs=$defs_a lib=$lib_a; else defs=$defs_b lib=$lib_b; fi
    if link "same_$side" "$defs" "$lib"; then
        echo "ok: the application and library of configuration $side link: $("$work/same_$side")"
    else
        cat "$work/same_$side.log" >&2
        fail "the application does not link with the library of its own configuration ($side)"
    fi
done
# the mismatch, both ways
for side in a b; do
    if [ $side = a ]; then defs=$defs_a lib=$lib_b; else defs=$defs_b lib=$lib_a; fi
    if link "mismatch_$side" "$defs" "$lib"; then
        fail "an application of configuration $side linked with the other configuration's library"
        continue
    fi
    for ctor in stp_renderer_create stp_playback_create stp_rt_create stp_direct_frame_project stp_spans_start; do
        if ! grep -q "undefined reference to .${ctor}_cfg_f[0-9]*_v[0-9]*_l[0-9]*_s[0-9]*_c[0-9]*_[01]*" \
            "$work/mismatch_$side.log"; then
            cat "$work/mismatch_$side.log" >&2
            fail "the mismatched link ($side) does not refuse $ctor by its tagged name"
        fi
    done
    echo "ok: configuration $side against the other library refused at link time:"
    grep -o "undefined reference to .stp_[a-z_]*_cfg_[a-z0-9_]*" "$work/mismatch_$side.log" | sort -u | sed 's/^/    /'
done
[ $status -eq 0 ] && echo "check_config_tag: ok"
exit $status
