#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Apply scripts/rename-api.sed (issue 12's module-first names) to every file
# git tracks, except the files that must keep the old names: the deprecated
# macros and their test, the changelog that lists them, and the rename
# scripts themselves.
# Usage: scripts/rename-api.sh [REPOSITORY]   (default: this checkout)
set -eu
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
git ls-files -z -- . ':!include/stipple/deprecated.h' ':!tests/core/test_deprecated.c' ':!CHANGELOG.md' ':!scripts/rename-api.sed' \
    ':!scripts/rename-api.sh' |
    xargs -0 grep -lIZ 'stp_' -- 2>/dev/null |
    xargs -0 -r sed -i -f scripts/rename-api.sed
