#!/usr/bin/env bash
# The benchmark as a smoke test: `texfilter bench --quick` (made smaller still) on this machine's device
# produces complete, finite results (tools/bench_check.py, standard library only: always asserted); then, in tools/.venv,
# tools/bench_report.py adds FLIP, plots and the HTML page and bench_check.py --require-flip checks them.
# When the venv cannot be made here (tools/python_env.sh exits 3: offline, no python3-venv) that second
# half is skipped, saying so; any other failure, the venv's scripts' included, fails the test. Timings
# are reported, never asserted (benchmarks, not timed tests).
#
# usage: bench_quick.sh TEXFILTER REPO_ROOT
set -euo pipefail
if [[ $# -ne 2 ]]; then
    echo "usage: $0 TEXFILTER REPO_ROOT" >&2
    exit 2
fi
texfilter=$(realpath "$1")
root=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# --quick's filters on two of its scenes, each result checked as ever, at the smallest sizes and counts the
# contract allows: 64x64 images, a 128² texture, 16 spp truths, 1 warm-up, 2 timed and 2 path frames. The
# run's cost is mostly lavapipe building each (scene, filter)'s pipelines, which no size changes, so the
# scenes are the two paths a scene takes: plane (ray cast in the shader) and mesh (rasterized triangles);
# the others render in the golden.* and view.* tests. The texture is uploaded as sRGB8 (--format), so the
# benchmark's format path runs end to end too.
# One filter of each kind the benchmark treats differently (a single-tap manual filter, probes through hardware
# taps, a manual EWA, the SAT with its footprint sweep, hw-trilinear that the times are relative to, the
# hardware's aniso): every path of bench.cpp, without building all 16 filters' pipelines twice each.
"$texfilter" bench --quick --scenes plane,mesh --filters trilinear,aniso16-hw,ewa,sat,hw-trilinear,hw-aniso16 \
    --format rgba8-srgb --size 64x64 --texture-size 128 --spp 16 \
    --warmup 1 --frames 2 --flicker-frames 2 --out "$work/bench"
python3 "$root/tools/bench_check.py" "$work/bench"

status=0
python=$("$root/tools/python_env.sh" | tail -1) || status=$?
if [[ $status -eq 3 ]]; then
    echo "bench_quick: SKIPPED the Python half (FLIP, plots, HTML): tools/python_env.sh cannot make tools/.venv" \
         "here (see its message above); bench --quick itself is complete and finite"
    exit 0
elif [[ $status -ne 0 ]]; then
    echo "bench_quick: tools/python_env.sh failed (exit $status)" >&2
    exit 1
fi
"$python" "$root/tools/bench_report.py" "$work/bench"
"$python" "$root/tools/bench_check.py" --require-flip "$work/bench"
for page in index.html quality_vs_cost.png quality_vs_cost_box.png quality_vs_reads.png; do
    [[ -s $work/bench/$page ]] || { echo "bench_quick: tools/bench_report.py wrote no $page" >&2; exit 1; }
done
echo "bench_quick: complete"
