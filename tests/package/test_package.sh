#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# stipple as a package, the way a user's project meets it:
#   find_package    cmake --install into a temporary prefix, then a C and a
#                   C++ consumer configured with find_package(stipple)
#   pkg-config      the same prefix, the consumers compiled with
#                   `pkg-config --cflags --libs`; and an application compiled
#                   with another configuration than the library's must fail
#                   to link, naming the configuration (config_guard.h)
#   subdirectory    a project that add_subdirectory()s the source tree: only
#                   the libraries are configured (no cmocka, no tools), its
#                   own files are compiled without -Werror, and a
#                   configuration given to stipple reaches them
#   without-png     the consumer's build line of docs/packaging.md (no tools,
#                   tests or bench) as on a machine without libpng-dev
#                   (CMAKE_DISABLE_FIND_PACKAGE_PNG): every archive it builds
#                   is installed, and a project linking stipple::core alone
#                   configures and builds through find_package and through
#                   add_subdirectory
#   (find_package also asks for the component png and writes a PNG;
#   pkg-config also builds a library with STP_CONFIG_DEFINITIONS and
#   STP_CONFIG_HEADER and compiles a consumer with nothing but its flags)
# Each consumer renders a square and checks pixels (exit 1 when wrong).
# Usage: test_package.sh MODE BUILD_DIR SOURCE_DIR CC CXX
# CFLAGS, CXXFLAGS, LDFLAGS from the environment reach every consumer (the
# sanitizer build's library needs its runtime).
set -u
CFLAGS=${CFLAGS:-} CXXFLAGS=${CXXFLAGS:-} LDFLAGS=${LDFLAGS:-}
export CFLAGS CXXFLAGS LDFLAGS
mode=$1 build=$2 src=$3 cc=$4 cxx=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

install_tree() {
    cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" 2>&1 ||
        { cat "$work/install.log"; fail "cmake --install"; }
    for f in include/stipple/stipple.h lib/libstipple.a lib/cmake/stipple/stippleConfig.cmake "$@" \
             lib/cmake/stipple/stippleConfigVersion.cmake lib/pkgconfig/stipple.pc; do
        [ -f "$work/prefix/$f" ] || fail "the install has no $f"
    done
}

run() { # NAME PROGRAM [ARGUMENTS]
    local out name=$1
    shift
    out=$("$@" 2>&1) || { echo "$out"; fail "$name: the consumer's picture is wrong"; }
    echo "ok: $name: $out"
}

case $mode in
find_package)
    install_tree lib/libstipple_posix_png.a lib/cmake/stipple/stipplePngTargets.cmake
    cmake -S "$src/tests/package/consumer" -B "$work/consumer" -DCMAKE_C_COMPILER="$cc" \
          -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "configuring the find_package consumer"; }
    cmake --build "$work/consumer" >"$work/log" 2>&1 || { cat "$work/log"; fail "building the find_package consumer"; }
    run "find_package C" "$work/consumer/consumer_c"
    run "find_package C++" "$work/consumer/consumer_cxx"
    # a version the package does not satisfy is refused
    mkdir -p "$work/v"
    printf 'cmake_minimum_required(VERSION 3.20)\nproject(v LANGUAGES C)\nfind_package(stipple 99.0 REQUIRED)\n' \
        >"$work/v/CMakeLists.txt"
    if cmake -S "$work/v" -B "$work/v/build" -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/log" 2>&1; then
        fail "find_package(stipple 99.0) was satisfied"
    fi
    echo "ok: find_package(stipple 99.0) refused"
    # the PNG component: stipple::posix_png, with libpng found for the consumer
    cmake -S "$src/tests/package/png" -B "$work/png" -DCMAKE_C_COMPILER="$cc" \
          -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "configuring the COMPONENTS png consumer"; }
    cmake --build "$work/png" >"$work/log" 2>&1 || { cat "$work/log"; fail "building the COMPONENTS png consumer"; }
    "$work/png/consumer_png" "$work/out.png" || fail "the PNG consumer"
    ;;
