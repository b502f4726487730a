#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's command-line examples (the ```sh block after the line
# "<!-- readme-example: cli -->"), run as written with bash -e in an empty
# directory laid out as scripts/demo.sh leaves a clone: build-demo/tools/stipple
# (the built command), out/teapot.nff (stipple scene teapot --size 4, as the
# demo writes it), tests/data/scenes/cube.obj, and photo.png (a grey PNG
# rendered by the command stands in for the user's photo).  Then each
# output is checked: teapot.png a 128x64 1-bit PNG, the text 40 lines of 80
# characters, photo-1bit.png a 1-bit PNG of the photo's size, cube.pbm a raw
# PBM, spin.gif a GIF of 36 frames.  Also the API's size the README states
# ("The C API is N public functions in H headers") against
# scripts/api_count.sh.
# Usage: test_readme_cli.sh SOURCE_DIR STIPPLE
set -u
src=$1 stipple=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

awk '$0 == "<!-- readme-example: cli -->" { armed = 1; next }
     armed && !inside && $0 == "```sh" { inside = 1; next }
     inside && $0 == "```" { exit }
     inside { print }' "$src/README.md" >"$work/cli.sh"
[ -s "$work/cli.sh" ] || fail "README.md has no sh block after <!-- readme-example: cli -->"
mkdir -p "$work/build-demo/tools" "$work/out" "$work/tests/data/scenes"
ln -s "$stipple" "$work/build-demo/tools/stipple"
cp "$src/tests/data/scenes/cube.obj" "$work/tests/data/scenes/"
"$stipple" scene teapot --size 4 -o "$work/out/teapot.nff" || fail "stipple scene teapot"
"$stipple" render "$work/out/teapot.nff" -s 160x120 -o "$work/photo.png" || fail "the stand-in photo"
# the API's size as the README states it, against the count
api=$(sh "$src/scripts/api_count.sh" "$src" | tail -n 1) || fail "scripts/api_count.sh"
case $api in
    *" public functions in "*" headers") ;;
    *) fail "scripts/api_count.sh printed no total: $api" ;;
esac
tr -s ' \n' '  ' <"$src/README.md" | grep -qF "API is $api" ||
    fail "README.md does not say \"The C API is $api\""
(cd "$work" && PATH=/usr/bin:/bin bash -e cli.sh >"$work/stdout" 2>"$work/stderr") ||
    { cat "$work/stderr"; fail "the README's examples do not run as written"; }

python3 - "$work" <<'PY' || fail "an example's output is wrong"
import struct, sys
work = sys.argv[1]
def png(name):
    with open(f"{work}/{name}", "rb") as f:
        head = f.read(33)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", f"{name} is not a PNG"
    w, h, depth, colour = struct.unpack(">IIBB", head[16:26])
    return w, h, depth, colour
w, h, depth, colour = png("teapot.png")
assert (w, h, depth, colour) == (128, 64, 1, 0), f"teapot.png is {w}x{h}, {depth}-bit, colour type {colour}"
text = open(f"{work}/stdout").read().split("\n")
rows = [r for r in text if len(r) == 80]
assert len(rows) == 40, f"the text picture has {len(rows)} rows of 80 characters, not 40"
w, h, depth, colour = png("photo-1bit.png")
assert (w, h, depth) == (160, 120, 1), f"photo-1bit.png is {w}x{h}, {depth}-bit"
with open(f"{work}/cube.pbm", "rb") as f:
    assert f.read(2) == b"P4", "cube.pbm is not a raw PBM"
with open(f"{work}/spin.gif", "rb") as f:
    gif = f.read()
assert gif[:6] in (b"GIF87a", b"GIF89a"), "spin.gif is not a GIF"
frames = gif.count(b"\x21\xf9\x04")  # one graphic control extension a frame
assert frames >= 36, f"spin.gif has {frames} frames, not 36"
print("ok: teapot.png 128x64 1-bit, 40 text rows, photo-1bit.png 160x120 1-bit, cube.pbm, spin.gif %d frames" % frames)
PY
