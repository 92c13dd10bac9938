#!/usr/bin/env bash
# The golden.* fixture: renders every golden case on the GPU in ONE `texfilter golden` process (one Vulkan
# context, each filter's pipeline built once: 120 cases take ~85 s of CPU here against ~200 s as 120
# processes) and keeps its verdict lines in OUT/verdicts.txt for tests/golden_case.sh, which makes each case
# its own ctest entry (golden.NAME). Cases that fail do not fail this fixture (their entries do); a run that
# does not finish (an error, a crash, a validation message: exit 2 or a signal) does, and then every
# golden.NAME entry is "Not Run", which ctest counts as a failure.
#
# usage: golden_run.sh TEXFILTER OUT_DIR [FLAG...]
# FLAGs go to texfilter golden (CMake passes --build cpu,gpu: every case rendered with the host's build, then
# with the device's, from level 0). Only what this script writes there is replaced (OUT_DIR/run/,
# OUT_DIR/verdicts.txt); nothing else in OUT_DIR is touched.
set -uo pipefail
if [[ $# -lt 2 ]]; then
    echo "usage: $0 TEXFILTER OUT_DIR [FLAG...]" >&2
    exit 2
fi
texfilter=$1 out=$2
shift 2
mkdir -p "$out"
rm -rf "$out/run" "$out/verdicts.txt" "$out/verdicts.tmp" # the previous run's, written by this script
"$texfilter" golden --out "$out/run" "$@" > "$out/verdicts.tmp"
status=$?
mv "$out/verdicts.tmp" "$out/verdicts.txt" # a golden.NAME entry never reads a half-written file
cat "$out/verdicts.txt"
if [[ $status -ne 0 && $status -ne 1 ]] || ! grep -q '^[0-9]* cases, [0-9]* failed' "$out/verdicts.txt"; then
    echo "golden_run: texfilter golden did not finish (exit $status)" >&2
    exit 1
fi
exit 0
