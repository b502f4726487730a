#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Render every mesh file in a format stipple reads that Debian's
# assimp-testmodels, geomview and brutalchess packages ship (names ending
# .obj, .off, .ply or .nff in any case, and files whose first word is an OFF
# header such as geomview's extensionless OFF files, read as OFF), each
# with a time limit, and sort the outcomes:
#   rendered  exit 0 and a picture with something drawn (counted apart:
#             how many show two or more grey levels; a flat single polygon
#             shows one)
#   refused   exit 1 and a message "stipple: FILE:LINE: ..." or
#             "stipple: FILE: ..." naming the file
#   BLANK     exit 0 but nothing drawn
#   CRASHED   anything else: a signal, a sanitizer report, a time-out, a
#             message without the file's name
# The packages are fetched with `apt-get download` (no install) and unpacked
# with dpkg-deb -x into a temporary folder.  Use the command of a build with
# -DSTP_SANITIZE=ON to render under AddressSanitizer + UBSan.
#
# Usage: debian_meshes.sh STIPPLE [WORK_DIR]
#   STP_MESH_TIMEOUT  seconds per file (default 60)
#   STP_MESH_RAYTRACE 1: ray-trace too (each file twice)
# Exit status: 0 when nothing is BLANK or CRASHED (and some file rendered),
# 1 otherwise; 77 when the packages cannot be downloaded.
set -u
stipple=$(realpath "$1")
work=${2:-$(mktemp -d)}
timeout_s=${STP_MESH_TIMEOUT:-60}
packages=(assimp-testmodels geomview brutalchess)
mkdir -p "$work/debs" "$work/root" "$work/out"
work=$(realpath "$work")

if ! (cd "$work/debs" && apt-get download "${packages[@]}" >"$work/download.log" 2>&1); then
    echo "debian_meshes: cannot download ${packages[*]} (apt-get download): skipped" >&2
    tail -n 3 "$work/download.log" >&2
    exit 77
fi
for deb in "$work"/debs/*.deb; do
    dpkg-deb -x "$deb" "$work/root" || exit 1
done

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
rendered=0 shaded=0 refused=0 blank=0 crashed=0
modes=(render)
[ "${STP_MESH_RAYTRACE:-0}" = 1 ] && modes+=(raytrace)

# distinct grey levels other than the background (the first pixel's level)
greys() {
    python3 -c '
import sys
d = open(sys.argv[1], "rb").read()
parts = d.split(b"\n", 3)
px = parts[3]
bg = px[0] if px else 0
print(len(set(px) - {bg}))' "$1"
}

# the files: by name, and OFF files by their first word
list_files() {
    find "$work/root" -type f \( -iname '*.obj' -o -iname '*.off' -o -iname '*.ply' -o -iname '*.nff' \) \
        -printf '%p\t\n'
    find "$work/root" -type f ! -iname '*.off' -size -20M -print0 |
        while IFS= read -r -d '' f; do
            word=$(head -c 64 "$f" | tr -d '\0' | head -n 1 | awk '{print $1}')
            case "$word" in
            OFF|COFF|NOFF|CNOFF) printf '%s\toff\n' "$f" ;;
            esac
        done
}

while IFS=$'\t' read -r f format; do
    for mode in "${modes[@]}"; do
        extra=()
        [ "$mode" = raytrace ] && extra+=(--raytrace)
        [ -n "$format" ] && extra+=(--scene-format "$format")
        out="$work/out/picture.pgm"
        rm -f "$out"
        timeout "$timeout_s" "$stipple" render "$f" -o "$out" -s 96x72 "${extra[@]}" \
            >"$work/out/stdout" 2>"$work/out/stderr"
        rc=$?
        name=${f#"$work/root/"}
        if [ "$rc" = 0 ] && [ -s "$out" ]; then
            g=$(greys "$out")
            if [ "$g" -ge 1 ]; then
                rendered=$((rendered + 1))
                [ "$g" -ge 2 ] && shaded=$((shaded + 1))
            else
                blank=$((blank + 1))
                echo "BLANK    $mode $name"
            fi
        elif [ "$rc" = 1 ] && grep -qF "stipple: $f:" "$work/out/stderr" &&
                ! grep -q "Sanitizer\|runtime error" "$work/out/stderr"; then
            refused=$((refused + 1))
            echo "refused  $mode $name: $(head -n 1 "$work/out/stderr" | head -c 200 | sed "s|$work/root/||")"
        else
            crashed=$((crashed + 1))
            echo "CRASHED  $mode $name (exit $rc): $(grep -m1 -E 'ERROR|runtime error|stipple' "$work/out/stderr" | head -c 300)"
        fi
    done
done < <(list_files | sort)

echo "debian meshes (${packages[*]}): $rendered rendered ($shaded with two or more grey levels)," \
     "$refused refused, $blank blank, $crashed crashed"
[ "$blank" = 0 ] && [ "$crashed" = 0 ] && [ "$rendered" -gt 0 ]
