#!/usr/bin/env bash
# The big-texture load path, measured (docs/BENCHMARKS.md, "Big textures"): the host's MIP build beside
# memcpy in one run, then a 512x512 trilinear render of an 8192x8192 PNG on the default device, with its
# wall time and peak memory (GNU time), against the goal: peak <= 1.25 x (bytes on the device) + one staging
# level. Prints figures; asserts nothing. The PNG is made in a temporary directory (oiiotool), never the repo.
#
# usage: tools/bench_big_texture.sh [TEXFILTER] [PNG]   (default build/texfilter, a new 8192^2 PNG)
set -euo pipefail
texfilter=${1:-build/texfilter}
png=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ -z $png ]]; then
    png=$work/big.png
    echo "making $png (8192x8192 RGB8: 64-texel checker plus Gaussian noise, about 150 MB)"
    oiiotool --pattern checker:width=64:height=64:color1=0.9,0.6,0.2:color2=0.1,0.2,0.5 8192x8192 3 \
        --pattern noise:type=gaussian:mean=0:stddev=0.05 8192x8192 3 --add -d uint8 -o "$png"
fi
read -r width height < <(oiiotool --info "$png" | sed -n 's/.* : *\([0-9]*\) x *\([0-9]*\).*/\1 \2/p')

echo "== MIP build beside memcpy (host library, every core)"
"$texfilter" bench --mip-build --texture-size "$width" --repeat 3

echo "== render --scene plane --filter trilinear --size 512x512 of $png (${width}x${height})"
/usr/bin/time -v "$texfilter" render --scene plane --texture "$png" --filter trilinear --size 512x512 \
    -o "$work/out.png" >/dev/null 2>"$work/time.txt" || { cat "$work/time.txt"; exit 1; }
elapsed=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt")
peak_kib=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
python3 - "$width" "$height" "$peak_kib" "$elapsed" <<'PY'
import sys
w, h, peak_kib, elapsed = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
chain, lw, lh = 0, w, h
while True:
    chain += lw * lh * 16
    if lw == 1 and lh == 1: break
    lw, lh = max(1, lw // 2), max(1, lh // 2)
device = chain + 2 * 4 * 5          # the chain + the 1x1 summed-area table placeholders
staging = w * h * 16                # one staging level: level 0
limit = 1.25 * device + staging
peak = peak_kib * 1024
print(f"wall {elapsed}; peak RSS {peak / 2**30:.2f} GiB; device holds {device / 2**30:.2f} GiB; "
      f"goal 1.25 x device + level 0 = {limit / 2**30:.2f} GiB: peak is {peak / limit:.2f} of it")
PY
