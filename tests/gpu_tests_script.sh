#!/usr/bin/env bash
# tools/gpu_tests.sh, the prepared device test run: its refusals write nothing, `pack` makes one archive, `run`
# runs what it packed on this machine's device and reports each test, exit 1 for a test not run.
#
# usage: gpu_tests_script.sh BUILD TEXFILTER REPO_ROOT
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/script_checks.sh" # fail, expect_refusal
if [[ $# -ne 3 ]]; then
    echo "usage: $0 BUILD TEXFILTER REPO_ROOT" >&2
    exit 2
fi
build=$(realpath "$1")
texfilter=$(realpath "$2")
script=$(realpath "$3")/tools/gpu_tests.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2 # no .gl here: nothing is unpacked
mkdir tmp
export TMPDIR="$work/tmp" # the script's temporary folders must be gone afterwards
export TF_PACK_TESTS="sample_order hw_vs_manual" # two small ones: packing every test takes a minute

expect_refusal "pack: no lean texfilter" "no lean texfilter" "$script" pack "$build" "$work/none" p1
[[ ! -e p1 ]] || fail "pack without texfilter: it created the folder"
mkdir full && echo "keep me" >full/mine.txt
expect_refusal "pack: a non-empty folder" "not empty" "$script" pack "$build" "$texfilter" full
[[ "$(ls full)" == mine.txt && "$(cat full/mine.txt)" == "keep me" ]] || fail "pack into a non-empty folder: it was changed"
"$script" pack "$build" "$texfilter" pack >pack.log 2>&1 || fail "pack: exit $? ($(cat pack.log))"
[[ "$(ls pack)" == tests.txz ]] || fail "pack: $(ls pack), expected tests.txz alone"
[[ $(tar -tJf pack/tests.txz | grep -c 'test_') -eq 2 ]] || fail "pack: $(tar -tJf pack/tests.txz)"

expect_refusal "run: a non-empty folder" "not empty" "$script" run pack full
[[ "$(ls full)" == mine.txt ]] || fail "run into a non-empty folder: it was changed"
expect_refusal "run: no archive" "tests.txz: missing" "$script" run "$work/none" o1
expect_refusal "run: a test not packed" "test_ewa: not in" "$script" run pack o2 ewa
expect_refusal "run: unknown device" "no Vulkan device matches 'no-such-gpu'" env TF_DEVICE=no-such-gpu "$script" run pack o3
for o in o1 o2 o3; do [[ ! -e $o ]] || fail "a refused run created $o"; done

env TF_DEVICE=llvmpipe "$script" run pack out sample_order >run.log 2>&1 || fail "run: exit $? ($(tail -3 run.log))"
grep -q "^== sample_order: exit 0" out/tests.txt || fail "run: no passing sample_order in $(cat out/tests.txt)"
grep -q "^######## sample_order: exit 0" out/tests_full.txt || fail "run: tests_full.txt lacks sample_order"
env TF_DEVICE=llvmpipe TF_TEST_BUDGET=1 "$script" run pack cut >cut.log 2>&1
rc=$?
[[ $rc -eq 1 ]] && grep -q "not run" cut/tests.txt || fail "a spent budget: exit $rc, expected 1 with 'not run'"
[[ -z "$(ls -A tmp)" ]] || fail "temporary folders left: $(ls tmp)"

[[ $failures -eq 0 ]] && echo "gpu_tests_script: all checks passed" && exit 0
exit 1
