#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Build the libFuzzer targets with clang in their own build directory and run
# each one over its committed seed corpus for a while; or replay the
# committed inputs; or add the few inputs that cover new edges to the corpus.
#
# Usage: tests/fuzz/run_fuzz.sh [options] [TARGET...]
#   -t SECONDS      fuzzing time per target (default 20; env STP_FUZZ_SECONDS)
#   -b DIR          build directory (default build-fuzz in the checkout)
#   --bin-dir DIR   where the fuzz binaries are (default DIR/tests/fuzz)
#   --no-build      use the binaries already in --bin-dir
#   --replay        run every committed input (corpus/<target>/ and
#                   regressions/<target>/) once and stop: the regression test
#   --merge         add to corpus/<target>/ the fewest inputs of the last
#                   fuzzing runs (<bin-dir>/work/<target>/) that cover edges
#                   its files do not (-set_cover_merge=1); its files stay
#   -- ARGS...      further libFuzzer flags for the fuzzing runs
# TARGET: fuzz_nff fuzz_obj fuzz_off fuzz_ply fuzz_pnm fuzz_display_file fuzz_raytrace
#         fuzz_playback fuzz_spans fuzz_frame (default all).
#
# New inputs found while fuzzing go to <bin-dir>/work/<target>/, never into
# the committed corpus.  A target that crashes, leaks, times out or runs out
# of memory makes the script fail; the reproducer's path is printed (files
# <bin-dir>/artifacts/<target>/crash-*, leak-*, timeout-*, oom-*).  Runs one
# target at a time, one fuzzing process each.
set -u

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
all_targets=(fuzz_nff fuzz_obj fuzz_off fuzz_ply fuzz_pnm fuzz_display_file fuzz_raytrace fuzz_playback fuzz_spans fuzz_frame)

seconds=${STP_FUZZ_SECONDS:-20}
build="$root/build-fuzz"
bin_dir=
do_build=1
mode=fuzz
targets=()
extra=()

usage() { sed -n '2,/^set -u/p' "$0" | sed -e '/^set -u/d' -e 's/^# \{0,1\}//'; exit "$1"; }

while [ $# -gt 0 ]; do
    case "$1" in
    -t) seconds=$2; shift 2 ;;
    -b) build=$2; shift 2 ;;
    --bin-dir) bin_dir=$2; shift 2 ;;
    --no-build) do_build=0; shift ;;
    --replay) mode=replay; shift ;;
    --merge) mode=merge; shift ;;
    -h|--help) usage 0 ;;
    --) shift; extra=("$@"); break ;;
    -*) echo "run_fuzz.sh: unknown option $1" >&2; usage 2 ;;
    *) targets+=("$1"); shift ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
case "$seconds" in ''|*[!0-9]*) echo "run_fuzz.sh: -t needs whole seconds" >&2; exit 2 ;; esac
[ -n "$bin_dir" ] || bin_dir="$build/tests/fuzz"

if [ "$do_build" = 1 ]; then
    cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DSTP_FUZZ=ON >/dev/null || exit 1
    cmake --build "$build" --target "${targets[@]}" -j"$(nproc)" || exit 1
fi

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

status=0
for t in "${targets[@]}"; do
    exe="$bin_dir/$t"
    seeds="$here/corpus/$t"
    regress="$here/regressions/$t"
    work="$bin_dir/work/$t"
    artifacts="$bin_dir/artifacts/$t"
    if [ ! -x "$exe" ]; then
        echo "run_fuzz.sh: no fuzz binary $exe (build with -DCMAKE_C_COMPILER=clang -DSTP_FUZZ=ON)" >&2
        status=1
        continue
    fi
    dict=()
    [ -f "$here/$t.dict" ] && dict=(-dict="$here/$t.dict")
    mkdir -p "$work" "$artifacts"
    log="$bin_dir/work/$t.log"

    case "$mode" in
    replay)
        inputs=()
        for d in "$seeds" "$regress"; do
            [ -d "$d" ] || continue
            while IFS= read -r -d '' f; do inputs+=("$f"); done \
                < <(find "$d" -type f ! -name '.*' ! -name '*.md' -print0 | sort -z)
        done
        if [ ${#inputs[@]} -eq 0 ]; then
            echo "== $t: no committed inputs"
            continue
        fi
        # Given files, libFuzzer runs each once and stops at the first failure.
        if "$exe" "${inputs[@]}" >"$log" 2>&1; then
            echo "== $t: ${#inputs[@]} committed inputs replayed, all pass"
        else
            bad=$(sed -n 's/^Running: //p' "$log" | tail -n 1)
            echo "== $t: FAILED on ${bad:-an input} (log: $log)" >&2
            tail -n 40 "$log" >&2
            status=1
        fi
        ;;
    merge)
        # The committed files stay; a greedy set cover over edges (counters
        # off) picks the fewest found inputs that cover what they do not.
        if "$exe" -set_cover_merge=1 -use_counters=0 "$seeds" "$work" >"$log" 2>&1; then
            echo "== $t: corpus now $(find "$seeds" -type f | wc -l) files," \
                 "$(du -sb "$seeds" | cut -f1) bytes"
        else
            echo "== $t: merge FAILED (log: $log)" >&2
            tail -n 40 "$log" >&2
            status=1
        fi
        ;;
    fuzz)
        before=$(find "$artifacts" -type f | wc -l)
        echo "== $t: fuzzing for $seconds s (log: $log)"
        "$exe" -max_total_time="$seconds" -timeout=25 -max_len=4096 -print_final_stats=1 \
            -artifact_prefix="$artifacts/" "${dict[@]}" "${extra[@]}" "$work" "$seeds" \
            >"$log" 2>&1
        rc=$?
        found=$(find "$artifacts" -type f -newer "$log" 2>/dev/null; true)
        [ -n "$found" ] || [ "$rc" = 0 ] ||
            found=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log")
        if [ "$rc" != 0 ] || [ "$(find "$artifacts" -type f | wc -l)" != "$before" ]; then
            echo "== $t: FAILED (exit $rc)" >&2
            grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|.*check failed)' "$log" | head -n 5 >&2
            for f in $found; do
                echo "   reproducer: $f" >&2
                echo "   reproduce:  $exe $f" >&2
            done
            echo "   log: $log" >&2
            status=1
        else
            sed -n 's/^stat::number_of_executed_units: */   executions: /p' "$log"
            grep -E '^#[0-9]+.*DONE' "$log" | tail -n 1 | sed 's/^/   /'
        fi
        ;;
    esac
done
exit $status
