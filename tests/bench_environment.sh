#!/usr/bin/env bash
# The benchmark on the environment scenes (bench/env_bench.cpp) as a smoke test: `texfilter bench` on reflect
# (the sky and the mirror) with a few filters (each a pipeline lavapipe builds), tiny sizes, produces complete,
# finite results (tools/bench_check.py: one result per scene and filter, both truths, a baseline). Timings are
# reported, never asserted.
#
# usage: bench_environment.sh TEXFILTER REPO_ROOT
set -euo pipefail
if [[ $# -ne 2 ]]; then
    echo "usage: $0 TEXFILTER REPO_ROOT" >&2
    exit 2
fi
texfilter=$(realpath "$1")
root=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$texfilter" bench --scenes reflect --filters trilinear,ewa,hw-trilinear --size 32x32 --texture-size 64 \
    --spp 16 --warmup 1 --frames 2 --flicker-frames 2 --out "$work/bench"
# (--env latlong takes the same path with another map: the goldens and environment.* cover its filters.)
python3 "$root/tools/bench_check.py" "$work/bench"
echo "bench_environment: complete"
