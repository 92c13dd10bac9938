#!/usr/bin/env bash
# The device-facing test executables on a GPU machine lent for minutes, as one prepared command: the suite's
# in-process and `texfilter sample` tests on that device, validation layers on (tests/README.md, "Another
# device"). Two steps, here and there:
#
#     tools/gpu_tests.sh pack BUILD LEAN_TEXFILTER DIR   # here: the test executables of BUILD (the default preset's
#                                                         # build folder), stripped, and the lean texfilter into DIR
#                                                         # (new or empty; ~6 MB of .txz), for `carry`
#     tools/gpu_tests.sh run DIR OUTDIR [TEST ...]        # there: unpacks DIR, runs each TEST (default: every packed
#                                                         # one) on TF_DEVICE (default NVIDIA), writes OUTDIR/tests.txt
#                                                         # (a summary) and OUTDIR/tests_full.txt (every line)
#
# On a bare NVIDIA machine `run` unpacks .gl/*.deb when present (the Vulkan loader, the GL libraries and the
# validation layers: the device tool's README, plus vulkan-validationlayers), and sets VK_DRIVER_FILES to the
# NVIDIA ICD when that file exists. Environment: TF_DEVICE, TF_TEST_BUDGET (seconds for all tests, default 240),
# TF_PACK_TESTS (the tests `pack` takes, default all below).
# The test executables have this checkout's absolute paths compiled in (golden/, the includes): `run` links the
# copy it runs in to that path when nothing is there. Tests needing image files (sat's hdr and non-finite texels,
# camera's golden case) fail without OpenImageIO, which the lean texfilter leaves out.
# Exit: 0 when every test passed, 1 when one failed or was cut off, 2 on a refusal (nothing written).
set -uo pipefail

fail() { echo "gpu_tests: $*" >&2; exit 2; }
empty_or_new() { [ ! -e "$1" ] || { [ -d "$1" ] && [ -z "$(ls -A "$1")" ]; }; }

# The test executables that run on the device (in process or through `texfilter sample`).
DEVICE_TESTS=${TF_PACK_TESTS:-"hw_vs_manual resource_kinds texel_sources brilinear_aniso ewa sat bicubic stochastic formats gpu_build
sample_order stages environment derivatives camera analytic_truth debug_views"}

pack() { # BUILD LEAN_TEXFILTER DIR
    [ $# -eq 3 ] || fail "usage: gpu_tests.sh pack BUILD LEAN_TEXFILTER DIR"
    local build=$1 lean=$2 dir=$3
    [ -x "$lean" ] || fail "$lean: no lean texfilter (cmake --preset lean && cmake --build --preset lean)"
    for t in $DEVICE_TESTS; do
        [ -x "$build/tests/test_$t" ] || fail "$build/tests/test_$t: missing (build the default preset first)"
    done
    empty_or_new "$dir" || fail "$dir: not empty (nothing in it is overwritten)"
    command -v xz >/dev/null && command -v strip >/dev/null || fail "needs xz and strip"
    local stage
    stage=$(mktemp -d) || fail "no temporary folder"
    trap "rm -rf '$stage'" EXIT
    for t in $DEVICE_TESTS; do strip -o "$stage/test_$t" "$build/tests/test_$t" || fail "strip test_$t failed"; done
    strip -o "$stage/texfilter" "$lean" || fail "strip $lean failed"
    # The source path the executables were built with (TEXFILTER_SOURCE_DIR, TF_GOLDEN_DIR), for `run`.
    grep -m1 '^CMAKE_HOME_DIRECTORY:' "$build/CMakeCache.txt" | cut -d= -f2- >"$stage/source_dir.txt"
    mkdir -p "$dir" && tar -cJf "$dir/tests.txz" -C "$stage" . || fail "$dir: cannot write tests.txz"
    echo "gpu_tests: packed $(wc -w <<<"$DEVICE_TESTS") tests and texfilter into $dir/tests.txz ($(du -h "$dir/tests.txz" | cut -f1))"
}

run() { # DIR OUTDIR [TEST ...]
    [ $# -ge 2 ] || fail "usage: gpu_tests.sh run DIR OUTDIR [TEST ...]"
    local dir=$1 out=$2
    shift 2
    [ -f "$dir/tests.txz" ] || fail "$dir/tests.txz: missing (gpu_tests.sh pack first)"
    [ -n "$out" ] && empty_or_new "$out" || fail "$out: the output folder is not empty (nothing in it is overwritten)"
    local work
    work=$(mktemp -d) || fail "no temporary folder"
    trap "rm -rf '$work'" EXIT
    tar -xJf "$dir/tests.txz" -C "$work" || fail "$dir/tests.txz: cannot unpack"
    local tests=${*:-$(cd "$work" && ls test_* | sed 's/^test_//')}
    for t in $tests; do [ -x "$work/test_$t" ] || fail "test_$t: not in $dir/tests.txz"; done
    if compgen -G ".gl/*.deb" >/dev/null; then
        for f in .gl/*.deb; do dpkg -x "$f" /; done
        ldconfig
    fi
    local icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
    [ -z "${VK_DRIVER_FILES:-}" ] && [ -f "$icd" ] && export VK_DRIVER_FILES=$icd
    local device=${TF_DEVICE:-NVIDIA}
    "$work/texfilter" info --device "$device" >"$work/info.txt" 2>&1 || {
        cat "$work/info.txt" >&2
        fail "no Vulkan device matches '$device' (TF_DEVICE)"
    }
    local source
    source=$(cat "$work/source_dir.txt")
    if [ -n "$source" ] && [ ! -e "$source" ]; then mkdir -p "$(dirname "$source")" && ln -s "$PWD" "$source"; fi
    mkdir -p "$out" || fail "$out: cannot create the output folder"
    export TEXFILTER_TEST_DEVICE=$device TEXFILTER_VALIDATE=1 TEXFILTER_EXE=$work/texfilter
    local budget=${TF_TEST_BUDGET:-240} start=$SECONDS failed=
    cat "$work/info.txt" >"$out/tests.txt"
    for t in $tests; do
        local left=$((budget - (SECONDS - start)))
        if [ "$left" -le 5 ]; then
            echo "== $t: not run (the ${budget} s budget is spent)" >>"$out/tests.txt"
            failed="$failed $t"
            continue
        fi
        local began=$SECONDS rc
        timeout "$left" "$work/test_$t" -nc >"$work/log.txt" 2>&1
        rc=$?
        { echo "######## $t: exit $rc"; cat "$work/log.txt"; } >>"$out/tests_full.txt"
        {
            echo "== $t: exit $rc after $((SECONDS - began)) s"
            grep -E "device LOD|FAIL|ERROR|SKIP|test cases" "$work/log.txt" | head -20
        } >>"$out/tests.txt"
        [ "$rc" -eq 0 ] || failed="$failed $t"
    done
    grep -E "^== " "$out/tests.txt"
    [ -z "$failed" ] || { echo "gpu_tests: failed or not run:$failed (see $out/tests_full.txt)" >&2; exit 1; }
}

case "${1:-}" in
pack) shift; pack "$@" ;;
run) shift; run "$@" ;;
*) fail "usage: gpu_tests.sh pack BUILD LEAN_TEXFILTER DIR | run DIR OUTDIR [TEST ...]" ;;
esac
