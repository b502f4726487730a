#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# stipple animate and the camera options of render (run by CTest):
#  1. numbered PBM and PNG frames: N files, numbered from 0;
#  2. the GIF holds exactly those frames (decoded by ImageMagick, pixel for
#     pixel), loops, and its later frames are the changed rectangles only;
#  3. --stats: 1 degree a frame changes at most 1 % of the pixels;
#  4. render --eye/--at draws exactly the frame animate draws from there
#     (a path of two --eye keys: the middle frame is the midpoint); the
#     scene's own view given as --eye/--at/--up changes nothing;
#  5. bad values: exit 2, the option named, nothing written.
# Usage: test_cli_animate.sh STIPPLE_BINARY SCENES_DIR
set -u
stipple=$1
scenes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
scene=$scenes/tetra-s1.nff

# --- 1. numbered frames
if "$stipple" animate "$scene" -o "$work/f%03d.pbm" --frames 5 --orbit 40 &&
        [ -f "$work/f000.pbm" ] && [ -f "$work/f004.pbm" ] && [ ! -e "$work/f005.pbm" ] &&
        [ "$(head -c 2 "$work/f000.pbm")" = P4 ] && ! cmp -s "$work/f000.pbm" "$work/f004.pbm"; then ok
else bad "animate -o f%03d.pbm: not 5 different PBM frames f000..f004"; fi
if "$stipple" animate "$scene" -o "$work/p%d.png" --frames 2 --orbit 40 &&
        [ "$(identify -format '%[bit-depth] %w %h' "$work/p1.png")" = "1 128 64" ]; then ok
else bad "animate -o p%d.png: not 1-bit 128x64 PNG frames"; fi

# --- 2. the GIF: the same frames
if "$stipple" animate "$scene" -o "$work/a.gif" --frames 5 --orbit 40 --fps 25 2>"$work/err"; then
    n=$(identify "$work/a.gif" | wc -l)
    [ "$n" = 5 ] && ok || bad "a.gif holds $n frames, want 5"
    # later frames: the changed rectangle, smaller than the screen
    if identify -format '%w %h\n' "$work/a.gif" | sed -n 2p | grep -vq '^128 64$'; then ok
    else bad "a.gif: the second frame is not a rectangle of changes"; fi
    [ "$(identify -format '%T\n' "$work/a.gif" | head -n 1)" = 4 ] && ok || bad "a.gif: delay not 4/100 s at --fps 25"
    grep -q NETSCAPE2.0 "$work/a.gif" && ok || bad "a.gif does not loop"
    convert "$work/a.gif" -coalesce "$work/g%d.pbm"
    for i in 0 1 2 3 4; do
        d=$(compare -metric AE "$work/g$i.pbm" "$work/f00$i.pbm" null: 2>&1)
        [ "$d" = 0 ] && ok || bad "GIF frame $i differs from f00$i.pbm in $d pixels"
    done
else bad "animate -o a.gif failed: $(cat "$work/err")"; fi

# --- 3. --stats: the changing pixels
if "$stipple" animate "$scene" -o "$work/s%d.pbm" --frames 11 --orbit 11 --stats 2>"$work/stats"; then
    share=$(sed -n 's/.*, \([0-9.]*\) % of pixels change.*/\1/p' "$work/stats")
    if [ -n "$share" ] && awk -v s="$share" 'BEGIN { exit !(s > 0 && s <= 1) }'; then ok
    else bad "--stats: '$(cat "$work/stats")' (want a share in (0, 1] %)"; fi
else bad "animate --stats failed"; fi

# --- 4. render from a camera = the animation's frame from there
common=(-d blue-noise -l 256 --exposure off)
if "$stipple" animate "$scene" "${common[@]}" --hold 0 --eye 4,0,0 --eye 0,4,2 --at 0,0,0.2 \
        --frames 3 -o "$work/k%d.pbm" &&
        "$stipple" render "$scene" "${common[@]}" --eye 2,2,1 --at 0,0,0.2 -o "$work/mid.pbm" &&
        cmp -s "$work/k1.pbm" "$work/mid.pbm" && ! cmp -s "$work/k0.pbm" "$work/mid.pbm"; then ok
else bad "render --eye (the midpoint of two keys) differs from animate's middle frame"; fi
if "$stipple" render "$scene" -o "$work/own.pbm" &&
        "$stipple" render "$scene" --eye 1.02285,-3.17715,-2.17451 --at -0.004103,-0.004103,0.216539 \
            --up -0.816497,-0.816497,0.816497 -o "$work/given.pbm" && cmp -s "$work/own.pbm" "$work/given.pbm"; then ok
else bad "render with the scene's own view as --eye/--at/--up differs from render"; fi

# --- 5. bad values
usage_error() {
    local cmd=$1 want=$2
    shift 2
    rm -f "$work/out"*
    "$stipple" "$@" 2>"$work/err" >"$work/stdout"
    local rc=$?
    if [ "$rc" != 2 ]; then bad "'$*': exit status $rc, want 2"
    elif ! grep -qF -- "$want" "$work/err"; then bad "'$*': message lacks '$want': $(cat "$work/err")"
    elif ls "$work"/out* >/dev/null 2>&1; then bad "'$*': wrote something"
    else ok; fi
}
usage_error animate "bad --frames '0' (1..10000)" animate "$scene" --frames 0 -o "$work/out.gif"
usage_error animate "give NAME.gif, or a pattern" animate "$scene" -o "$work/out.txt"
usage_error animate "give NAME.gif, or a pattern" animate "$scene" -o "$work/out%d%d.pbm"
usage_error animate "bad --eye '1,2'" animate "$scene" --eye 1,2 -o "$work/out.gif"
usage_error animate "bad --elevation '95'" animate "$scene" --elevation 95 -o "$work/out.gif"
usage_error animate "bad --up '0,0,0'" animate "$scene" --up 0,0,0 -o "$work/out.gif"
usage_error animate "bad --hold '-1'" animate "$scene" --hold -1 -o "$work/out.gif"
usage_error animate "no output given" animate "$scene"
usage_error render "--eye given twice" render "$scene" --eye 1,2,3 --eye 1,2,4 -o "$work/out.pbm"
"$stipple" render "$scene" --eye 0,0,0.2 --at 0,0,0.2 -o "$work/out.pbm" 2>"$work/err"
rc=$?
if [ $rc = 1 ] && grep -q "on the look-at point" "$work/err" && [ ! -e "$work/out.pbm" ]; then ok
else bad "render with the eye on the look-at point: exit $rc, '$(cat "$work/err")'"; fi

echo "$passes passed, $failures failed"
[ "$failures" = 0 ]
