#!/usr/bin/env bash
# A longer local fuzzing run (docs/FUZZING.md): installs the packages (tools/setup.sh), builds the fuzz
# preset into build-fuzz/, then fuzzes TARGET (or each target in turn: all) for SECONDS (default 600).
# The working corpus build-fuzz/work/TARGET/corpus/ starts from fuzz/corpus/TARGET/ and keeps growing
# across runs; crashes land in build-fuzz/work/TARGET/artifacts/. Extra arguments go to libFuzzer
# (e.g. -jobs=2 -workers=2, -dict=FILE). With --merge, the working corpus's inputs that add coverage are
# merged into fuzz/corpus/TARGET/ instead (review them before committing: keep the seeds small).
#
#   tools/fuzz.sh TARGET|all [SECONDS] [libFuzzer flags...]
#   tools/fuzz.sh --merge TARGET
#   targets: lookups_csv manifest args pfm image reference_filters
set -euo pipefail
cd "$(dirname "$0")/.."

targets=(lookups_csv manifest args pfm image reference_filters)
usage() { echo "usage: $0 TARGET|all [SECONDS] [libFuzzer flags...] | --merge TARGET  (targets: ${targets[*]})" >&2; exit 2; }
[ $# -ge 1 ] || usage

merge=0
if [ "$1" = "--merge" ]; then
  merge=1
  shift
  [ $# -eq 1 ] || usage
fi
target=$1
shift
if [ "$target" != all ] && [[ " ${targets[*]} " != *" $target "* ]]; then usage; fi

./tools/setup.sh
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

if [ $merge -eq 1 ]; then
  [ "$target" != all ] || usage
  work=build-fuzz/work/$target/corpus
  [ -d "$work" ] || { echo "fuzz.sh: no working corpus $work yet: run tools/fuzz.sh $target first" >&2; exit 2; }
  LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan.supp build-fuzz/fuzz/fuzz_$target -merge=1 "fuzz/corpus/$target" "$work"
  exit 0
fi

seconds=600
if [ $# -ge 1 ] && [[ $1 =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
[ "$target" = all ] && run=("${targets[@]}") || run=("$target")
for t in "${run[@]}"; do
  echo "fuzz.sh: fuzz_$t for $seconds s (corpus build-fuzz/work/$t/corpus)"
  fuzz/run.sh fuzz build-fuzz "$t" "$seconds" "build-fuzz/work/$t" "$@"
done
