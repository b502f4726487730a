#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The man page and the bash completion (run by CTest):
#  1. stipple.1 (built by help2man) is valid roff (groff -ww: no warnings),
#     names the version of --version, and has a section for every
#     subcommand the main help lists, holding that subcommand's options;
#  2. the completion offers, for every subcommand, exactly the long options
#     its --help prints; completes subcommands, option values and scene
#     files by extension;
#  3. `cmake --install --component cli` puts the command, the man page and
#     the completion under bin/, share/man/man1/ and
#     share/bash-completion/completions/.
# Usage: test_cli_docs.sh STIPPLE_BINARY MAN_PAGE COMPLETION_FILE BUILD_DIR
set -u
stipple=$1
man=$2
completion=$(realpath "$3")
build=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

commands=$("$stipple" --help | sed -n 's/^  \([a-z][a-z]*\) .*/\1/p' | grep -vx help)
[ -n "$commands" ] || bad "no commands in the main help"
# the options a help defines: its lines "  -x, --name ..." or "      --name ..."
long_options() {
    "$stipple" "$1" --help | grep -oE -- '^ +(-[a-zA-Z], )?--[a-z][a-z0-9-]*' |
        grep -oE -- '--[a-z][a-z0-9-]*' | sort -u
}

# --- 1. the man page
if [ ! -s "$man" ]; then
    bad "no man page at $man"
else
    if groff -man -Tutf8 -ww -z "$man" 2>"$work/groff" && [ ! -s "$work/groff" ]; then ok
    else bad "groff warns: $(head -n 5 "$work/groff")"; fi
    version=$("$stipple" --version | cut -d' ' -f2)
    if grep -q "^\.TH STIPPLE \"1\" .*\"stipple $version\"" "$man"; then ok; else bad "man page lacks version $version"; fi
    man -l "$man" 2>/dev/null | col -b >"$work/man.txt"
    for cmd in $commands; do
        upper=$(echo "$cmd" | tr '[:lower:]' '[:upper:]')
        # the section, from its heading to the next one
        sed -n "/^COMMAND $upper\$/,/^[A-Z]/p" "$work/man.txt" >"$work/section"
        if [ ! -s "$work/section" ]; then bad "man page: no section for $cmd"; continue; fi
        missing=$(comm -23 <(long_options "$cmd") <(grep -o -- '--[a-z][a-z0-9-]*' "$work/section" | sort -u))
        if [ -z "$missing" ]; then ok; else bad "man page section $cmd lacks $missing"; fi
    done
fi

# --- 2. the completion
complete_words() { # WORD... (the last one is being completed)
    bash -c '
        source "$1"; shift
        COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
        _stipple
        printf "%s\n" "${COMPREPLY[@]}"' completion "$completion" stipple "$@" | sort
}
for cmd in $commands; do
    if diff <(complete_words "$cmd" --) <(long_options "$cmd") >"$work/diff"; then ok
    else bad "completion of '$cmd --' differs from its --help (< completion, > help): $(cat "$work/diff")"; fi
done
[ "$(complete_words ren)" = render ] && ok || bad "subcommand 'ren' does not complete to render"
[ "$(complete_words help com)" = compile ] && ok || bad "help com"
[ "$(complete_words render x.nff --hidden "" | tr '\n' ' ')" = "none painter zbuffer " ] && ok || bad "--hidden values"
[ "$(complete_words render x.nff --scene-format p)" = ply ] && ok || bad "--scene-format values"
[ "$(complete_words render x.nff --format png | tr '\n' ' ')" = "png png1 " ] && ok || bad "--format values"
mkdir -p "$work/scenes/sub"
touch "$work/scenes/a.nff" "$work/scenes/b.PLY" "$work/scenes/c.txt" "$work/scenes/d.png"
got=$(cd "$work" && complete_words render scenes/ | tr '\n' ' ')
[ "$got" = "scenes/a.nff scenes/b.PLY scenes/sub " ] && ok || bad "scene files: '$got'"
got=$(cd "$work" && complete_words dither scenes/ | tr '\n' ' ')
[ "$got" = "scenes/d.png scenes/sub " ] && ok || bad "image files: '$got'"

# --- 3. installation
if cmake --install "$build" --prefix "$work/prefix" --component cli >"$work/install.log" 2>&1; then
    for f in bin/stipple share/man/man1/stipple.1 share/bash-completion/completions/stipple; do
        if [ -s "$work/prefix/$f" ]; then ok; else bad "not installed: $f"; fi
    done
    if cmp -s "$work/prefix/share/man/man1/stipple.1" "$man" &&
        cmp -s "$work/prefix/share/bash-completion/completions/stipple" "$completion"; then ok
    else bad "installed man page or completion differ from the built ones"; fi
    if "$work/prefix/bin/stipple" --version >/dev/null; then ok; else bad "installed stipple does not run"; fi
else
    bad "cmake --install failed: $(tail -n 5 "$work/install.log")"
fi

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
