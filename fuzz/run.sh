#!/usr/bin/env bash
# Runs one libFuzzer target of the fuzz build (cmake --preset fuzz), with its limits. Used by ctest
# (tests/CMakeLists.txt) and tools/fuzz.sh; docs/FUZZING.md says what each target checks.
#
#   fuzz/run.sh fuzz FUZZ_BUILD_DIR TARGET SECONDS WORK [--fresh] [libFuzzer flags...]
#       fuzzes for SECONDS on WORK/corpus (seeded from fuzz/corpus/TARGET; --fresh starts from a clean copy,
#       as CI does: the repo's corpus is never written). Crashes go to WORK/artifacts/.
#   fuzz/run.sh regressions FUZZ_BUILD_DIR TARGET
#       runs every input in fuzz/regressions/TARGET/ once (each one a crash found and fixed).
set -euo pipefail

usage() { echo "usage: $0 fuzz FUZZ_BUILD_DIR TARGET SECONDS WORK [--fresh] [flags] | regressions FUZZ_BUILD_DIR TARGET" >&2; exit 2; }
[ $# -ge 3 ] || usage
mode=$1 build=$2 target=$3
shift 3
source_dir=$(cd "$(dirname "$0")/.." && pwd)
binary=$build/fuzz/fuzz_$target
[ -x "$binary" ] || { echo "run.sh: $binary is not built (cmake --preset fuzz && cmake --build --preset fuzz)" >&2; exit 2; }

# Per input: at most max_len bytes, 10 s, and memory: 1 GB in one allocation, 2 GB resident. Text formats
# need little; image seeds are under 1 KB, and 16 KB leaves room for a real file's structure. The image
# target allows one allocation of 3 GB: OpenEXR allocates whatever size an attribute's header claims (up
# to 2 GB) before it reads it, untouched memory that is freed when the read fails (fuzz/findings/image/).
case $target in
  image) max_len=16384 malloc_mb=3072 rss_mb=3072 ;;
  args) max_len=1024 malloc_mb=1024 rss_mb=2048 ;;
  reference_filters) max_len=1024 malloc_mb=1024 rss_mb=2048 ;;
  *) max_len=4096 malloc_mb=1024 rss_mb=2048 ;;
esac
limits=(-max_len=$max_len -timeout=10 -rss_limit_mb=$rss_mb -malloc_limit_mb=$malloc_mb)
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Leaks inside third-party libraries that are not ours to fix, each explained in the file.
export LSAN_OPTIONS=suppressions=$source_dir/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}

case $mode in
  regressions)
    dir=$source_dir/fuzz/regressions/$target
    shopt -s nullglob
    inputs=("$dir"/*)
    [ ${#inputs[@]} -gt 0 ] || { echo "run.sh: no inputs in $dir" >&2; exit 2; }
    # Files (not a directory) are each run once, nothing is written.
    exec "$binary" "${limits[@]}" "${inputs[@]}"
    ;;
  fuzz)
    [ $# -ge 2 ] || usage
    seconds=$1 work=$2
    shift 2
    if [ "${1:-}" = "--fresh" ]; then
      # Only what this script makes there (corpus/, artifacts/) is removed; anything else is refused.
      if [ -d "$work" ] && [ -n "$(find "$work" -mindepth 1 -maxdepth 1 ! -name corpus ! -name artifacts -print -quit)" ]; then
        echo "run.sh: $work holds files run.sh did not make; not removing it (choose another WORK)" >&2
        exit 2
      fi
      rm -rf "$work/corpus" "$work/artifacts"
      shift
    fi
    mkdir -p "$work/corpus" "$work/artifacts"
    cp -n "$source_dir/fuzz/corpus/$target"/* "$work/corpus/"
    status=0
    "$binary" "${limits[@]}" -max_total_time="$seconds" -print_final_stats=1 \
      -artifact_prefix="$work/artifacts/" "$@" "$work/corpus" || status=$?
    if [ $status -ne 0 ]; then
      echo "run.sh: fuzz_$target failed (exit $status); reproducer(s):" >&2
      ls -l "$work/artifacts/" >&2 || true
      echo "run.sh: rerun one with $binary FILE; once fixed, copy it to fuzz/regressions/$target/" >&2
    fi
    exit $status
    ;;
  *) usage ;;
esac
