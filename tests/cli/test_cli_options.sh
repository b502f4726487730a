#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The stipple command's option handling (run by CTest):
#  1. options the chosen renderer does not read are refused (exit 2, the
#     option named, nothing written); so are options the output does not use;
#  2. every subcommand has its own help (COMMAND --help and help COMMAND give
#     the same text, which starts with "usage: stipple COMMAND");
#  3. usage errors are at most two lines, the last "Try 'stipple CMD --help'";
#  4. --depth's error gives the real bound (STP_RT_MAX_DEPTH of config.h);
#  5. default levels: .pgm/.ppm 256 (the same picture as -l 256, not as
#     -l 16), .pbm 16 (the same as -l 16), text 16.
# Usage: test_cli_options.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
scene=$scenes/tetra-s1.nff

# usage_error CMD EXPECTED_SUBSTRING ARGS...: exit 2, a short message naming
# the problem, the Try line last, no output file.
usage_error() {
    local cmd=$1 want=$2
    shift 2
    rm -f "$work/out."*
    "$stipple" "$@" 2>"$work/err" >"$work/stdout"
    local rc=$?
    local try="Try 'stipple${cmd:+ $cmd} --help'"
    if [ "$rc" != 2 ]; then
        bad "'$*': exit status $rc, want 2"
    elif ! grep -qF -- "$want" "$work/err"; then
        bad "'$*': message lacks '$want': $(cat "$work/err")"
    elif [ "$(wc -l <"$work/err")" -gt 2 ] || [ "$(tail -n 1 "$work/err")" != "$try" ]; then
        bad "'$*': not a short error ending with \"$try\": $(cat "$work/err")"
    elif [ -s "$work/stdout" ] || ls "$work"/out.* >/dev/null 2>&1; then
        bad "'$*': wrote something"
    else ok; fi
}

# --- 1. options the renderer or the output does not use
for o in "--shadows 64" "--hidden painter" "--smooth" "--backface" "--no-shading" \
         "--transparent" "--slices 8" "--stacks 4" "--edge-aa"; do
    # shellcheck disable=SC2086
    usage_error render "${o%% *} is an option of the polygon renderer" \
        render "$scene" --raytrace $o -o "$work/out.pbm"
done
usage_error render "--hidden, --smooth, --shadows are options of the polygon renderer" \
    render "$scene" --raytrace --shadows 64 --hidden painter --smooth -o "$work/out.pbm"
for o in "--depth 2" "--min-weight 0.5" "--no-hierarchy"; do
    # shellcheck disable=SC2086
    usage_error render "${o%% *} is an option of the ray tracer" render "$scene" $o -o "$work/out.pbm"
    # shellcheck disable=SC2086
    usage_error compile "${o%% *} is an option of the ray tracer" compile "$scene" $o -o "$work/out.c"
done
usage_error compile "--edge-aa is not supported for compiled scenes" compile "$scene" --edge-aa -o "$work/out.c"
# --edge-aa changes the grey picture and keeps its size and format
if "$stipple" render "$scene" --edge-aa -s 64x32 -o "$work/aa.pgm" &&
        "$stipple" render "$scene" -s 64x32 -o "$work/plain.pgm" &&
        [ "$(head -c 15 "$work/aa.pgm")" = "$(head -c 15 "$work/plain.pgm")" ] &&
        ! cmp -s "$work/aa.pgm" "$work/plain.pgm"; then ok
else bad "render --edge-aa: no picture, or the same as without"; fi
usage_error render "--dither halftones 1-bit pictures" render "$scene" -d bayer8 -o "$work/out.pgm"
usage_error render "--spacing halftones 1-bit pictures" render "$scene" --spacing cubic -o "$work/out.ppm"
usage_error render "--levels: text has 16 levels" render "$scene" -l 8 -o "$work/out.txt"
usage_error render "at most 255 levels" render "$scene" --palette grey -l 256 -o "$work/out.ppm"
# ... while the options each renderer does read are taken
if "$stipple" render "$scene" --raytrace --depth 2 --min-weight 0.1 --no-hierarchy -s 32x16 \
        -o "$work/rt.pbm" && "$stipple" render "$scene" --hidden painter --smooth --shadows 16 \
        --backface -d bayer8 --spacing cubic -s 32x16 -o "$work/poly.pbm"; then ok
else bad "options of the renderer in use refused"; fi

