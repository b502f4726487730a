#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The tests on a fresh machine: install, then build and run the whole suite
# three times: plainly, under AddressSanitizer + UndefinedBehaviorSanitizer,
# and with the 32-bit target arithmetic on the host (STP_ARITH32) under the
# same sanitizers.
# Usage: scripts/test.sh
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/install-deps.sh"
# The Linux kernel test must not skip itself in CI for want of a download.
export STP_LINUX_TEST_REQUIRED=${STP_LINUX_TEST_REQUIRED:-1}
status=0
for kind in plain sanitize arith32; do
    build="$here/build-test-$kind"
    flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
    [ "$kind" = sanitize ] && flags=(-DCMAKE_BUILD_TYPE=Debug -DSTP_SANITIZE=ON)
    [ "$kind" = arith32 ] && flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTP_SANITIZE=ON -DSTP_ARITH32=ON)
    echo "=== $kind build"
    cmake -S "$here" -B "$build" "${flags[@]}" >/dev/null
    cmake --build "$build" -j"$(nproc)"
    ctest --test-dir "$build" --output-on-failure -j"$(nproc)" || status=1
    # the Arduino examples' flash, RAM and cycles (tests/avr/run_arduino_test.sh)
    grep -h '^FIGURES ' "$build/Testing/Temporary/LastTest.log" 2>/dev/null | sort || true
done
# A short fuzzing run of every libFuzzer target (clang, ASan+UBSan), after
# replaying the committed corpus and regressions.
echo "=== fuzz"
"$here/tests/fuzz/run_fuzz.sh" --replay || status=1
"$here/tests/fuzz/run_fuzz.sh" --no-build -t "${STP_FUZZ_SECONDS:-20}" || status=1
exit $status
