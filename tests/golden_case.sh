#!/usr/bin/env bash
# One golden case's verdict from the golden.* fixture's run (tests/golden_run.sh): passes when the case's
# line says PASS. A failed case left its actual, golden and diff images and report.html in OUT_DIR/run/.
# A case the run skipped (--build gpu: mipcolors and integer formats are built on the host only) prints
# "SKIP: ..." and passes, which ctest reports as skipped (SKIP_REGULAR_EXPRESSION).
#
# usage: golden_case.sh OUT_DIR NAME
set -uo pipefail
if [[ $# -ne 2 ]]; then
    echo "usage: $0 OUT_DIR NAME" >&2
    exit 2
fi
# Field by field, not a regex: case names hold '+' (bias+1).
line=$(awk -v name="$2" '$1 == name && ($2 == "PASS" || $2 == "FAIL" || $2 == "SKIP")' "$1/verdicts.txt" 2>/dev/null)
if [[ -z $line ]]; then
    echo "golden.$2: no verdict in $1/verdicts.txt (the fixture golden_run did not render it)" >&2
    exit 1
fi
echo "$line"
if [[ $(awk '{print $2}' <<<"$line") == SKIP ]]; then
    echo "SKIP: $(cut -d' ' -f2- <<<"$line" | sed 's/^ *SKIP *//')"
    exit 0
fi
[[ $(awk '{print $2}' <<<"$line") == PASS ]] || { echo "golden.$2 failed: see $1/run/report.html" >&2; exit 1; }
