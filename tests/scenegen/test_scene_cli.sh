#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# stipple scene from the command line: every scene written and rendered, to
# a file and to stdout alike; bad names, sizes and outputs refused without
# leaving a file; and scripts/demo.sh run from a bare copy of the repository
# (nothing beside it: no shared scenes), its install step skipped.
# Usage: test_scene_cli.sh STIPPLE SOURCE_DIR
set -u
stipple=$1
source_dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

names=$("$stipple" scene --list) || fail "--list"
"$stipple" help scene | grep -q "^usage: stipple scene NAME" || fail "stipple help scene"
[ "$(echo "$names" | wc -l)" -eq 6 ] || fail "--list gives $(echo "$names" | wc -l) scenes, not 6"
for name in $names; do
    "$stipple" scene "$name" --size 2 -o "$tmp/$name.nff" || { fail "$name: scene"; continue; }
    "$stipple" scene "$name" -s 2 >"$tmp/$name.stdout.nff" || fail "$name: scene to stdout"
    cmp -s "$tmp/$name.nff" "$tmp/$name.stdout.nff" || fail "$name: stdout differs from -o"
    head -1 "$tmp/$name.nff" | grep -q "^# $name, size 2" || fail "$name: no header comment"
    "$stipple" render "$tmp/$name.nff" -s 64x48 -o "$tmp/$name.pbm" || fail "$name: render"
    [ "$(head -c 2 "$tmp/$name.pbm")" = P4 ] || fail "$name: not a PBM"
done

# usage errors: exit 2, a message naming the problem, no output file
expect() { # STATUS PATTERN ARGS...
    local want=$1 pattern=$2 status
    shift 2
    "$stipple" "$@" >"$tmp/out" 2>"$tmp/err"
    status=$?
    [ "$status" -eq "$want" ] || fail "stipple $*: exit $status, not $want"
    grep -q -- "$pattern" "$tmp/err" || fail "stipple $*: message '$(cat "$tmp/err")' lacks '$pattern'"
}
expect 2 "unknown scene 'teapots'" scene teapots -o "$tmp/bad.nff"
expect 2 "bad --size '0'" scene tetra --size 0 -o "$tmp/bad.nff"
expect 2 "bad --size '9' (tetra: 1..8)" scene tetra --size 9 -o "$tmp/bad.nff"
expect 2 "bad --size '2x'" scene torus --size 2x -o "$tmp/bad.nff"
expect 2 "give one scene NAME" scene
[ ! -e "$tmp/bad.nff" ] || fail "a refused run left bad.nff"
expect 1 "$tmp/no/such/dir/x.nff" scene teapot -o "$tmp/no/such/dir/x.nff"
# a write error on stdout is an error, not a silent short scene
if [ -w /dev/full ]; then
    "$stipple" scene teapot --size 8 >/dev/full 2>/dev/null && fail "writing to /dev/full succeeded"
fi
# a failed run leaves an existing file as it was
echo keep >"$tmp/keep.nff"
"$stipple" scene mountain --size 99 -o "$tmp/keep.nff" 2>/dev/null
[ "$(cat "$tmp/keep.nff")" = keep ] || fail "a refused run changed an existing file"

# the README's demo from a bare copy: scripts/ only, no ../shared beside it
mkdir -p "$tmp/bare/clone/scripts"
cp "$source_dir/scripts/demo.sh" "$tmp/bare/clone/scripts/"
if ! env -u STP_SCENES_DIR STP_DEMO_SKIP_INSTALL=1 STP_DEMO_STIPPLE="$stipple" \
    "$tmp/bare/clone/scripts/demo.sh" >"$tmp/demo.out" 2>"$tmp/demo.err" </dev/null; then
    fail "demo.sh: $(cat "$tmp/demo.err")"
fi
[ -e "$tmp/bare/shared" ] && fail "the demo created ../shared"
for f in teapot.nff teapot.pbm teapot-512.pbm; do
    [ -s "$tmp/bare/clone/out/$f" ] || fail "demo.sh wrote no out/$f"
done
# the text picture: 40 rows of 80 characters (no terminal here), and the
# teapot in them (several of the 16 characters, not only the background)
rows=$(tail -n +2 "$tmp/demo.out" | awk 'length($0) == 80' | wc -l)
[ "$rows" -eq 40 ] || fail "demo printed $rows rows of 80 characters, not 40"
shades=$(tail -n +2 "$tmp/demo.out" | fold -w1 | sort -u | wc -l)
[ "$shades" -ge 5 ] || fail "demo's picture has only $shades distinct characters"

[ "$failures" -eq 0 ] && echo "all scene command checks passed"
exit $((failures > 0))
