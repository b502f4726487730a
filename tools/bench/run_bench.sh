#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Error against run time of every numeric configuration of the core.
#
# Runs each bench_<cfg> executable (built by tools/bench/CMakeLists.txt, one
# per configuration), collects their CSV rows into OUT/bench.csv, plots error
# against run time into OUT/bench.png (gnuplot, log scales) and prints the
# table.  Each run's full report goes to OUT/bench-<cfg>.txt.
#
# usage: run_bench.sh [--bin-dir DIR] [--out-dir DIR] [--scenes DIR] [--quick]
#                     [--firmware FILE] [CFG...]
#   --bin-dir DIR  where the bench_<cfg> executables are (default: the
#                  tools/bench folder of ./build)
#   --out-dir DIR  where bench.csv, bench.png and the reports go (default .)
#   --scenes DIR   the shared NFF scenes (default: $STP_SCENES_DIR, else the
#                  executables' built-in path)
#   --quick        short runs (smoke test; the numbers are rough)
#   --firmware FILE  the Cortex-M instruction counts (tools/bench/firmware_figures.sh):
#                  printed as a second table and copied to OUT/firmware.csv
#   CFG...         configurations to run (default: every bench_* in DIR)
set -euo pipefail

bin_dir=build/tools/bench
out_dir=.
scenes=${STP_SCENES_DIR:-}
quick=()
configs=()
firmware=""
while [ $# -gt 0 ]; do
    case $1 in
    --bin-dir) bin_dir=$2; shift 2 ;;
    --out-dir) out_dir=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    --quick) quick=(--quick); shift ;;
    --firmware) firmware=$2; shift 2 ;;
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "run_bench.sh: unknown option $1" >&2; exit 2 ;;
    *) configs+=("$1"); shift ;;
    esac
done

