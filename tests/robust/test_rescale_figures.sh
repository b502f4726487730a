#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The figures docs/robust-inputs.md gives for how much a scene's units change
# its picture hold: rescale_figures.py measures the SPD files at scale 1
# against 10^4, and each measured maximum (share of pixels differing, largest
# difference in levels, pixels off by more than 16 levels) must be at most
# the bound of the document's line "<!-- rescale bound: P % L levels N pixels -->".
# Usage: test_rescale_figures.sh STIPPLE SOURCE_DIR WORK_DIR
set -u
stipple=$1 source=$2 work=$3
doc="$source/docs/robust-inputs.md"
bound=$(sed -n 's/^<!-- rescale bound: \([0-9.]*\) % \([0-9]*\) levels \([0-9]*\) pixels -->$/\1 \2 \3/p' "$doc")
[ -n "$bound" ] || { echo "FAIL: no '<!-- rescale bound: ... -->' line in $doc"; exit 1; }
python3 "$source/tests/robust/rescale_figures.py" "$stipple" "$work" "$source"/tests/data/spd/*.nff \
    >"$work.out" || { echo "FAIL: rescale_figures.py"; cat "$work.out"; exit 1; }
cat "$work.out"
measured=$(sed -n 's/^max: \([0-9.]*\) % \([0-9]*\) levels \([0-9]*\) pixels$/\1 \2 \3/p' "$work.out")
read -r bp bl bn <<<"$bound"
read -r mp ml mn <<<"$measured"
if awk -v mp="$mp" -v bp="$bp" -v ml="$ml" -v bl="$bl" -v mn="$mn" -v bn="$bn" \
        'BEGIN { exit !(mp <= bp && ml <= bl && mn <= bn) }'; then
    echo "measured $mp % $ml levels $mn pixels: within the documented $bp % $bl levels $bn pixels"
else
    echo "FAIL: measured $mp % $ml levels $mn pixels beyond the documented $bp % $bl levels $bn pixels"
    exit 1
fi
