#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Renders every mesh (.obj .off .nff) of a few Debian packages with the
# stipple command, flat and ray-traced: each run must either exit 0 with a
# file pamvalidate accepts or exit 1 with a "file: ..." message; a crash,
# a signal, a hang (60 s) or an invalid file with exit 0 fails.  The
# packages are fetched with apt-get download into WORK (never committed).
# usage: tests/robust/mesh_corpus.sh STIPPLE WORK [PACKAGE...]
# (default packages: assimp-testmodels geomview)
set -u
stipple=${1:?usage: mesh_corpus.sh STIPPLE WORK [PACKAGE...]}
work=${2:?usage: mesh_corpus.sh STIPPLE WORK [PACKAGE...]}
shift 2
packages=("$@")
[ ${#packages[@]} -eq 0 ] && packages=(assimp-testmodels geomview)
mkdir -p "$work/debs" "$work/root" "$work/out" || exit 1
(cd "$work/debs" && apt-get download "${packages[@]}") >/dev/null || exit 1
for deb in "$work"/debs/*.deb; do dpkg-deb -x "$deb" "$work/root" || exit 1; done
ok=0 refused=0 bad=0
while IFS= read -r -d '' mesh; do
    for mode in flat raytrace; do
        args=()
        [ $mode = raytrace ] && args=(--raytrace)
        out="$work/out/last.pgm"
        rm -f "$out"
        timeout 60 "$stipple" render "$mesh" "${args[@]}" --size 64x48 -o "$out" 2> "$work/err"
        rc=$?
        if [ $rc -eq 0 ] && pamvalidate < "$out" >/dev/null 2>&1; then
            ok=$((ok + 1))
        elif [ $rc -eq 1 ] && grep -q "^stipple: .*: " "$work/err"; then
            refused=$((refused + 1))
            echo "refused ($mode): $(head -c 300 "$work/err")"
        else
            bad=$((bad + 1))
            echo "BAD ($mode, exit $rc): $mesh: $(head -c 300 "$work/err")"
        fi
    done
done < <(find "$work/root" -type f \( -iname '*.obj' -o -iname '*.off' -o -iname '*.nff' \) -print0 | sort -z)
echo "rendered $ok, refused with a message $refused, bad $bad"
[ $bad -eq 0 ]
