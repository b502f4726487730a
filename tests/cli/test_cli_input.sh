#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The stipple command's inputs and outputs beyond NFF and PNM (run by CTest):
#  1. '-' reads the scene from standard input with --scene-format, giving the
#     very picture the file gives; without --scene-format it is a usage
#     error; a bad scene on stdin is named "stdin:LINE:";
#  2. a PLY mesh (a cube written by hand) renders identically from ASCII,
#     binary little-endian and binary big-endian files, and identically to
#     the same cube as OFF; a malformed PLY gives "file:line:" (ASCII) or
#     "file: byte N:" (binary) and writes nothing;
#  3. PNG out: .png files are valid (netpbm's pngtopnm reads them back) and
#     hold exactly the pixels of the PNM outputs: 8-bit grey
#     = .pgm, RGB with --color = .ppm, 1-bit (--format png1) = .pbm;
#  4. PNG in: `stipple dither photo.png` equals `stipple dither photo.pgm`,
#     for grey, RGB, palette, 16-bit and grey+alpha PNGs written by netpbm,
#     and dither can write PNG; a damaged PNG is refused;
#  5. real meshes from a Debian package (CGAL demo data, fetched by
#     tests/fetch_cgal_meshes.sh): every face declared is drawn, and the
#     sphere re-encoded as binary PLY of both byte orders draws the same.
# Usage: test_cli_input.sh STIPPLE_BINARY SCENES_DIR MESH_DIR
set -u
stipple=$1
scenes=$2
meshes=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
scene=$scenes/teapot-s1.nff

# --- 1. standard input
"$stipple" render "$scene" -s 64x48 -o "$work/file.pgm" || bad "render from a file"
if "$stipple" render - --scene-format nff -s 64x48 -o "$work/stdin.pgm" <"$scene" &&
    cmp -s "$work/file.pgm" "$work/stdin.pgm"; then ok
else bad "scene from stdin differs from the file's picture"; fi
if "$stipple" compile - --scene-format nff -o "$work/c1.c" <"$scene" &&
    "$stipple" compile "$scene" -o "$work/c2.c" && cmp -s "$work/c1.c" "$work/c2.c"; then ok
else bad "compile from stdin differs"; fi
"$stipple" render - -o "$work/x.pbm" <"$scene" 2>"$work/err"
if [ $? = 2 ] && grep -q -- "--scene-format" "$work/err"; then ok; else bad "stdin without --scene-format: $(cat "$work/err")"; fi
printf 'p 3\n0 0 0\n1 0\n' | "$stipple" render - --scene-format nff -o "$work/x.pbm" 2>"$work/err"
if [ $? = 1 ] && grep -q "^stipple: stdin:3: " "$work/err" && [ ! -e "$work/x.pbm" ]; then ok
else bad "bad stdin scene: $(cat "$work/err")"; fi
"$stipple" render - --scene-format stl -o "$work/x.pbm" <"$scene" 2>"$work/err"
if [ $? = 2 ] && grep -q "bad --scene-format 'stl'" "$work/err"; then ok; else bad "--scene-format stl"; fi

# --- 2. PLY: one cube in four files
cube_v="-1 -1 -1
1 -1 -1
1 1 -1
-1 1 -1
-1 -1 1
1 -1 1
1 1 1
-1 1 1"
cube_f="4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3"
{ printf 'OFF\n8 6 12\n%s\n%s\n' "$cube_v" "$cube_f"; } >"$work/cube.off"
{
    printf 'ply\nformat ascii 1.0\ncomment a cube\nelement vertex 8\nproperty float x\n'
    printf 'property float y\nproperty float z\nelement face 6\n'
    printf 'property list uchar int vertex_indices\nend_header\n%s\n%s\n' "$cube_v" "$cube_f"
} >"$work/cube.ply"
# binary: the same numbers packed by perl (f/l with < or > for the byte order)
for order in little big; do
    o='<'
    [ $order = big ] && o='>'
    {
        printf 'ply\nformat binary_%s_endian 1.0\nelement vertex 8\nproperty float x\n' $order
        printf 'property float y\nproperty float z\nelement face 6\n'
        printf 'property list uchar int vertex_indices\nend_header\n'
        echo "$cube_v" | perl -ne "print pack('f$o f$o f$o', split)"
        echo "$cube_f" | perl -ne "my (\$n, @i) = split; print pack('C', \$n), pack('l$o' x \$n, @i)"
    } >"$work/cube-$order.ply"
done
for f in cube.off cube.ply cube-little.ply cube-big.ply; do
    "$stipple" render "$work/$f" -s 96x64 --light 3,4,5 -o "$work/$f.pgm" 2>"$work/err" ||
        bad "$f: $(cat "$work/err")"