if [ ${#configs[@]} -eq 0 ]; then
    for exe in "$bin_dir"/bench_*; do
        # bench_quality is the dithering bench (tools/bench/quality.c), not a
        # numeric configuration
        [ -x "$exe" ] && [ "${exe##*/}" != bench_quality ] && configs+=("${exe##*/bench_}")
    done
fi
if [ ${#configs[@]} -eq 0 ]; then
    echo "run_bench.sh: no bench_* executables in $bin_dir (build them first:" \
         "cmake --build build --target bench)" >&2
    exit 1
fi

if [ -n "$firmware" ] && ! head -n 1 "$firmware" 2>/dev/null | grep -q "instr_per_shade"; then
    echo "run_bench.sh: $firmware is not a firmware figures CSV (tools/bench/firmware_figures.sh)" >&2
    exit 2
fi

mkdir -p "$out_dir"
csv=$out_dir/bench.csv
tmp=$csv.tmp
rm -f "$tmp"
scene_args=()
[ -n "$scenes" ] && scene_args=(--scenes "$scenes")
status=0
for cfg in "${configs[@]}"; do
    echo "== running bench_$cfg" >&2
    if ! "$bin_dir/bench_$cfg" --csv "$tmp" "${scene_args[@]}" "${quick[@]}" \
            > "$out_dir/bench-$cfg.txt"; then
        echo "run_bench.sh: bench_$cfg reported a failure (see $out_dir/bench-$cfg.txt)" >&2
        status=1
    fi
done
[ -s "$tmp" ] || { echo "run_bench.sh: no results" >&2; exit 1; }
mv "$tmp" "$csv"

# The table: errors, then run time.
awk -F, '
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
function v(name) { return $(col[name]) }
{
    rows[NR] = sprintf("%-13s %9.2e %9.2e %9.2e | %8.2e %8.2e %4d | %8.2e %8.2e %6.2f | %7.3f %8.2e | %7.0f %7.0f %7.0f %7.0f | %7.0f %9.0f %7.4f | %8.2e %8.2e %6.3f %7.0f %6.3f",
        v("config"), v("rand_max"), v("rand_mean"), v("rand_max_wellcond"), v("stiff_max"), v("stiff_mean"),
        v("stiff_over_half_step"), v("scene_max"), v("scene_mean"), v("style_diff_pct"),
        v("img_diff_pct"), v("img_blur_mad"), v("ns_per_shade"), v("us_frame_128x64"),
        v("us_frame_400x240"), v("us_frame_640x480"), v("fill_mpx_s"), v("memset_mpx_s"),
        v("fill_memset_ratio"), v("rt_max"), v("rt_mean"), v("rt_above_pct"), v("rt_us_frame_balls128"),
        v("rt_mrays_s"))
}
END {
    print ""
    printf "%-13s %-29s | %-22s | %-24s | %-16s | %-31s | %-25s | %s\n", "", "random shades", "stiff suite",
        "scene polygons", "pictures", "run time", "HALFTONE-FILLIN", "ray tracer"
    printf "%-13s %9s %9s %9s | %8s %8s %4s | %8s %8s %6s | %7s %8s | %7s %7s %7s %7s | %7s %9s %7s | %8s %8s %6s %7s %6s\n",
        "config", "max", "mean", "max>2^-10", "max", "mean", ">1/30", "max", "mean", "style%", "diff%", "blurMAD",
        "ns/shd", "us@128", "us@400", "us@640", "Mpx/s", "memset", "ratio", "max", "mean", ">1/30%",
        "us/frm", "Mray/s"
    for (i = 2; i <= NR; i++) print rows[i]
    print ""
    print "errors: absolute shade error against the double reference (1/30 = half an INTENSITY"
    print "  step at 16 levels); max>2^-10: random inputs whose N.E and |N.L| are all >= 2^-10,"
    print "  away from the jumps where the eye or a light crosses the surface plane"
    print "pictures: MONO1 renders of the shared scenes and the torus at 128x64 and 400x240:"
    print "  differing pixels, and the mean absolute difference after a 3x3 box blur"
    print "run time: ns per stp_shade_point; us per torus frame (1000 triangles entered and"
    print "  rendered) at 128x64, 400x240, 640x480; HALFTONE-FILLIN vs memset in Mpixel/s"
    print "ray tracer: every pixel of the 8 scenes at 96x64 against the double reference ray"
    print "  tracer (shade error max, mean, share of pixels above 1/30); us per frame and"
    print "  million rays (primary, secondary, shadow) per second, balls-s2 at 128x128 with"
    print "  the hierarchy"
}' "$csv"

# The Cortex-M figures: emulated instructions, the same on every run.
if [ -n "$firmware" ]; then
    awk -F, '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    function v(name) { return (name in col) ? $(col[name]) : "" }
    function n(x) { return x == "" ? "-" : x }
    {
        rows[NR] = sprintf("%-12s %-13s %-13s %-8s %11s %13s %13s %15s%s", v("board"), v("scene"), v("cpu"),
            v("config"), n(v("instr_per_shade")), n(v("instr_enter")), n(v("instr_frame")),
            n(v("instr_frame_with_transfer")), v("options") == "" ? "" : "  (" v("options") ")")
    }
    END {
        print ""
        print "Cortex-M (QEMU -icount, emulated instructions)"
        printf "%-12s %-13s %-13s %-8s %11s %13s %13s %15s\n", "board", "scene", "cpu", "config",
            "per shade", "enter scene", "frame (core)", "frame + panel"
        for (i = 2; i <= NR; i++) print rows[i]
        print ""
        print "per shade: one stp_shade_point call with its argument passing and loop, mean over"
        print "  256 calls on 64 of the scene'"'"'s polygons; frame: one 128x64 render of the entered"
        print "  scene in 4-row bands, through the core alone / with the SSD0323 transfer over SSI;"
        print "  config: the scene'"'"'s compiled minimal configuration or the full library; M0+"
        print "  images run on QEMU'"'"'s Cortex-M3 (counts are instructions, not cycles)"
    }' "$firmware"
    if [ "$(cd "$(dirname "$firmware")" && pwd)/$(basename "$firmware")" != \
         "$(cd "$out_dir" && pwd)/firmware.csv" ]; then
        cp "$firmware" "$out_dir/firmware.csv"
    fi
    echo "wrote $out_dir/firmware.csv" >&2
fi

if command -v gnuplot > /dev/null; then
    if "$(dirname "$0")/plot_bench.sh" "$csv" "$out_dir/bench.png"; then
        echo "wrote $csv and $out_dir/bench.png" >&2
    else
        echo "run_bench.sh: gnuplot failed; no plot" >&2
        status=1
    fi
else
    echo "run_bench.sh: gnuplot not found (Debian: apt-get install gnuplot-nox); no plot" >&2
    echo "wrote $csv" >&2
fi
exit $status
