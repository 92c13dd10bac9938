#!/usr/bin/env bash
# The compute bench's yardsticks (shaders/harness/minimal.glsl), timed beside its own frames: every scene of a
# compute run reports the minimal pass and the minimal trilinear pass (timed by the process's CPU clock, --timer
# cpu-time), and the minimal trilinear pass is a fair yardstick for tf_trilinear: on a scene with no seam (plane,
# slanted) its frame equals trilinear's bit for bit (the same texels, the same weights, the same level). Timings
# are reported, never asserted.
#
# usage: bench_minimal_pass.sh TEXFILTER
set -euo pipefail
if [[ $# -ne 1 ]]; then
    echo "usage: $0 TEXFILTER" >&2
    exit 2
fi
texfilter=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$texfilter" bench --out "$work/run" --stage compute --timer cpu-time --scenes plane,slanted,tunnel --filters trilinear \
    --size 64x64 --texture-size 256 --spp 1 --warmup 0 --frames 1 --flicker-frames 2 --validate >"$work/log"
python3 - "$work/run/bench.json" <<'PY'
import json, math, sys
run = json.load(open(sys.argv[1]))
for scene in ("plane", "slanted", "tunnel"):
    for key in ("baseline_ms", "minimal_ms", "minimal_trilinear_ms"):
        t = run[key].get(scene)
        assert t and math.isfinite(t["median"]) and t["median"] > 0, f"{key} has no time for {scene}: {t}"
for scene in ("plane", "slanted"):
    d = run["minimal_trilinear_vs_trilinear"][scene]
    assert d == 0.0, f"{scene}: the minimal trilinear pass differs from tf_trilinear by {d}"
print("minimal passes timed on 3 scenes; minimal trilinear == tf_trilinear on plane and slanted")
PY
