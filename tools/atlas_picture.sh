#!/usr/bin/env bash
# The picture of docs/API.md "Texel sources": a 64² checker as one tile of an atlas (`sample --resource atlas`:
# the other cells red, green, blue), looked up at every pixel of a 192x192 grid over the whole tile with a
# footprint of 8 texels (LOD 3) and repeat wrap. Left: the hardware sampler at the tile's uv in the atlas
# (hw-trilinear, what an engine does without TF_SOURCE): its footprints near the tile's edges reach the
# neighbouring cells, a coloured fringe. Right: tf_trilinear through TF_SOURCE: the tile repeats into itself.
#
# usage: tools/atlas_picture.sh [TEXFILTER]   (default: build/texfilter; build it first: tools/build.sh)
# Writes docs/images/atlas-bleeding.png (8-bit sRGB, ~20 KB; python3's standard library writes the PNG).
# Deterministic on one device and driver; a few seconds on lavapipe.
set -euo pipefail
cd "$(dirname "$0")/.."
texfilter=${1:-./build/texfilter}
if [[ ! -x $texfilter ]]; then
    echo "no texfilter binary at $texfilter: build it first (tools/build.sh)" >&2
    exit 2
fi
out=docs/images/atlas-bleeding.png
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

side=192       # pixels a panel side: a lookup each
footprint=8    # level-0 texels a pixel's footprint side
tile=64
python3 - "$side" "$footprint" "$tile" >"$work/lookups.csv" <<'EOF'
import sys
side, footprint, tile = (int(a) for a in sys.argv[1:])
d = footprint / tile
print("u,v,dudx,dvdx,dudy,dvdy")
for y in range(side):
    for x in range(side):
        print(f"{(x + 0.5) / side!r},{(y + 0.5) / side!r},{d!r},0,0,{d!r}")
EOF
for filter in hw-trilinear trilinear; do
    "$texfilter" sample --texture checker --texture-size "$tile" --resource atlas --wrap repeat --filter "$filter" \
        --lookups "$work/lookups.csv" -o "$work/$filter.csv" >/dev/null
done
python3 - "$side" "$work/hw-trilinear.csv" "$work/trilinear.csv" "$work/picture.png" <<'EOF'
import struct, sys, zlib
side = int(sys.argv[1])
gap = 8

def srgb(c):
    c = min(max(c, 0.0), 1.0)
    return round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055))

panels = []
for path in sys.argv[2:4]:
    with open(path) as f:
        next(f)
        panels.append([[srgb(float(c)) for c in line.split(",")[:3]] for line in f])
width = 2 * side + gap
rows = b""
for y in range(side):
    row = bytearray(b"\x00")  # filter type: none
    for panel in (0, 1):
        for x in range(side):
            row += bytes(panels[panel][y * side + x])
        if panel == 0:
            row += b"\xff" * (3 * gap)
    rows += bytes(row)

def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, side, 8, 2, 0, 0, 0))
png += chunk(b"sRGB", b"\x00") + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
with open(sys.argv[4], "wb") as f:
    f.write(png)
EOF
mkdir -p "$(dirname "$out")"
mv "$work/picture.png" "$out"
du -h "$out"
