#!/bin/sh
# SPDX-License-Identifier: MIT
# scripts/check_shape.sh finds what it is for, on small made-up cores: an
# import circle by includes only (two headers each naming the other's file),
# one by symbols only, a header declaring another file's function, and
# passes a core whose shared types live in a header with no .c of its own,
# and a listed (known) circle.
#   check_shape_finds.sh SOURCE_DIR CC
set -eu
root=$1
cc=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0

# make NAME: an empty core in $work/NAME, its src/ directory printed
make_core() {
    mkdir -p "$work/$1/src" "$work/$1/include"
    echo "$work/$1/src"
}

# expect NAME STATUS PATTERN...: the check on core NAME exits STATUS and
# prints a line matching each PATTERN
expect() {
    name=$1 status=$2 this=0
    shift 2
    set +e
    sh "$root/scripts/check_shape.sh" --cc "$cc" ${known:+--known "$known"} "$work/$name" >"$work/$name.out" 2>&1
    got=$?
    set -e
    if [ "$got" -ne "$status" ]; then
        echo "FAIL $name: exit $got, expected $status"
        cat "$work/$name.out"
        this=1
    fi
    for pattern in "$@"; do
        if ! grep -q -- "$pattern" "$work/$name.out"; then
            echo "FAIL $name: no line matching '$pattern'"
            this=1
        fi
    done
    if [ "$this" -eq 0 ]; then echo "ok $name"; else failed=1; fi
}
known=

# 1. a.c and b.c include each other's header, neither calls the other
src=$(make_core includes)
printf '#ifndef A_H\n#define A_H\nint a_value(void);\n#endif\n' >"$src/a_private.h"
printf '#ifndef B_H\n#define B_H\nint b_value(void);\n#endif\n' >"$src/b_private.h"
printf '#include "a_private.h"\n#include "b_private.h"\nint a_value(void) { return 1; }\n' >"$src/a.c"
printf '#include "b_private.h"\n#include "a_private.h"\nint b_value(void) { return 2; }\n' >"$src/b.c"
expect includes 1 '^NEW: *include-circle a.c b.c' '0 circles by symbols, 1 by includes'

# 2. the same circle, listed as known
known="$work/known.txt"
printf '# made up\ninclude-circle b.c a.c\n' >"$known"
expect includes 0 '^known: include-circle a.c b.c'
known=

# 3. a.c and b.c call each other, each declaring the other's function itself
src=$(make_core symbols)
printf 'int b_value(int x);\nint a_value(void);\nint a_value(void) { return b_value(0) - 1; }\n' >"$src/a.c"
printf 'int a_value(void);\nint b_value(int x);\nint b_value(int x) { return x ? a_value() : 2; }\n' >"$src/b.c"
expect symbols 1 '^NEW: *circle a.c b.c' '1 circles by symbols, 0 by includes'

# 4. a_private.h also declares b.c's function (b.c does not include it)
src=$(make_core declares)
printf '#ifndef A_H\n#define A_H\nint a_value(void);\nint b_value(void);\n#endif\n' >"$src/a_private.h"
printf '#include "a_private.h"\nint a_value(void) { return b_value(); }\n' >"$src/a.c"
printf 'int b_value(void);\nint b_value(void) { return 2; }\n' >"$src/b.c"
expect declares 1 '^NEW: *declares a_private.h b.c b_value' '0 by includes'

# 5. shared types in state.h (no .c of its own): a.c calls b.c, no circle
src=$(make_core types)
printf '#ifndef STATE_H\n#define STATE_H\ntypedef struct state { int n; } state;\n#endif\n' >"$src/state.h"
printf '#ifndef A_H\n#define A_H\n#include "state.h"\nint a_value(const state *s);\n#endif\n' >"$src/a_private.h"
printf '#ifndef B_H\n#define B_H\n#include "state.h"\nint b_value(const state *s);\n#endif\n' >"$src/b_private.h"
printf '#include "a_private.h"\n#include "b_private.h"\nint a_value(const state *s) { return b_value(s) + 1; }\n' >"$src/a.c"
printf '#include "b_private.h"\nint b_value(const state *s) { return s->n; }\n' >"$src/b.c"
expect types 0 '0 circles by symbols, 0 by includes'

exit "$failed"