# --- 2. help for every subcommand
for cmd in render dither compile bench help; do
    "$stipple" "$cmd" --help >"$work/h1" 2>"$work/e1"
    rc1=$?
    "$stipple" help "$cmd" >"$work/h2" 2>"$work/e2"
    rc2=$?
    if [ $rc1 != 0 ] || [ $rc2 != 0 ] || [ -s "$work/e1" ] || [ -s "$work/e2" ]; then
        bad "help $cmd: exit $rc1/$rc2 or stderr"
    elif ! head -n 1 "$work/h2" | grep -q "^usage: stipple $cmd"; then
        bad "help $cmd: prints '$(head -n 1 "$work/h2")'"
    elif ! cmp -s "$work/h1" "$work/h2"; then
        bad "$cmd --help and help $cmd differ"
    else ok; fi
done
if "$stipple" help | head -n 1 | grep -q '^usage: stipple COMMAND'; then ok; else bad "help"; fi
usage_error "" "no command 'frobnicate'" help frobnicate
usage_error "" "unknown command 'frobnicate'" frobnicate
usage_error "" "no command given"

# --- 3. usage errors of each subcommand
usage_error render "unknown option '--bogus'" render "$scene" --bogus -o "$work/out.pbm"
usage_error render "unknown option '-x'" render "$scene" -x -o "$work/out.pbm"
usage_error render "option '--size' needs a value" render "$scene" -o "$work/out.pbm" --size
usage_error render "no scene given" render -o "$work/out.pbm"
usage_error render "one scene only" render "$scene" "$scene" -o "$work/out.pbm"
usage_error render "no output given" render "$scene"
usage_error render "bad --levels" render "$scene" -l 1 -o "$work/out.pbm"
usage_error render "unknown output extension" render "$scene" -o "$work/out.jpeg"
usage_error dither "unknown option '--bogus'" dither "$work/none.pgm" --bogus -o "$work/out.pbm"
usage_error dither "no image given" dither -o "$work/out.pbm"
usage_error compile "no output given" compile "$scene"
usage_error compile "unknown option '--bogus'" compile "$scene" --bogus -o "$work/out.c"
usage_error bench "bad --budget" bench --budget 0

# --- 4. --depth names its real bound
max=$(awk '/^#define STP_RT_MAX_DEPTH /{print $3}' "$here/../../include/stipple/config.h")
usage_error render "bad --depth (0..$max): '$((max + 1))'" render "$scene" --raytrace --depth $((max + 1)) -o "$work/out.pbm"
if "$stipple" render "$scene" --raytrace --depth "$max" -s 16x16 -o "$work/d.pbm"; then ok
else bad "--depth $max refused"; fi

# --- 5. default levels by output
r() { "$stipple" render "$scenes/teapot-s1.nff" -s 96x64 "$@"; }
for ext in pgm ppm; do
    r -o "$work/def.$ext" && r -l 256 -o "$work/l256.$ext" && r -l 16 -o "$work/l16.$ext" ||
        bad ".$ext renders"
    if cmp -s "$work/def.$ext" "$work/l256.$ext" && ! cmp -s "$work/def.$ext" "$work/l16.$ext"; then ok
    else bad ".$ext: default is not 256 levels"; fi
done
greys=$(pnmtoplainpnm "$work/def.pgm" | tail -n +4 | tr -s ' \n' '\n' | grep . | sort -u | wc -l)
if [ "$greys" -gt 16 ]; then ok; else bad ".pgm default has only $greys greys"; fi
# a still 1-bit picture file is diffused at 256 levels (README, Dithering)
r -o "$work/def.pbm" && r -d fs:blue -l 256 -o "$work/fs256.pbm" && r -d bayer4 -l 16 -o "$work/b16.pbm" ||
    bad ".pbm renders"
if cmp -s "$work/def.pbm" "$work/fs256.pbm" && ! cmp -s "$work/def.pbm" "$work/b16.pbm"; then ok
else bad ".pbm: default is not Floyd-Steinberg at 256 levels"; fi
r -o "$work/def.txt" && r -l 16 -o "$work/l16.txt" || bad ".txt renders"
if cmp -s "$work/def.txt" "$work/l16.txt"; then ok; else bad ".txt: default is not 16 levels"; fi
# the ray tracer too
"$stipple" render "$scenes/balls-s1.nff" --raytrace -s 64x64 -o "$work/rt.pgm" &&
    "$stipple" render "$scenes/balls-s1.nff" --raytrace -s 64x64 -l 256 -o "$work/rt256.pgm" || bad "rt .pgm"
if cmp -s "$work/rt.pgm" "$work/rt256.pgm"; then ok; else bad "ray-traced .pgm: default is not 256 levels"; fi

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
