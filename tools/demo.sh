#!/usr/bin/env bash
# Quick start, part 1: set up, build, and render the demo scenes on lavapipe into demo/.
# Each scene is rendered unfiltered (nearest, level 0: the aliasing the seed slides show) and with
# the manual trilinear include, plus the hardware trilinear sampler for comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/build.sh
mkdir -p demo
texfilter=./build/texfilter
render() { # scene texture filter [extra flags]
  local scene=$1 texture=$2 filter=$3
  shift 3
  "$texfilter" render --scene "$scene" --texture "$texture" --filter "$filter" --size 512x512 "$@" \
    -o "demo/$scene-$texture-$filter.png"
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
echo "demo images are in $(pwd)/demo/"
