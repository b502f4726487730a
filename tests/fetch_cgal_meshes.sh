#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetch two real PLY meshes from Debian's CGAL demo data, for the PLY part of
# tests/cli/test_cli_input.sh (run by CTest as the setup of the fixture
# "cgal_meshes").
#
#   tests/fetch_cgal_meshes.sh DATA_DIR
#
# libcgal-demo (about 24 MB) is fetched with apt-get download once per build
# tree; only data/meshes/sphere.ply (ASCII, 162 vertices, 320 triangles, by
# CGAL) and data/meshes/colored_tetra.ply (ASCII, vertex normals and colours,
# face colours and an edge element) are kept, as DATA_DIR/cgal/*.ply, and the
# package is deleted.  Any failed step is an error (exit 1): the test must
# not pass by skipping.
set -eu
data=${1:?usage: fetch_cgal_meshes.sh DATA_DIR}
fail() {
    echo "fetch_cgal_meshes.sh: FAIL: $*" >&2
    exit 1
}
for tool in apt-get dpkg-deb tar; do
    command -v "$tool" >/dev/null 2>&1 || fail "$tool is not available"
done
mkdir -p "$data/cgal"
cd "$data/cgal"
if [ -s sphere.ply ] && [ -s colored_tetra.ply ]; then
    echo "fetch_cgal_meshes.sh: ok (cached in $data/cgal)"
    exit 0
fi
rm -rf deb.tmp
mkdir deb.tmp
(cd deb.tmp && apt-get download libcgal-demo >/dev/null) || fail "apt-get download libcgal-demo failed"
set -- deb.tmp/libcgal-demo_*.deb
[ -f "$1" ] || fail "apt-get download left no libcgal-demo .deb"
# the meshes sit in a tarball inside the package
dpkg-deb --fsys-tarfile "$1" | tar -xO ./usr/share/doc/libcgal-dev/data.tar.gz |
    tar -xz -C deb.tmp data/meshes/sphere.ply data/meshes/colored_tetra.ply ||
    fail "no data/meshes/{sphere,colored_tetra}.ply in $1"
for m in sphere colored_tetra; do
    mv "deb.tmp/data/meshes/$m.ply" "$m.ply"
done
rm -rf deb.tmp
ls -l sphere.ply colored_tetra.ply
echo "fetch_cgal_meshes.sh: ok ($data/cgal)"