done
for f in cube.ply cube-little.ply cube-big.ply; do
    if [ -s "$work/cube.off.pgm" ] && cmp -s "$work/cube.off.pgm" "$work/$f.pgm"; then ok
    else bad "$f renders differently from cube.off"; fi
done
# more than one grey: the faces are lit differently (the cube is there)
greys=$(pnmtoplainpnm "$work/cube.ply.pgm" | tail -n +4 | tr -s ' \n' '\n' | grep . | sort -u | wc -l)
if [ "$greys" -ge 3 ]; then ok; else bad "cube.ply: $greys greys"; fi
sed 's/^4 2 3 7 6$/4 2 3 7 8/' "$work/cube.ply" >"$work/badindex.ply"
"$stipple" render "$work/badindex.ply" -o "$work/bad.pbm" 2>"$work/err"
if [ $? = 1 ] && grep -qF "badindex.ply:22: face 3: index 8 out of range (0..7)" "$work/err" &&
    [ ! -e "$work/bad.pbm" ]; then ok
else bad "bad ASCII PLY: $(cat "$work/err")"; fi
head -c 250 "$work/cube-big.ply" >"$work/short.ply"
"$stipple" render "$work/short.ply" -o "$work/bad.pbm" 2>"$work/err"
if [ $? = 1 ] && grep -qE "short.ply: byte [0-9]+: " "$work/err" && [ ! -e "$work/bad.pbm" ]; then ok
else bad "truncated binary PLY: $(cat "$work/err")"; fi

# --- 3. PNG out
"$stipple" render "$scene" -s 80x60 -o "$work/g.pgm" && "$stipple" render "$scene" -s 80x60 -o "$work/g.png" ||
    bad "grey PNG render"
"$stipple" render "$scene" -s 80x60 --color -o "$work/c.ppm" &&
    "$stipple" render "$scene" -s 80x60 --color -o "$work/c.png" || bad "colour PNG render"
"$stipple" render "$scene" -s 80x60 -o "$work/m.pbm" &&
    "$stipple" render "$scene" -s 80x60 --format png1 -o "$work/m1.png" || bad "1-bit PNG render"
"$stipple" render "$scene" -s 80x60 --palette pseudo -o "$work/p.ppm" &&
    "$stipple" render "$scene" -s 80x60 --palette pseudo -o "$work/p.png" || bad "palette PNG render"
