#!/usr/bin/env bash
# The benchmark as a smoke test: `texfilter bench --quick` on this machine's device produces complete,
# finite results; tools/bench_report.py adds FLIP, plots and the HTML page; tools/bench_check.py finds
# nothing missing or non-finite. Timings are reported, never asserted (benchmarks, not timed tests).
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

"$texfilter" bench --quick --out "$work/bench"
python=$("$root/tools/python_env.sh" | tail -1)
"$python" "$root/tools/bench_report.py" "$work/bench"
"$python" "$root/tools/bench_check.py" --require-flip "$work/bench"
for page in index.html quality_vs_cost.png quality_vs_cost_box.png; do
    [[ -s $work/bench/$page ]] || { echo "bench_quick: tools/bench_report.py wrote no $page" >&2; exit 1; }
done
echo "bench_quick: complete"