without-png)
    # the consumer's build line, as a top-level build of the libraries alone
    cmake -S "$src" -B "$work/lib" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=Release \
          -DSTP_BUILD_TOOLS=OFF -DSTP_BUILD_TESTS=OFF -DSTP_WITH_LINUX=OFF \
          -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "configuring the libraries with -DSTP_BUILD_TOOLS=OFF and no libpng"; }
    cmake --build "$work/lib" >"$work/log" 2>&1 || { cat "$work/log"; fail "building the libraries"; }
    cmake --install "$work/lib" --prefix "$work/prefix" >"$work/log" 2>&1 || { cat "$work/log"; fail "installing"; }
    built=$(find "$work/lib" -name '*.a' -printf '%f\n' | sort | tr '\n' ' ')
    installed=$(find "$work/prefix" -name '*.a' -printf '%f\n' | sort | tr '\n' ' ')
    [ "$built" = "$installed" ] || fail "built archives ($built) are not the installed ones ($installed)"
    echo "ok: built and installed: $built"
    execs=$(find "$work/lib" -type f -perm -u+x ! -path '*/CMakeFiles/*' -printf '%f ')
    [ -z "$execs" ] || fail "the libraries' build built programs: $execs"
    [ -e "$work/prefix/lib/cmake/stipple/stipplePngTargets.cmake" ] && fail "a PNG export without libpng"
    for how in find_package subdirectory; do
        args=(-DCMAKE_PREFIX_PATH="$work/prefix")
        [ $how = subdirectory ] && args=(-DSTIPPLE_SOURCE_DIR="$src")
        cmake -S "$src/tests/package/core_only" -B "$work/core_$how" -DCMAKE_C_COMPILER="$cc" \
              -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON "${args[@]}" >"$work/log" 2>&1 ||
            { cat "$work/log"; fail "configuring a stipple::core consumer ($how) without libpng"; }
        cmake --build "$work/core_$how" >"$work/log" 2>&1 || { cat "$work/log"; fail "building it ($how)"; }
        run "stipple::core without libpng, $how" "$work/core_$how/consumer_cxx"
    done
    ;;