check_png() { # PNG PNM WANT_TYPE(pngtopnm's output magic) WANT_DEPTH
    local png=$1 pnm=$2 magic=$3 depth=$4
    if [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" != 89504e470d0a1a0a ]; then
        bad "$(basename "$png"): no PNG signature"
    elif ! pngtopnm "$png" >"$png.pnm" 2>"$work/err"; then
        bad "$(basename "$png"): pngtopnm refuses it: $(cat "$work/err")"
    elif [ "$(head -c 2 "$png.pnm")" != "$magic" ]; then
        bad "$(basename "$png"): decodes as $(head -c 2 "$png.pnm"), want $magic"
    elif [ "$(od -An -tu1 -j 24 -N 1 "$png" | tr -d ' ')" != "$depth" ]; then
        bad "$(basename "$png"): bit depth $(od -An -tu1 -j 24 -N 1 "$png"), want $depth"
    elif ! cmp -s <(pnmtoplainpnm "$png.pnm" | tail -n +3 | tr -s ' \n' ' ') \
                  <(pnmtoplainpnm "$pnm" | tail -n +3 | tr -s ' \n' ' '); then
        bad "$(basename "$png"): pixels differ from $(basename "$pnm")"
    else ok; fi
}
check_png "$work/g.png" "$work/g.pgm" P5 8
check_png "$work/c.png" "$work/c.ppm" P6 8
check_png "$work/m1.png" "$work/m.pbm" P4 1
check_png "$work/p.png" "$work/p.ppm" P6 8
printf 'keep me' >"$work/keep.png"
if "$stipple" render "$work/badindex.ply" -o "$work/keep.png" 2>/dev/null ||
    [ "$(cat "$work/keep.png")" != "keep me" ] || ls -a "$work" | grep -q '^\.keep\.png\.'; then
    bad "a failed render touched keep.png or left a temporary file"
else ok; fi

# --- 4. PNG in
{
    printf 'P3\n64 16\n255\n'
    for y in $(seq 0 15); do
        for x in $(seq 0 63); do printf '%d %d %d ' $((x * 4)) $(((x * 3 + y * 9) % 256)) $((y * 16)); done
        printf '\n'
    done
} >"$work/photo.ppm"
ppmtopgm "$work/photo.ppm" >"$work/photo-grey.pgm"
pnmtopng "$work/photo.ppm" >"$work/rgb.png" 2>/dev/null
pnmtopng "$work/photo-grey.pgm" >"$work/grey.png" 2>/dev/null
pnmdepth 65535 "$work/photo.ppm" | pnmtopng >"$work/rgb16.png" 2>/dev/null
pnmquant 64 "$work/photo.ppm" 2>/dev/null >"$work/quant.ppm" && pnmtopng "$work/quant.ppm" >"$work/pal.png" 2>/dev/null
pgmmake 0.5 64 16 >"$work/alpha.pgm" && pnmtopng -alpha="$work/alpha.pgm" "$work/photo-grey.pgm" >"$work/greya.png" 2>/dev/null
for pair in rgb.png:photo.ppm grey.png:photo-grey.pgm rgb16.png:photo.ppm pal.png:quant.ppm greya.png:photo-grey.pgm; do
    png=${pair%%:*} ref=${pair#*:}
    if [ ! -s "$work/$png" ]; then bad "netpbm did not make $png"; continue; fi
    "$stipple" dither "$work/$png" -d bayer8 -o "$work/$png.pbm" 2>"$work/err" || { bad "dither $png: $(cat "$work/err")"; continue; }
    "$stipple" dither "$work/$ref" -d bayer8 -o "$work/$ref.pbm" || bad "dither $ref"
    if cmp -s "$work/$png.pbm" "$work/$ref.pbm"; then ok; else bad "dither $png differs from dither $ref"; fi
done
"$stipple" dither "$work/rgb.png" -o "$work/d.png" && "$stipple" dither "$work/rgb.png" -o "$work/d.pbm" || bad "dither to PNG"
if "$stipple" dither - -o "$work/stdin.pbm" <"$work/rgb.png" && cmp -s "$work/stdin.pbm" "$work/d.pbm"; then ok
else bad "dither of a PNG on stdin differs"; fi
check_png "$work/d.png" "$work/d.pbm" P4 1
head -c $(($(wc -c <"$work/rgb.png") / 2)) "$work/rgb.png" >"$work/cut.png"
"$stipple" dither "$work/cut.png" -o "$work/cut.pbm" 2>"$work/err"
if [ $? = 1 ] && grep -q "cut.png: " "$work/err" && [ ! -e "$work/cut.pbm" ]; then ok
else bad "truncated PNG: $(cat "$work/err")"; fi

# --- 5. real meshes from Debian's CGAL demo data (tests/fetch_cgal_meshes.sh)
if [ -n "$meshes" ]; then
    # the polygon counts their headers declare; every face is entered
    for pair in sphere.ply:320 colored_tetra.ply:4; do
        m=$meshes/${pair%%:*} want=${pair#*:}
        if "$stipple" render "$m" -s 160x120 --backface --stats -o "$work/real.pgm" 2>"$work/err"; then
            n=$(sed -n 's/.*: \([0-9]*\) polygons (0 degenerate skipped).*/\1/p' "$work/err")
            greys=$(pnmtoplainpnm "$work/real.pgm" | tail -n +4 | tr -s ' \n' '\n' | grep . | sort -u | wc -l)
            if [ "$n" = "$want" ] && [ "$greys" -ge 2 ]; then ok
            else bad "$(basename "$m"): '$n' polygons (want $want), $greys greys"; fi
        else bad "$(basename "$m"): $(cat "$work/err")"; fi
    done
    # the same sphere as binary PLY of both byte orders (re-encoded by perl)
    # gives the same picture
    "$stipple" render "$meshes/sphere.ply" -s 96x96 -o "$work/sphere.pgm"
    for order in little big; do
        o='<'
        [ $order = big ] && o='>'
        perl -e '
            my ($o, $order) = @ARGV; my $body = 0;
            while (<STDIN>) {
                if (!$body) {
                    s/^format ascii/format binary_${order}_endian/;
                    print; $body = 1 if /^end_header/; next;
                }
                my @f = split;
                if (@f == 3) { print pack("d$o" x 3, @f) }
                else { my $n = shift @f; print pack("C", $n), pack("l$o" x $n, @f) }
            }' "$o" "$order" <"$meshes/sphere.ply" >"$work/sphere-$order.ply"
        "$stipple" render "$work/sphere-$order.ply" -s 96x96 -o "$work/sphere-$order.pgm" 2>"$work/err" ||
            bad "binary sphere ($order): $(cat "$work/err")"
        if cmp -s "$work/sphere.pgm" "$work/sphere-$order.pgm"; then ok
        else bad "sphere.ply as binary $order-endian renders differently"; fi
    done
else
    bad "no directory of fetched meshes given"
fi

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
