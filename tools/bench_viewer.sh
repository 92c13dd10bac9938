#!/usr/bin/env bash
# The viewer's frame rate, measured (docs/BENCHMARKS.md, "Viewer"): a scripted fly-through of the plane scene
# at 1280x720 for each filter, in a real window under Xvfb (or on $DISPLAY with --display), with the preview
# (a fraction of the pixels while the camera moves) and without it (--full: every frame at full size, the
# baseline), side by side in one run. Prints the frame times (median, 95th percentile, worst) and how much of
# the flight ran as a preview; asserts nothing.
#
# usage: tools/bench_viewer.sh [TEXFILTER] [--device D] [--size WxH] [--frames N] [FILTER...]
set -euo pipefail
texfilter=build/texfilter
[[ ${1:-} != -* && -n ${1:-} && -x ${1:-} ]] && { texfilter=$1; shift; }
device=() size=1280x720 frames=60 filters=()
while [[ $# -gt 0 ]]; do
    case $1 in
    --device) device=(--device "$2"); shift 2 ;;
    --size) size=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    *) filters+=("$1"); shift ;;
    esac
done
[[ ${#filters[@]} -gt 0 ]] || filters=(nearest bilinear trilinear brilinear aniso hw-aniso ewa sat)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
texfilter=$(realpath "$texfilter")
run_x() { if [[ -n ${DISPLAY:-} ]]; then "$@"; else xvfb-run -a -s "-screen 0 ${size}x24" "$@"; fi; }

info=$("$texfilter" info "${device[@]}" 2>/dev/null)
echo "device: $(sed -n 's/^texfilter would use: *//p' <<<"$info")"
echo "driver: $(grep -m1 '^    driver' <<<"$info" | sed 's/^ *//')"
echo "date: $(date -u +%Y-%m-%dT%H:%MZ)  size: $size  flight: $frames frames, then a rest"
printf '%-12s %-8s %10s %10s %10s %10s %8s\n' filter mode median_ms p95_ms worst_ms rest_ms preview
for f in "${filters[@]}"; do
    for mode in preview full; do
        {
            echo "scene plane"
            echo "texture checker --texture-size 1024"
            echo "filter $f"
            echo "wait 2"
            # The fly-through: a small step a frame, so the camera never rests.
            for ((i = 0; i < frames; ++i)); do echo "camera fly 0.01 0 0.02"; echo "camera turn 0.3 0"; echo "wait 1"; done
            echo "wait 30" # rests: refines to full size
            echo "quit"
        } >"$work/fly.txt"
        flags=()
        [[ $mode == full ]] && flags=(--no-preview)
        run_x "$texfilter" view --script "$work/fly.txt" --size "$size" "${device[@]}" "${flags[@]}" \
            --frame-log "$work/$f-$mode.csv" >/dev/null 2>"$work/err.txt" || { cat "$work/err.txt"; exit 1; }
        python3 - "$work/$f-$mode.csv" "$f" "$mode" "$frames" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
frames = int(sys.argv[4])
flight = rows[2:2 + frames]   # after the first frames (pipeline creation), the flying frames
rest = rows[2 + frames:]
t = sorted(float(r["frame_ms"]) for r in flight)
p95 = t[min(len(t) - 1, int(round(0.95 * (len(t) - 1))))]
preview = sum(1 for r in flight if int(r["preview_scale"]) > 1) / max(1, len(flight))
rest_ms = max((float(r["frame_ms"]) for r in rest), default=0.0)
print(f"{sys.argv[2]:<12} {sys.argv[3]:<8} {statistics.median(t):10.1f} {p95:10.1f} {t[-1]:10.1f} {rest_ms:10.1f} {preview:7.0%}")
PY
    done
done
