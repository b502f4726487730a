#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# No file of the repository points at files that are not in it (the
# specification and design notes that lived beside the checkout, test files
# that moved).  Lists them and fails; with --fix rewrites them with
# scripts/fix-spec-refs.sed instead (run it after merging branches).
# Usage: check_refs.sh SOURCE_DIR [--fix]
set -u
cd "$1" || exit 2
stale='SPEC\.md|shared/DESIGN\.md|tests/test_raster\.c|tests/test_gamma\.c|=/work/shared/scenes/'
list() {
    grep -rlE "$stale" --exclude-dir=.git --exclude-dir='build*' --exclude-dir=out \
        --exclude=fix-spec-refs.sed --exclude=check_refs.sh . || true
}
if [ "${2:-}" = --fix ]; then
    list | while IFS= read -r f; do sed -i -f scripts/fix-spec-refs.sed "$f" && echo "fixed $f"; done
fi
files=$(list)
if [ -n "$files" ]; then
    # shellcheck disable=SC2086
    grep -nE "$stale" $files
    echo "stale references (above): run tests/model/check_refs.sh SOURCE_DIR --fix" >&2
    exit 1
fi
echo "no stale references"
