#!/bin/sh
# SPDX-License-Identifier: MIT
# The stipple(1) man page, generated from the command's own help by help2man
# (run by the build: the page cannot drift from --help).  The main --help
# gives NAME, SYNOPSIS and DESCRIPTION; each subcommand's --help becomes a
# section of its own, kept as printed (.nf).
# Usage: make_manpage.sh STIPPLE_BINARY OUTPUT.1
set -eu
stipple=$1
out=$2
include=$out.include
{
    printf '[NAME]\nstipple \\- halftoned pictures of 3D polygon scenes for 1-bit panels, grey and colour framebuffers\n'
    # the commands the main help lists ("  NAME ARGS  what it does")
    for cmd in $("$stipple" --help | sed -n 's/^  \([a-z][a-z]*\) .*/\1/p' | grep -vx help); do
        upper=$(echo "$cmd" | tr '[:lower:]' '[:upper:]')
        printf '[COMMAND %s]\n.nf\n' "$upper"
        # a leading dot or quote would be read as a roff request; \ as an escape
        "$stipple" "$cmd" --help | sed -e 's/\\/\\e/g' -e "s/^\\([.']\\)/\\\\\\&\\1/"
        printf '.fi\n'
    done
    printf '[SEE ALSO]\nThe README and docs/ of the stipple source tree.\n'
} >"$include"
help2man --no-info --include="$include" --output="$out.tmp" "$stipple"
mv "$out.tmp" "$out"
rm -f "$include"
