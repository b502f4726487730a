#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's C example is a whole program: extract it (the ```c block after
# the line "<!-- readme-example: program -->"), compile it as a user would
# (-std=c99, warnings as errors) against the built library, run it, and
# compare what it prints with the README's ```text block after
# "<!-- readme-example: output -->" (trailing blanks ignored).  Then the
# firmware example (the ```c block after "<!-- readme-example: firmware -->")
# the same way, run by firmware_harness.c against a model of the SSD1306's
# pages.
# Usage: test_readme_example.sh SOURCE_DIR CC LIBRARY [DEFINITIONS] [INCLUDE_DIR]
#   DEFINITIONS: the library's configuration, NAME=VALUE separated by ':'
# CFLAGS and LDFLAGS from the environment are passed on (sanitizer builds).
set -u
src=$1 cc=$2 lib=$3 defs=${4:-} extra_include=${5:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

block() { # MARKER LANGUAGE: the fenced block after the marker line
    awk -v marker="<!-- readme-example: $1 -->" -v fence="\`\`\`$2" '
        $0 == marker { armed = 1; next }
        armed && !inside && $0 == fence { inside = 1; next }
        inside && $0 == "```" { exit }
        inside { print }' "$src/README.md"
}
block program c >"$work/example.c"
block output text >"$work/expected.txt"
[ -s "$work/example.c" ] || fail "README.md has no C block after <!-- readme-example: program -->"
[ -s "$work/expected.txt" ] || fail "README.md has no text block after <!-- readme-example: output -->"

flags=()
IFS=: read -r -a list <<<"$defs"
for d in "${list[@]}"; do [ -n "$d" ] && flags+=("-D$d"); done
[ -n "$extra_include" ] && flags+=("-I$extra_include")
# shellcheck disable=SC2086 # CFLAGS and LDFLAGS are lists of words
"$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror ${CFLAGS:-} "${flags[@]}" -I "$src/include" \
    "$work/example.c" "$lib" ${LDFLAGS:-} -o "$work/example" 2>"$work/cc.log" ||
    { cat "$work/cc.log"; fail "the README's example does not compile"; }
"$work/example" >"$work/actual.txt" || fail "the README's example exited with $?"
sed 's/[[:space:]]*$//' "$work/actual.txt" >"$work/actual.trimmed"
sed 's/[[:space:]]*$//' "$work/expected.txt" >"$work/expected.trimmed"
if ! diff -u "$work/expected.trimmed" "$work/actual.trimmed"; then
    fail "the README's example prints something else than the README shows"
fi
echo "ok: the README's example compiles, runs and prints the README's picture ($(wc -l <"$work/actual.txt") lines)"

block firmware c >"$work/readme_firmware.c"
[ -s "$work/readme_firmware.c" ] || fail "README.md has no C block after <!-- readme-example: firmware -->"
# shellcheck disable=SC2086 # CFLAGS and LDFLAGS are lists of words
"$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror ${CFLAGS:-} "${flags[@]}" -I "$src/include" -I "$work" \
    "$src/tests/readme/firmware_harness.c" "$lib" -lm ${LDFLAGS:-} -o "$work/firmware" 2>"$work/cc.log" ||
    { cat "$work/cc.log"; fail "the README's firmware example does not compile"; }
"$work/firmware" >"$work/firmware.txt" || { cat "$work/firmware.txt"; fail "the README's firmware example draws a wrong picture"; }
echo "ok: the README's firmware example compiles and spins: $(tail -n 1 "$work/firmware.txt")"
