#!/usr/bin/env bash
# Quick start, part 2: set up, build, and run the whole test suite (validation layers on for GPU tests).
# A failing golden case leaves actual/golden/diff images and report.html in build/golden-out/NAME/.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/build.sh
ctest --preset default