pkg-config)
    install_tree lib/libstipple_posix_png.a lib/pkgconfig/stipple-posix-png.pc
    export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
    pkg-config --exists stipple stipple-posix stipple-posix-png || fail "pkg-config does not find stipple"
    # shellcheck disable=SC2046,SC2086 # the flags are words
    "$cc" -std=c99 -Wall -Wextra -Werror $CFLAGS $LDFLAGS -o "$work/consumer_png" "$src/tests/package/png/consumer_png.c" \
        $(pkg-config --cflags --libs stipple-posix-png) || fail "compiling the PNG consumer with pkg-config"
    run "pkg-config PNG" "$work/consumer_png" "$work/out.png"
    # shellcheck disable=SC2046,SC2086 # the flags are words
    "$cc" -std=c99 -Wall -Wextra -Werror $CFLAGS $LDFLAGS -o "$work/consumer_c" "$src/tests/package/consumer/consumer.c" \
        $(pkg-config --cflags --libs stipple-posix) || fail "compiling the C consumer with pkg-config"
    # shellcheck disable=SC2046,SC2086
    "$cxx" -std=c++11 -Wall -Wextra -Werror $CXXFLAGS $LDFLAGS -o "$work/consumer_cxx" "$src/tests/package/consumer/consumer.cpp" \
        $(pkg-config --cflags --libs stipple) || fail "compiling the C++ consumer with pkg-config"
    run "pkg-config C" "$work/consumer_c"
    run "pkg-config C++" "$work/consumer_cxx"
    # the configuration guard: two lights in the application, four in the library
    # shellcheck disable=SC2046,SC2086
    if "$cc" -std=c99 -DSTP_MAX_LIGHTS=2 $CFLAGS $LDFLAGS -o "$work/mismatch" "$src/tests/package/consumer/consumer.c" \
        $(pkg-config --cflags --libs stipple-posix) >"$work/log" 2>&1; then
        fail "an application built with STP_MAX_LIGHTS=2 linked against the default library"
    fi
    grep -q "stp_renderer_create_cfg_f16_v160_l2_" "$work/log" ||
        { cat "$work/log"; fail "the mismatch error does not name the configuration"; }
    echo "ok: a configuration mismatch fails to link: $(grep -o 'stp_renderer_create_cfg_[a-z0-9_]*' "$work/log" | head -1)"
    # a library built with another configuration (switches and a header)
    # hands it to the application through stipple.pc's Cflags
    printf '#define STP_MAX_SEGMENTS 4\n' >"$work/my_config.h"
    cmake -S "$src" -B "$work/configured" -DCMAKE_C_COMPILER="$cc" -DSTP_BUILD_HOST=OFF \
          -DSTP_CONFIG_DEFINITIONS="STP_MAX_LIGHTS=2;STP_WITH_SHADOWS=0" \
          -DSTP_CONFIG_HEADER="$work/my_config.h" >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "configuring stipple with STP_CONFIG_DEFINITIONS"; }
    cmake --build "$work/configured" >"$work/log" 2>&1 || { cat "$work/log"; fail "building the configured stipple"; }
    cmake --install "$work/configured" --prefix "$work/prefix2" >"$work/log" 2>&1 || fail "installing the configured stipple"
    nm "$work/prefix2/lib/libstipple.a" | grep -q " T stp_renderer_create_cfg_f16_v160_l2_s4_c64_11010$" ||
        fail "the configured library is not built with STP_MAX_LIGHTS=2, STP_MAX_SEGMENTS=4, STP_WITH_SHADOWS=0"
    flags=$(PKG_CONFIG_PATH="$work/prefix2/lib/pkgconfig" pkg-config --cflags --libs stipple)
    for want in -DSTP_MAX_LIGHTS=2 -DSTP_WITH_SHADOWS=0 -DSTP_USER_CONFIG=1; do
        case " $flags " in *" $want "*) ;; *) fail "stipple.pc's flags ($flags) lack $want" ;; esac
    done
    # shellcheck disable=SC2086
    "$cxx" -std=c++11 $CXXFLAGS $LDFLAGS -o "$work/configured_cxx" "$src/tests/package/consumer/consumer.cpp" \
        $flags >"$work/log" 2>&1 || { cat "$work/log"; fail "the configured library's consumer does not build"; }
    run "pkg-config C++, STP_MAX_LIGHTS=2 STP_WITH_SHADOWS=0 and a config header" "$work/configured_cxx"
    ;;
subdirectory)
    cmake -S "$src/tests/package/subproject" -B "$work/sub" -DCMAKE_C_COMPILER="$cc" \
          -DCMAKE_CXX_COMPILER="$cxx" -DSTIPPLE_SOURCE_DIR="$src" \
          -DSTP_CONFIG_DEFINITIONS="STP_MAX_LIGHTS=1;STP_WITH_PAINTER=0" >"$work/log" 2>&1 ||
        { cat "$work/log"; fail "configuring the add_subdirectory consumer"; }
    grep -q "^CMOCKA_" "$work/sub/CMakeCache.txt" && fail "a subproject build looked for cmocka (the tests are on)"
    grep -q "^STP_WERROR:BOOL=OFF" "$work/sub/CMakeCache.txt" || fail "STP_WERROR is not off in a subproject"
    cmake --build "$work/sub" >"$work/log" 2>&1 || { cat "$work/log"; fail "building the add_subdirectory consumer"; }
    [ -e "$work/sub/stipple/tools/stipple" ] && fail "a subproject build built the stipple command"
    python3 - "$work/sub/compile_commands.json" <<'PY' || fail "flags leak into the consumer's own files"
import json, sys
for entry in json.load(open(sys.argv[1])):
    if "/tests/package/consumer/" in entry["file"]:
        cmd = entry.get("command") or " ".join(entry["arguments"])
        for flag in ("-Werror", "-Wpedantic"):
            if flag in cmd.split():
                sys.exit(f"{entry['file']} is compiled with {flag}")
PY
    run "add_subdirectory C" "$work/sub/consumer_c"
    run "add_subdirectory C++" "$work/sub/consumer_cxx"
    ;;
*) fail "unknown mode $mode" ;;
esac
