#!/bin/sh
# SPDX-License-Identifier: MIT
# The public functions of the core: every function declared by the headers
# of include/stipple/ (as the compiler sees them through stipple/stipple.h,
# gcc -aux-info; a constructor under its plain name), counted per header
# and in total.  With --internal, also those no code outside src/ calls
# (tools/, ports/, firmware/, tests/, docs/, README.md): helpers the core
# exports only for itself.
#
#   scripts/api_count.sh [--internal] [ROOT]
set -eu
internal=0
[ "${1:-}" = --internal ] && { internal=1; shift; }
root=$(cd "${1:-$(dirname "$0")/..}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo '#include "stipple/stipple.h"' >"$work/api.c"
"${CC:-cc}" -std=c99 -I "$root/include" -aux-info "$work/api.aux" -fsyntax-only "$work/api.c"
# "/* include/stipple/H.h:LINE:NC */ extern TYPE NAME (ARGS);": header and name
sed -n 's|^/\* [^ ]*include/stipple/\([a-z_0-9]*\.h\):[0-9]*:[A-Z]* \*/ .*[ *]\(stp_[a-z0-9_]*\) (.*|\1 \2|p' "$work/api.aux" |
    sed 's/_cfg_f[0-9a-z_]*$//' | sort -u >"$work/api"
awk '{ n[$1]++ } END { for (h in n) printf "%4d %s\n", n[h], h }' "$work/api" | sort -k2
echo "$(wc -l <"$work/api") public functions in $(cut -d' ' -f1 "$work/api" | sort -u | wc -l) headers"
if [ $internal = 1 ]; then
    echo "called only inside src/:"
    while read -r header name; do
        if ! grep -rqw "$name" "$root/tools" "$root/ports" "$root/firmware" "$root/tests" "$root/docs" "$root/README.md" 2>/dev/null; then
            echo "  $header $name"
        fi
    done <"$work/api"
fi
