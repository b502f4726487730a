#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Faults the command must report rather than exit 0 through:
#  - help and version texts that cannot be written (stdout closed, or a
#    full device): exit status non-zero and a message on stderr;
#  - a build with tests but without help2man (no man page for test_cli_docs
#    to check): configuring stops with a message naming help2man.
# Usage: test_cli_faults.sh STIPPLE SOURCE_DIR WORK_DIR
set -u
stipple=$1
source=$2
work=$3
failures=0
bad() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
mkdir -p "$work"

for args in "--help" "--version" "help render" "render --help" "help"; do
    # shellcheck disable=SC2086
    "$stipple" $args >&- 2>"$work/err"
    rc=$?
    [ "$rc" != 0 ] || bad "stipple $args with stdout closed exited 0"
    grep -q "standard output" "$work/err" || bad "stipple $args with stdout closed: no message"
    if [ -w /dev/full ]; then
        # shellcheck disable=SC2086
        "$stipple" $args >/dev/full 2>"$work/err"
        [ $? != 0 ] || bad "stipple $args > /dev/full exited 0"
    fi
    # shellcheck disable=SC2086
    "$stipple" $args >/dev/null 2>"$work/err" || bad "stipple $args > /dev/null failed"
done

# configuring the tests without help2man (its cache entry says not found)
rm -rf "$work/no-help2man"
if cmake -S "$source" -B "$work/no-help2man" -DSTP_HELP2MAN=STP_HELP2MAN-NOTFOUND \
        >"$work/cmake.out" 2>&1; then
    bad "configured with the tests on and no help2man"
else
    grep -q "help2man not found" "$work/cmake.out" || bad "no help2man message: $(tail -n 5 "$work/cmake.out")"
fi
rm -rf "$work/no-help2man"

[ "$failures" = 0 ] || exit 1
echo "cli faults: all pass"
