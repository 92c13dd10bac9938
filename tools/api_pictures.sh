#!/usr/bin/env bash
# Renders the pictures of docs/API.md with our own CLI: one per filter family on the same view (the
# plane scene, a 512² checker, 256x256, the fragment stage with fine quad derivatives), the Gaussian-pixel
# ground truth they are judged against, three LOD pictures (mipcolors: each MIP level a flat colour), the
# environment maps, and an atlas tile under the hardware sampler and through TF_SOURCE.
#
# usage: tools/api_pictures.sh [TEXFILTER]   (default: build/texfilter; build it first: tools/build.sh)
# Writes docs/images/api/*.png (8-bit sRGB, ~0.2 MB in all); a few seconds a picture on lavapipe.
# The pictures are deterministic on one device and driver; re-run after changing a filter and commit them.
set -euo pipefail
cd "$(dirname "$0")/.."
texfilter=${1:-./build/texfilter}
if [[ ! -x $texfilter ]]; then
    echo "no texfilter binary at $texfilter: build it first (tools/build.sh)" >&2
    exit 2
fi
out=docs/images/api
rm -rf "$out" && mkdir -p "$out" # no picture of an earlier run left beside these

# picture NAME SCENE TEXTURE FILTER [extra flags]: one 256x256 render into $out/NAME.png.
picture() {
    local name=$1 scene=$2 texture=$3 filter=$4
    shift 4
    "$texfilter" render --scene "$scene" --texture "$texture" --texture-size 512 --filter "$filter" \
        --size 256x256 "$@" -o "$out/$name.png" >/dev/null
    echo "$out/$name.png"
}

# The reference: the level-0 texture integrated over a Gaussian pixel (sigma 0.5 px), 256 samples a pixel.
picture ground-truth plane checker ground-truth --pixel-filter gaussian
# One per filter family, default options (the CLI's defaults are the includes' suggested values).
picture nearest plane checker nearest           # tf_nearest: level 0 only
picture nearest-mip plane checker nearest-mip   # tf_nearest_mip
picture bilinear-mip plane checker bilinear-mip # tf_bilinear_mip
picture trilinear plane checker trilinear       # tf_trilinear
picture brilinear plane checker brilinear --band 0.25
picture aniso plane checker aniso --probes 16 --aniso-shape gpu
picture ewa plane checker ewa --alpha 2 --max-aniso 16
picture sat plane checker sat
picture sat-assembly plane checker sat-assembly --boxes 4
picture hw-trilinear plane checker hw-trilinear # the hardware sampler (textureGrad), for comparison
# LOD: the level each pixel reads. Quad derivatives jump across the tunnel's texture seam (u wraps from 1
# to 0), ray differentials do not; on the plane trilinear blends the levels continuously.
picture lod-tunnel-quads tunnel mipcolors nearest-mip
picture lod-tunnel-ray tunnel mipcolors nearest-mip --derivatives ray
picture lod-plane-trilinear plane mipcolors trilinear
# Environment maps (cube.glsl, latlong.glsl): a mirror ball in a cube of six tinted 512² checker faces, and the
# cube's corner from inside (cube-labels: each face's hue, a bar along its t = 0 edge, its orientation marks).
picture reflect-ground-truth reflect checker ground-truth --pixel-filter gaussian
picture reflect-trilinear reflect checker trilinear
picture reflect-aniso reflect checker aniso --probes 16
picture reflect-ewa reflect checker ewa
picture reflect-hw-aniso reflect checker hw-aniso
picture reflect-latlong-ewa reflect checker ewa --env latlong
picture skybox-labels skybox cube-labels trilinear

# Texel sources (docs/API.md): a 64² checker as one tile of an atlas (`sample --resource atlas`: the other cells
# red, green, blue), looked up at every pixel of a 192x192 grid over the tile with a footprint of 8 texels (LOD 3)
# and repeat wrap. Left the hardware sampler at the tile's uv in the atlas (hw-trilinear: footprints near the
# edges reach the neighbouring cells), right tf_trilinear through TF_SOURCE (the tile repeats into itself).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 tools/atlas_picture.py lookups 192 8 64 >"$work/lookups.csv"
for filter in hw-trilinear trilinear; do
    "$texfilter" sample --texture checker --texture-size 64 --resource atlas --wrap repeat --filter "$filter" \
        --lookups "$work/lookups.csv" -o "$work/$filter.csv" >/dev/null
done
python3 tools/atlas_picture.py png 192 "$work/hw-trilinear.csv" "$work/trilinear.csv" "$out/atlas-bleeding.png"
echo "$out/atlas-bleeding.png"

du -ch "$out"/*.png | tail -n 1
