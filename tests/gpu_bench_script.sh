#!/usr/bin/env bash
# tools/gpu_bench.sh, the prepared real-GPU check, on this machine's device: what it refuses leaves the output
# folder as it was, benches cut off by the time limit make it exit 1, and a one-scene run at 32x32 brings back
# its six files with the goals judged. Timings are never asserted (benchmarks, not timed tests).
#
# usage: gpu_bench_script.sh TEXFILTER REPO_ROOT
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/script_checks.sh" # fail, expect_refusal
if [[ $# -ne 2 ]]; then
    echo "usage: $0 TEXFILTER REPO_ROOT" >&2
    exit 2
fi
texfilter=$(realpath "$1")
script=$(realpath "$2")/tools/gpu_bench.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2 # no .gl here: nothing is unpacked
mkdir tmp
export TMPDIR="$work/tmp" # the script's own temporary folder must be gone afterwards

mkdir full && echo "keep me" >full/mine.txt
expect_refusal "non-empty output folder" "the output folder is not empty" env TEXFILTER="$texfilter" "$script" full
[[ "$(ls full)" == mine.txt && "$(cat full/mine.txt)" == "keep me" ]] || fail "non-empty output folder: it was changed"
expect_refusal "no binary" "no texfilter binary" env TEXFILTER="$work/none" "$script" out1
[[ ! -e out1 ]] || fail "no binary: it created the output folder"
expect_refusal "no output folder" "no output folder" env -u OUT TEXFILTER="$texfilter" "$script"
mkdir out2
expect_refusal "unknown device" "no Vulkan device matches 'no-such-gpu'" \
    env TEXFILTER="$texfilter" TF_DEVICE=no-such-gpu "$script" out2
[[ -z "$(ls -A out2)" ]] || fail "unknown device: it left $(ls out2) in the output folder"
expect_refusal "unknown device, new folder" "no Vulkan device matches" \
    env TEXFILTER="$texfilter" TF_DEVICE=no-such-gpu "$script" out3
[[ ! -e out3 ]] || fail "unknown device: it created the output folder"

env TEXFILTER="$texfilter" TF_DEVICE=llvmpipe TF_SCENES=plane TF_STAGE_LIMIT=1 "$script" cut >cut.log 2>&1
rc=$?
[[ $rc -eq 1 ]] && grep -qF "cut off by the 1 s limit: timing quality" cut.log ||
    fail "benches cut off by the limit: exit $rc, expected 1 naming both ($(tail -2 cut.log))"
env TEXFILTER="$texfilter" TF_DEVICE=llvmpipe TF_SCENES=plane TF_TIMING_SIZE=32x32 TF_QUALITY_SIZE=32x32 TF_LOOKUPS=2 \
    "$script" run >run.log 2>&1 || fail "one-scene run: exit $? ($(tail -3 run.log))"
for f in device.txt log.txt timing.json timing.csv quality.json quality.csv; do
    [[ -s run/$f ]] || fail "one-scene run: no run/$f"
done
[[ $(ls run | wc -l) -eq 6 ]] || fail "one-scene run: $(ls run | wc -l) files, expected 6: $(ls run)"
[[ $(grep -c ": exit 0 after" run/log.txt) -eq 2 ]] || fail "one-scene run: a bench did not exit 0: $(grep '== ' run/log.txt)"
[[ -z "$(ls -A tmp)" ]] || fail "one-scene run: its temporary folder was left: $(ls tmp)"
python3 - run/timing.json run/quality.json <<'EOF' || fail "one-scene run: the goals"
import json, sys
timing, quality = (json.load(open(p)) for p in sys.argv[1:])
def goal(run, start):
    found = [g for g in run["goals"] if g["goal"].startswith(start)]
    assert len(found) == 1, f"goal '{start}': {len(found)} found"
    return found[0]
# The speed goals were measured (a status other than not-applicable), on the plane alone.
for start in ("manual trilinear <=", "brilinear faster than trilinear", "sat <= 6x"):
    g = goal(timing, start)
    assert g["status"] in ("met", "missed"), f"timing: {g}"
assert timing["config"]["scenes"] == ["plane"], timing["config"]["scenes"]
assert timing["config"]["width"] == 32, timing["config"]
# The timed frames take TF_LOOKUPS lookups a pixel; the quality run the default one.
assert timing["config"]["lookups_per_pixel"] == 2 and quality["config"]["lookups_per_pixel"] == 1, timing["config"]
# The harness's frame against the minimal pass: judged where a frame is one lookup a pixel (the quality run).
assert goal(quality, "the no-texture frame <=")["status"] in ("met", "missed"), goal(quality, "the no-texture frame <=")
assert goal(timing, "the no-texture frame <=")["status"] == "not-applicable", goal(timing, "the no-texture frame <=")
g = goal(quality, "ewa: Gaussian-truth error and flicker below hw-aniso")
assert g["measured"].split(" (")[0].endswith(" of 1 scenes"), f"quality: {g}"
EOF
if [[ $failures -ne 0 ]]; then
    echo "gpu_bench_script: $failures failure(s)"
    exit 1
fi
echo "gpu_bench_script: refusals leave the output folder as it was; a one-scene run brings back 6 files, goals judged"
