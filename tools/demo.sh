#!/usr/bin/env bash
# Quick start, part 1: set up, build, and render the demo scenes on lavapipe into demo/.
# Each scene is rendered unfiltered (nearest, level 0: the aliasing the seed slides show), with the
# manual trilinear include and the hardware trilinear sampler for comparison; then the filter suite
# (brilinear, aniso, ewa, sat) on the plane and the rasterized mesh, and the plane's ground truth; then the
# environment scenes (skybox, reflect) from cube and lat-long maps.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/build.sh
rm -rf demo && mkdir -p demo # no images of an earlier run left beside these
texfilter=./build/texfilter
render() { # scene texture filter [extra flags]
  local scene=$1 texture=$2 filter=$3
  shift 3
  "$texfilter" render --scene "$scene" --texture "$texture" --filter "$filter" --size 512x512 "$@" \
    -o "demo/$scene-$texture-$filter${*:+$(printf '%s' "$*" | tr -d ' -' | sed 's/^/-/')}.png"
}
for filter in nearest trilinear hw-trilinear; do
  render plane checker "$filter"
  render tunnel mipcolors "$filter"
  render zoom noise "$filter" --texture-size 64
  render minify zoneplate "$filter"
  render slanted checker "$filter"
done
render tunnel mipcolors nearest-mip
render tunnel mipcolors bilinear-mip
for filter in brilinear aniso ewa sat sat-assembly hw-aniso; do
  render plane checker "$filter"
done
render plane checker ground-truth --pixel-filter gaussian # what every filter above is judged against
render triangles checker trilinear
render triangles checker trilinear --derivatives ray
render mesh zoneplate aniso
render mesh mipcolors trilinear
# Bicubic magnification, the analytic truth that judges it, stochastic filtering, ray cones.
for filter in bspline catmull-rom; do
  render zoom zoneplate "$filter" --texture-size 64
done
render zoom zoneplate ground-truth --texture-size 64 --truth analytic --spp 64
render slanted checker trilinear --stochastic blue --accumulate 16
render reflect checker trilinear --texture-size 512 --derivatives cone
# Environment maps (docs/ENVIRONMENT.md): the cube's corner from inside, and a mirror ball (cube and lat-long).
render skybox cube-labels trilinear --texture-size 128
render skybox checker ewa --texture-size 512
for filter in trilinear aniso ewa hw-trilinear; do
  render reflect checker "$filter" --texture-size 512
done
render reflect checker ewa --texture-size 256 --env latlong
echo "demo images are in $(pwd)/demo/"
