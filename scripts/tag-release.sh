#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Tags a release: the annotated tag vMAJOR.MINOR.PATCH on COMMIT (default
# HEAD), the version read from that commit's include/stipple/version.h.
# Refuses when CHANGELOG.md at that commit has no "## [MAJOR.MINOR.PATCH]"
# heading, when the tag exists already (on another commit), or, for HEAD,
# when the work tree has uncommitted changes.  Pushing is left to the
# maintainer: git push origin vMAJOR.MINOR.PATCH.
# Usage: scripts/tag-release.sh [--check] [COMMIT]
#   --check  say what would be tagged, change nothing (exit 1 if refused)
set -eu
check=0
if [ "${1:-}" = --check ]; then check=1; shift; fi
commit=$(git rev-parse --verify "${1:-HEAD}^{commit}")
part() {
    git show "$commit:include/stipple/version.h" | sed -n "s/^#define STP_VERSION_$1 \([0-9][0-9]*\)\$/\1/p"
}
version="$(part MAJOR).$(part MINOR).$(part PATCH)"
case $version in
[0-9]*.[0-9]*.[0-9]*) ;;
*) echo "tag-release.sh: no version in $commit's include/stipple/version.h" >&2; exit 1 ;;
esac
tag=v$version
if ! git show "$commit:CHANGELOG.md" | grep -q "^## \[$version\]"; then
    echo "tag-release.sh: CHANGELOG.md at $commit has no '## [$version]' heading:" \
        "move the Unreleased entries under it first" >&2
    exit 1
fi
if existing=$(git rev-parse -q --verify "refs/tags/$tag^{commit}"); then
    if [ "$existing" = "$commit" ]; then
        echo "$tag is already $commit"
        exit 0
    fi
    echo "tag-release.sh: $tag exists already, on $existing" >&2
    exit 1
fi
if [ -z "${1:-}" ] && [ -n "$(git status --porcelain --untracked-files=no)" ]; then
    echo "tag-release.sh: the work tree has uncommitted changes" >&2
    exit 1
fi
if [ "$check" = 1 ]; then
    echo "would tag $commit as $tag"
    exit 0
fi
git tag -a "$tag" -m "stipple $version" "$commit"
echo "tagged $commit as $tag (publish it: git push origin $tag)"
