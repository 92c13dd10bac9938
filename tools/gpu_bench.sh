#!/usr/bin/env bash
# The real-GPU rows of docs/BENCHMARKS.md in one prepared command, for a GPU machine lent for minutes.
#
# Usage (in the repository root of a copy that holds build-lean/texfilter, built beforehand with
# `cmake --preset lean && cmake --build --preset lean`):
#     tools/gpu_bench.sh OUTDIR            # OUTDIR new or empty; default $OUT
# Environment: TF_DEVICE (default NVIDIA: part of the device's name, as --device takes it), TF_STAGE (default
# compute: NVIDIA's datacenter GPUs run the graphics path ~30x slower, DESIGN.md §4), TF_TIMING_SIZE (512x512),
# TF_LOOKUPS (lookups a pixel in the timed frames, default 16: on an H200 the harness's own per-pixel cost hid
# the filters at one, 0.32 ms a 1024x1024 frame whatever the filter), TF_QUALITY_SIZE (512x512), TF_STAGE_LIMIT
# (seconds each bench may run, default 240), TF_SCENES (the 7 2D scenes), TEXFILTER (the binary, default
# build-lean/texfilter).
#
# Writes OUTDIR/device.txt (texfilter info, nvidia-smi), timing.json/.csv (the speed goals: TF_LOOKUPS lookups a
# pixel, one truth sample, 2 path frames: its error columns are not a measurement), quality.json/.csv (the error and
# flicker goals at the default 256 samples and 8 path frames) and log.txt. The benches' images stay in a
# temporary folder that is removed at the end: six small files come back from a lent machine. Each bench has
# its own time limit, so a slow one still leaves the other's results; the exit status is 1 when either failed.
# Then, here, read the goals with
#     python3 -c 'import json,sys; [print(g["status"], "|", g["goal"], "|", g["measured"]) for g in json.load(open(sys.argv[1]))["goals"]]' OUTDIR/timing.json
set -uo pipefail

out=${1:-${OUT:-}}
bin=${TEXFILTER:-build-lean/texfilter}
device=${TF_DEVICE:-NVIDIA}
stage=${TF_STAGE:-compute}
limit=${TF_STAGE_LIMIT:-240}
scenes=${TF_SCENES:-plane,tunnel,zoom,minify,slanted,triangles,mesh}

fail() { echo "gpu_bench: $*" >&2; exit 2; }
[ -n "$out" ] || fail "no output folder (give one, or set OUT)"
[ -x "$bin" ] || fail "$bin: no texfilter binary (build the lean preset first, or set TEXFILTER)"
[ ! -e "$out" ] || [ -z "$(ls -A "$out")" ] || fail "$out: the output folder is not empty (nothing in it is overwritten)"
work=$(mktemp -d) || fail "no temporary folder"
trap 'rm -rf "$work"' EXIT

# A bare NVIDIA machine: the Vulkan loader and GL libraries come as .deb files in .gl (the device README), the
# driver's ICD file is off the loader's default path.
if compgen -G ".gl/*.deb" >/dev/null; then
    for f in .gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
fi
icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
[ -z "${VK_DRIVER_FILES:-}" ] && [ -f "$icd" ] && export VK_DRIVER_FILES=$icd

log="$out/log.txt"
if ! "$bin" info --device "$device" >"$work/info.txt" 2>&1; then
    cat "$work/info.txt" >&2
    fail "no Vulkan device matches '$device' (TF_DEVICE)"
fi
mkdir -p "$out" || fail "$out: cannot create the output folder" # only once nothing is left to refuse
{
    date -u '+%Y-%m-%d %H:%M:%S UTC'
    cat "$work/info.txt"
    if command -v nvidia-smi >/dev/null; then nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv; fi
} >"$out/device.txt" 2>&1

run_bench() { # name, bench arguments...
    local name=$1
    shift
    echo "== $name: $bin bench $*" >>"$log"
    local started=$SECONDS
    timeout "$limit" "$bin" bench --device "$device" --stage "$stage" --scenes "$scenes" --out "$work/$name" "$@" \
        >>"$log" 2>&1
    local rc=$?
    echo "== $name: exit $rc after $((SECONDS - started)) s" >>"$log"
    [ "$rc" -eq 0 ] || failed="$failed $name"
    for ext in json csv; do
        [ -f "$work/$name/bench.$ext" ] && cp "$work/$name/bench.$ext" "$out/$name.$ext"
    done
    return 0 # the other bench still runs
}
failed=

# Speed: trilinear, brilinear and sat against hw-trilinear; aniso's two forms and EWA against hw-aniso16.
run_bench timing --size "${TF_TIMING_SIZE:-512x512}" --lookups-per-pixel "${TF_LOOKUPS:-16}" --spp 1 \
    --flicker-frames 2 --warmup 5 --frames 20 \
    --filters trilinear,brilinear,sat,sat-assembly,hw-trilinear,aniso16,aniso16-hw,hw-aniso16,ewa,ewa-hw,ewa-fast
# Quality: EWA's error and flicker against the hardware's anisotropic filter, the manual/hardware pairs; at one
# lookup a pixel, so its bench.json also judges the harness's no-texture frame against the minimal pass.
run_bench quality --size "${TF_QUALITY_SIZE:-512x512}" --warmup 1 --frames 3 \
    --filters trilinear,hw-trilinear,aniso16,aniso16-hw,hw-aniso16,ewa,ewa-hw,ewa-fast
tail -n 4 "$log"
[ -z "$failed" ] || { echo "gpu_bench: failed or cut off by the ${limit} s limit:$failed (see $log)" >&2; exit 1; }
