# Sourced by the tests of the prepared device scripts (gpu_bench_script.sh, gpu_tests_script.sh): a failure
# tally and the refusal check (exit 2, the expected message).
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

expect_refusal() { # name, expected message, command...
    local name=$1 message=$2
    shift 2
    local output rc
    output=$("$@" 2>&1)
    rc=$?
    [[ $rc -eq 2 ]] || fail "$name: exit $rc, expected 2"
    grep -qF -- "$message" <<<"$output" || fail "$name: no '$message' in: $output"
}
